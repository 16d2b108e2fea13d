// Steady FSI (Fluid/Transient = Solid/Transient = false): prm/fsi_pressure_column.prm with the
// full gravity g = 10 m/s^2 from the start, solved for its steady state directly. The water
// column at rest presses hydrostatically on the elastic block, whose top sinks by
//   d = rho g H h / (M - rho g h) = 3.715668e-4 m,  M = E (1 - nu) / ((1 + nu)(1 - 2 nu))
// (the number of tests/coupling/fsi_pressure_column). Each coupling iteration converges the
// steady fluid on the moved mesh and the static block under its tractions.
// Asserted:
//   - d within 1e-8 of the exact value (relative): a steady state has no dynamic oscillation
//     left, and the discrete hydrostatic state and the uniaxial strain of the block are exact up
//     to the solver tolerances (measured 7e-11);
//   - at most 6 coupling iterations (measured 4, IQN-ILS; the added mass that makes the transient
//     column take 449 iterations over 120 steps does not exist in a steady state);
//   - a steady fluid with a transient solid stops with an error naming Solid/Transient.
// Momentum relaxation 0.7: a fluid at rest has no convection, and the local pseudo time step of
// 0.95 (its viscous part alone) is so long that the pseudo steps oscillate.
// Verdicts only: np = 1 and np = 2 write the same file.
#include <fvfsi/scenes/fsi_scene.h>

#include "../test_utilities.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace fvfsi_test;

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  std::filesystem::create_directories("out");
  const std::vector<std::string> steady = {"Fluid/Transient=false", "Solid/Transient=false",
                                           "Fluid/Body force=0; -10",
                                           "Fluid/Momentum relaxation=0.7", "Output directory=out"};
  const double exact = 5000 / (1e7 * 0.7 / (1.3 * 0.4) - 5000);
  {
    const auto p = shipped_case("fsi_pressure_column", steady);
    fvfsi::FsiScene<2> scene(p->fsi_input(), MPI_COMM_WORLD, ".", "out");
    scene.run();
    const double d = -scene.solid_probe(0)[1];
    const unsigned int k = scene.results().total_coupling_iterations;
    std::printf("steady column: d = %.10e m (error %.2e), %u coupling iterations\n", d,
                std::abs(d - exact) / exact, k);
    out << "steady column: d within 1e-8 of the static solution: "
        << yes_no(std::abs(d - exact) < 1e-8 * exact) << "\n";
    out << "at most 6 coupling iterations: " << yes_no(k <= 6) << "\n";
    out << "fsi_steady_history.txt written: "
        << yes_no(std::filesystem::exists("out/fsi_steady_history.txt")) << "\n";
  }
  {
    auto overrides = steady;
    overrides[1] = "Solid/Transient=true";
    const auto p = shipped_case("fsi_pressure_column", overrides);
    std::string error;
    try
    {
      fvfsi::FsiScene<2> scene(p->fsi_input(), MPI_COMM_WORLD, ".", "out");
    }
    catch (const std::exception& e)
    {
      error = e.what();
    }
    out << "steady fluid with a transient solid: an error naming Solid/Transient: "
        << yes_no(error.find("Solid/Transient") != std::string::npos) << "\n";
  }
}
