// Temporal order of BDF2 in the fluid solver: the Taylor-Green vortex (prm/taylor_green.prm:
// nu = 0.1, [0, pi]^2, exact time-dependent velocity on the whole boundary, end time T = 1 s, the
// velocity decays to 0.82 of its initial value) on one fixed 32 x 32 mesh with interior vertices
// moved randomly by up to 0.25 of the local edge, with dt = T/10, T/20, T/40, T/80 (max Courant
// number 2.1 ... 0.27). To isolate the time error from the (larger, 2.2e-3) spatial error, the error
// measure is the difference of successive runs e(dt) = ||u_dt - u_dt/2||_L2 at t = T (pressure:
// of p - mean(p)); e(dt) / e(dt/2) -> 2^order.
//
// Asserted, linear solves to 1e-10, 2 pressure correctors per outer loop: velocity and
// pressure orders >= 1.8 on the finest pair
//  - with 2 outer (PIMPLE) correctors (measured 2.87, 2.88: the self-differences converge faster
//    than second order here), and
//  - with plain PISO (1 outer corrector, measured 2.25, 2.06). Its momentum equation is assembled
//    once per step; with `Flux extrapolation` (the default) it is linearised about the
//    extrapolated state: convecting flux 2 F^n - F^(n-1) and velocity 2 u^n - u^(n-1) for the
//    explicit parts (deferred linear-upwind and non-orthogonal corrections), an O(dt^2) lag.
//
// Printed, not asserted: plain PISO without the extrapolation (as OpenFOAM's PISO: the fluxes
// and explicit parts of the previous step, an O(dt) lag that more pressure or non-orthogonal
// correctors do not remove) is first order in time (pressure 0.98, velocity 1.38 and falling).
//
// Differences are printed with 3 significant digits, orders with 2 decimals: the linear solves
// (1e-10) and the deterministic distortion make the values reproducible to far better than that,
// so numdiff's default tolerance is enough.
#include <fvfsi/scenes/fluid_scene.h>

#include "../test_utilities.h"

#include <cmath>
#include <filesystem>

using namespace fvfsi_test;

struct State
{
  std::vector<double> volume, u, v, p; // per cell at t = T; p - mean(p)
  double l2_velocity_error = 0;
};

State run(const unsigned int n_steps, const std::vector<std::string>& extra)
{
  // Two pressure correctors in every step: the order of one scheme. (By default the solver adds
  // correctors where the second one still changed the face velocities by more than 1e-3, which
  // it does at the larger steps here: an order study would then mix two schemes.)
  std::vector<std::string> settings = {"Fluid/Max pressure correctors=2"};
  settings.insert(settings.end(), extra.begin(), extra.end());
  const auto scene_pointer = run_fluid_case("taylor_green", 1.0 / n_steps, settings);
  const auto& scene = *scene_pointer;
  const auto& fv = scene.geometry();
  State s;
  double mean = 0, total = 0;
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
  {
    s.volume.push_back(fv.cell_volume[c]);
    s.u.push_back(scene.solver().velocity()[c][0]);
    s.v.push_back(scene.solver().velocity()[c][1]);
    s.p.push_back(scene.solver().kinematic_pressure().local_element(c));
    mean += s.volume.back() * s.p.back();
    total += s.volume.back();
  }
  for (double& x : s.p)
    x -= mean / total;
  s.l2_velocity_error = scene.results().l2_velocity_error;
  return s;
}

/// Prints the successive differences and orders; returns the orders (u, p) of the finest pair.
std::array<double, 2> study(std::ofstream& out, const std::vector<std::string>& extra)
{
  const std::vector<unsigned int> steps = {10, 20, 40, 80};
  std::vector<State> states;
  for (const unsigned int n : steps)
    states.push_back(run(n, extra));
  out << "dt pair           ||u_dt - u_dt/2||  ||p_dt - p_dt/2||  orders u, p\n";
  std::array<double, 2> previous{}, order{};
  for (unsigned int k = 0; k + 1 < states.size(); ++k)
  {
    const State& a = states[k];
    const State& b = states[k + 1];
    std::array<double, 2> e{};
    for (unsigned int c = 0; c < a.volume.size(); ++c)
    {
      e[0] += a.volume[c] * (std::pow(a.u[c] - b.u[c], 2) + std::pow(a.v[c] - b.v[c], 2));
      e[1] += a.volume[c] * std::pow(a.p[c] - b.p[c], 2);
    }
    for (double& x : e)
      x = std::sqrt(x);
    out << format("T/%-2u - T/%-2u     %.3e          %.3e", steps[k], steps[k + 1], e[0], e[1]);
    if (k > 0)
    {
      for (unsigned int i = 0; i < 2; ++i)
        order[i] = std::log2(previous[i] / e[i]);
      out << format("          %.2f %.2f", order[0], order[1]);
    }
    out << "\n";
    previous = e;
  }
  out << format("(L2 velocity error against the exact solution, dt = T/80: %.3e, spatial)\n",
                states.back().l2_velocity_error);
  return order;
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  out << "Taylor-Green vortex, 1024 cells (distorted), T = 1 s\n";
  out << "2 outer correctors, 2 pressure correctors:\n";
  const auto pimple = study(out, {});
  out << "velocity and pressure orders >= 1.8 on the finest pair: "
      << yes_no(pimple[0] >= 1.8 && pimple[1] >= 1.8) << "\n";
  out << "plain PISO (1 outer corrector), extrapolated linearisation:\n";
  const auto piso = study(out, {"Fluid/Outer correctors=1"});
  out << "velocity and pressure orders >= 1.8 on the finest pair: "
      << yes_no(piso[0] >= 1.8 && piso[1] >= 1.8) << "\n";
  out << "plain PISO without extrapolation (Flux extrapolation = false), not asserted:\n";
  study(out, {"Fluid/Outer correctors=1", "Fluid/Flux extrapolation=false"});
}
