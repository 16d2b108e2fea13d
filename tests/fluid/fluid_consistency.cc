// The consistent Rhie-Chow flux makes the converged steady solution independent of the (pseudo)
// time step. In steady mode each cell takes the pseudo time step 1 / dt_P = a*_P (1 - alpha) / alpha
// (alpha = Fluid/Momentum relaxation), so alpha = 0.5 and alpha = 10/11 differ by a factor of 10
// in every cell's dt. Both are run to a steady tolerance of 1e-12 (Kovasznay) and 1e-11
// (Turek-Hron) on
//   (a) Kovasznay flow (prm/kovasznay.prm, 192 cells, randomly distorted by 0.25 of the local
//       edge: non-orthogonal and skewed faces, the skewness-corrected h / a* interpolation), and
//   (b) a coarse CFD2-like Turek-Hron channel (prm/turek_hron_cfd2.prm with n = 8: 898 cells,
//       Re = 100, parabolic inflow, outlet p = 0, walls, cylinder and flag as no-slip walls),
// and the max over cells of |u_0.5 - u_10/11| / max |u| and |p_0.5 - p_10/11| / max |p| (and for
// (b) the relative drag and lift differences) are asserted below 1e-6 (issue 4). Measured:
// 2e-12 ... 4e-10, the remaining steady-iteration error (237 / 62 pseudo time steps for (a),
// 532 / 98 for (b)).
//
// The differences are printed with 2 digits: deal.II's numdiff (-a 1e-6 -r 1e-8) accepts any
// change of a value below 1e-6, so the comparison with the .output fails exactly when a
// difference grows beyond the asserted 1e-6.
#include <fvfsi/scenes/fluid_scene.h>

#include "../test_utilities.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace fvfsi_test;

struct Steady
{
  std::vector<dealii::Tensor<1, 2>> u;
  std::vector<double> p;
  dealii::Tensor<1, 2> force;
  unsigned int n_cells = 0, n_steps = 0;
};

Steady run(const std::string& name, std::vector<std::string> overrides, const double alpha)
{
  overrides.push_back("Fluid/Momentum relaxation=" + format("%.17g", alpha));
  overrides.push_back("Fluid/Max steady iterations=100000");
  overrides.push_back("Output directory=out");
  const auto p = shipped_case(name, overrides);
  std::filesystem::create_directories("out");
  fvfsi::FluidScene<2> scene(p->mesh, p->fluid, p->fluid_scene, p->time, MPI_COMM_WORLD, ".",
                             "out");
  scene.run();
  Steady s;
  for (unsigned int c = 0; c < scene.geometry().n_owned_cells(); ++c)
  {
    s.u.push_back(scene.solver().velocity()[c]);
    s.p.push_back(scene.solver().kinematic_pressure().local_element(c));
  }
  if (!p->fluid_scene.force_patches.empty())
    s.force = scene.body_force();
  s.n_cells = scene.geometry().n_global_cells();
  s.n_steps = scene.results().n_time_steps;
  return s;
}

void compare(std::ofstream& out, const std::string& title, const std::string& name,
             const std::vector<std::string>& overrides, const bool forces)
{
  const Steady a = run(name, overrides, 0.5), b = run(name, overrides, 10. / 11.);
  double du = 0, max_u = 0, dp = 0, max_p = 0;
  for (unsigned int c = 0; c < a.u.size(); ++c)
  {
    du = std::max(du, (a.u[c] - b.u[c]).norm());
    max_u = std::max(max_u, a.u[c].norm());
    dp = std::max(dp, std::abs(a.p[c] - b.p[c]));
    max_p = std::max(max_p, std::abs(a.p[c]));
  }
  std::vector<double> differences = {du / max_u, dp / max_p};
  out << title << ", " << a.n_cells << " cells: relative difference alpha = 0.5 vs 10/11: u "
      << format("%.1e", differences[0]) << ", p " << format("%.1e", differences[1]);
  if (forces)
  {
    differences.push_back(std::abs(a.force[0] - b.force[0]) / std::abs(a.force[0]));
    differences.push_back(std::abs(a.force[1] - b.force[1]) / std::abs(a.force[1]));
    out << ", drag " << format("%.1e", differences[2]) << ", lift "
        << format("%.1e", differences[3]);
    std::printf("%s: drag %.10g %.10g, lift %.10g %.10g\n", title.c_str(), a.force[0], b.force[0],
                a.force[1], b.force[1]);
  }
  std::printf("%s: %u and %u pseudo time steps\n", title.c_str(), a.n_steps, b.n_steps);
  bool ok = true;
  for (const double d : differences)
    ok = ok && d < 1e-6;
  out << "\n  all < 1e-6: " << yes_no(ok) << "\n";
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  compare(out, "Kovasznay (distorted)", "kovasznay",
          {"Mesh/Global refinements=0", "Fluid/Steady tolerance=1e-12"}, false);
  compare(out, "Turek-Hron CFD2 channel, n = 8", "turek_hron_cfd2",
          {"Mesh/Generator arguments=8", "Fluid/Steady tolerance=1e-11"}, true);
}
