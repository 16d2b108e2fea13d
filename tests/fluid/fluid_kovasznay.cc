// Spatial order of the fluid solver: Kovasznay flow at Re = 40 (prm/kovasznay.prm, an exact
// steady Navier-Stokes solution) on a randomly distorted coarse mesh (interior vertices moved by
// up to 0.25 of the local edge; 192 cells) and its first two refinements (768, 3072 cells). Steady,
// linear-upwind convection, exact velocity on the whole boundary.
// Asserted: observed order of the max velocity error and of the L2 velocity and pressure errors
// >= 1.8 on the finest pair. (The max pressure error sits in cells at the walls, where the
// pressure extrapolated to the wall is first order; it is printed, not asserted.)
// Errors are printed with 3 significant digits: the converged solution is independent of the
// solver settings to ~1e-9 (steady tolerance 1e-9), far below that.
#include <fvfsi/apps/fluid_scene.h>

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
  bool ok = true;
  for (const unsigned int r : {0u, 1u, 2u})
  {
    const auto p = shipped_case("kovasznay", {"Mesh/Global refinements=" + std::to_string(r),
                                              "Output directory=out"});
    std::filesystem::create_directories("out");
    fvfsi::FluidScene<2> scene(p->mesh, p->fluid, p->fluid_scene, MPI_COMM_WORLD, ".", "out");
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
  }
  out << "max u, L2 u and L2 p orders >= 1.8 on the finest pair: " << yes_no(ok) << "\n";
}
