// Mesh sequencing of the steady FSI path (`Initial state from`): prm/cavity_flexible_bottom.prm,
// the channel over a cavity with a flexible bottom, started from the final state of an earlier
// steady run (its fluid_state.txt and interface_state.txt).
//   (a) h = 0.1 from rest, and from the state of h = 0.2 (a mesh twice as coarse): the same
//       u_y(A) to 1e-5 relative (the two runs stop at different points inside the
//       coupling tolerance, 1e-6 |d~|, and the steady fluid's, 1e-6 per pseudo step; measured
//       2.0e-8), and fewer fluid pseudo steps and coupling iterations from the coarse state
//       (measured 147 against 209, 5 against 7, with the shipped SIMPLEC and Newton solid, on
//       uniform plates; the gain the fine meshes of doc/results/cavity.md take);
//   (b) the errors: a missing state names the parameter and the file; a transient run refuses it.
// Verdicts only: np = 1 and np = 2 write the same file.
#include <fvfsi/scenes/fsi_scene.h>

#include "../test_utilities.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace fvfsi_test;

namespace
{
  struct CavityRun
  {
    double uy_A;
    unsigned int coupling_iterations, pseudo_steps;
  };

  /// The cavity at cell size h, written to `directory`, started from `initial_state` ("": rest).
  CavityRun run_cavity(const std::string& h, const std::string& directory,
                       const std::string& initial_state)
  {
    const auto p =
      shipped_case("cavity_flexible_bottom",
                   {"Mesh/Generator arguments=" + h, "Solid mesh/Generator arguments=" + h,
                    "Output directory=" + directory, "Initial state from=" + initial_state});
    std::filesystem::create_directories(directory);
    fvfsi::FsiScene<2> scene(p->fsi_input(), MPI_COMM_WORLD, ".", directory);
    scene.set_checkpoints(p->run.checkpoint);
    scene.run();
    const CavityRun run{scene.solid_probe(0)[1], scene.results().total_coupling_iterations,
                        scene.fluid_solver().pseudo_steps()};
    std::printf("h = %s from %s: u_y(A) = %.10f m, %u coupling iterations, %u pseudo steps\n",
                h.c_str(), initial_state.empty() ? "rest" : initial_state.c_str(), run.uy_A,
                run.coupling_iterations, run.pseudo_steps);
    return run;
  }

  double relative(const double a, const double b)
  {
    return std::abs(a - b) / std::abs(b);
  }
} // namespace

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();

  run_cavity("0.2", "coarse", "");
  const CavityRun rest = run_cavity("0.1", "rest", "");
  const CavityRun sequenced = run_cavity("0.1", "sequenced", "coarse");
  std::printf("(a) difference %.2e\n", relative(sequenced.uy_A, rest.uy_A));
  out << "(a) from the coarse state: the same u_y(A) to 1e-5: "
      << yes_no(relative(sequenced.uy_A, rest.uy_A) < 1e-5) << "\n";
  out << "(a) fewer fluid pseudo steps and coupling iterations than from rest: "
      << yes_no(sequenced.pseudo_steps < rest.pseudo_steps &&
                sequenced.coupling_iterations < rest.coupling_iterations)
      << "\n";

  std::string error;
  try
  {
    run_cavity("0.1", "missing", "no_such_run");
  }
  catch (const std::exception& e)
  {
    error = e.what();
  }
  out << "(b) a missing state: an error naming the parameter and the file: "
      << yes_no(error.find("Initial state from") != std::string::npos &&
                error.find("no_such_run/fluid_state.txt") != std::string::npos)
      << "\n";
  error.clear();
  try
  {
    const auto p = shipped_case("turek_hron_fsi3", {"Initial state from=rest"});
    fvfsi::FsiScene<2> scene(p->fsi_input(), MPI_COMM_WORLD, ".", "out");
    scene.set_checkpoints(p->run.checkpoint);
    scene.run();
  }
  catch (const std::exception& e)
  {
    error = e.what();
  }
  out << "(b) a transient run with an initial state: an error naming it: "
      << yes_no(error.find("Initial state from") != std::string::npos) << "\n";
}
