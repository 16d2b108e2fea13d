// SIMPLEC in the steady fluid (`Fluid/Consistent pressure coupling = true`):
// prm/turek_hron_cfd2.prm on a coarse channel (n = 12, 1921 cells) with the mean inflow U = 0.01,
// 0.2 and 1 m/s (Re = 1, 20, 100), Momentum relaxation 0.95, steady tolerance 1e-9.
//   (a) SIMPLEC converges at alpha = 0.95 without lowering it, also at Re = 1 where SIMPLE's
//       pressure correction (1 / a_P, 1 / (1 - alpha) = 20 times too strong for a smooth
//       correction where viscosity dominates) oscillates and solve_steady() lowers alpha to 0.8
//       (tests/fluid/fluid_steady_range);
//   (b) the same steady state: the drag equals SIMPLE's at a fixed alpha = 0.7 to 1e-6 relative
//       (SIMPLEC's predicted fluxes carry the difference of the two coefficients times the last
//       pressure gradient, so that its fixed point has SIMPLE's Rhie-Chow flux; measured
//       differences ~1e-9, the steady tolerance);
//   (c) at Re = 1 fewer pseudo steps than SIMPLE from alpha = 0.95.
// Printed: verdicts, and the pseudo steps to stdout only (they depend on round-off).
#include "steady_channel.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace fvfsi_test;

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  for (const double U : {0.01, 0.2, 1.0})
  {
    const Result simplec = run_steady_channel(U, {"Fluid/Consistent pressure coupling=true"});
    const Result simple = run_steady_channel(U, {});
    const Result fixed = run_steady_channel(U, {"Fluid/Momentum relaxation=0.7"});
    std::printf("U = %g: SIMPLEC %u pseudo steps (alpha %.3g at the end), SIMPLE %u (alpha %.3g), "
                "SIMPLE at alpha 0.7 %u; drag %.12g / %.12g\n",
                U, simplec.pseudo_steps, simplec.relaxation, simple.pseudo_steps, simple.relaxation,
                fixed.pseudo_steps, simplec.drag, fixed.drag);
    out << format("Re = %g: SIMPLEC converged at alpha 0.95 throughout: ", U / 1e-2)
        << yes_no(simplec.error.empty() && simplec.relaxation == 0.95)
        << ", the drag of SIMPLE at alpha 0.7 to 1e-6: "
        << yes_no(fixed.error.empty() &&
                  std::abs(simplec.drag - fixed.drag) <= 1e-6 * std::abs(fixed.drag));
    if (U == 0.01)
      out << ", fewer pseudo steps than SIMPLE from alpha 0.95: "
          << yes_no(simplec.pseudo_steps < simple.pseudo_steps);
    out << "\n";
  }
}
