// Spatial order of the fluid solver: Kovasznay flow at Re = 40 (prm/kovasznay.prm, an exact
// steady Navier-Stokes solution) on a randomly distorted coarse mesh (interior vertices moved by
// up to 0.25 of the local edge; 192 cells) and its first two refinements (768, 3072 cells). Steady,
// linear-upwind convection, exact velocity on the whole boundary.
// Asserted: observed order of the max velocity error and of the L2 velocity and pressure errors
// >= 1.8 on the finest pair. (The max pressure error sits in cells at the walls, where the
// pressure extrapolated to the wall is first order; it is printed, not asserted.)
// Point probes (`Fluid scene/Probes`): three points away from cell centres, where the probe reads
// the linear reconstruction u_P + (x - r_P).(grad u)_P of the cell that holds the point. Asserted:
// the max probe velocity error against the exact u(x) falls at order >= 1.8 on the finest pair
// (a probe is as accurate as the cells), and the probe columns of fluid_history.txt are named.
// Errors are printed with 3 significant digits: the converged solution is independent of the
// solver settings to ~1e-9 (steady tolerance 1e-9), far below that.
#include <fvfsi/base/parsed_function.h>
#include <fvfsi/scenes/fluid_scene.h>

#include "../test_utilities.h"

#include <cmath>
#include <filesystem>

using namespace fvfsi_test;

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  out << "cells  max|u-u_h|  L2(u)  max|p-p_h|  L2(p)   orders: max u, L2 u, max p, L2 p\n";
  std::array<double, 4> previous{};
  std::vector<double> probe_errors, cell_errors;
  bool ok = true;
  for (const unsigned int r : {0u, 1u, 2u})
  {
    const auto p = shipped_case("kovasznay", {"Mesh/Global refinements=" + std::to_string(r),
                                              "Output directory=out",
                                              "Fluid scene/Probes=A: 0.13, 0.41 | B: -0.31, 1.17 | "
                                              "C: 0.77, -0.21"});
    std::filesystem::create_directories("out");
    fvfsi::FluidScene<2> scene(p->mesh, p->fluid, p->fluid_scene, p->time, MPI_COMM_WORLD, ".",
                               "out");
    scene.run();
    const auto& res = scene.results();
    const std::array<double, 4> e = {res.max_velocity_error, res.l2_velocity_error,
                                     res.max_pressure_error, res.l2_pressure_error};
    out << scene.geometry().n_global_cells();
    for (const double x : e)
      out << format("  %.3e", x);
    if (previous[0] > 0)
    {
      out << "  ";
      for (unsigned int i = 0; i < 4; ++i)
        out << format(" %.2f", std::log2(previous[i] / e[i]));
      if (r == 2)
        ok = std::log2(previous[0] / e[0]) >= 1.8 && std::log2(previous[1] / e[1]) >= 1.8 &&
             std::log2(previous[3] / e[3]) >= 1.8;
    }
    out << "\n";
    previous = e;

    dealii::FunctionParser<2> exact(2);
    fvfsi::initialize_function(exact, p->fluid_scene.exact_velocity, "exact velocity");
    double probe_error = 0;
    for (unsigned int i = 0; i < scene.point_probes().size(); ++i)
    {
      const auto x = scene.point_probes().point(i);
      const auto [u, pressure] = scene.probe_values(i);
      for (unsigned int d = 0; d < 2; ++d)
        probe_error = std::max(probe_error, std::abs(u[d] - exact.value(x, d)));
    }
    probe_errors.push_back(probe_error);
    cell_errors.push_back(res.max_velocity_error);
  }
  out << "max u, L2 u and L2 p orders >= 1.8 on the finest pair: " << yes_no(ok) << "\n";
  out << "max probe velocity error:";
  for (const double e : probe_errors)
    out << format("  %.3e", e);
  const double probe_order = std::log2(probe_errors[1] / probe_errors[2]);
  out << format(", order on the finest pair %.2f", probe_order) << "\n";
  bool below = true;
  for (unsigned int i = 0; i < probe_errors.size(); ++i)
    below = below && probe_errors[i] < cell_errors[i];
  out << "probe velocity error < max cell velocity error on every mesh: " << yes_no(below) << "\n";
  std::ifstream history("out/fluid_history.txt");
  std::string header;
  std::getline(history, header);
  out << "fluid_history.txt header: " << header << "\n";
}
