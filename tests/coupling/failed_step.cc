// A failed time step leaves a usable state, and Time step control retries it with half the time
// step. The coarse Turek-Hron FSI3 of checkpoint_restart (20 steps of 2 ms, the fluid alone to
// step 5, IQN-ILS with 4 to 10 coupling iterations per coupled step), with the preconditioners
// rebuilt every step (Fluid/Preconditioner update interval = 1, so that a run continued from any
// step does the arithmetic of an uninterrupted one), run five ways:
//   U  to step 20: the reference;
//   A  to step 10 with a checkpoint there;
//   F  continued from A with Solid/Max outer iterations = 150: the first later step whose solid
//      solve needs more (step 15) stops the run;
//   R  continued from what F wrote, with the shipped 20000, to step 20;
//   T  continued from A with 150 and Time/Time step control = 4.
// Asserted:
//   (a) F ends with an error naming the time step and the solid's iterations, after writing the
//       state of the step before it as a checkpoint and as VTU (a .pvd record at its time);
//   (b) what F wrote is the last converged state itself: R reproduces U's history exactly (every
//       number of every line to 1e-12 relative; measured 0);
//   (c) T runs to the end time: the step F stopped at is tried again with dt / 2, where the solid
//       converges within 150 iterations (its larger inertia term), and the run goes on with it (the
//       dt column of fsi_history.txt). (A smaller dt does not help coupling iterations that do not
//       converge: the added-mass effect of this flag grows as dt shrinks.)
//   (d) the same for a solid scene (prm/turek_hron_csm3.prm on a 20 x 2 flag, dt = 0.01 s, 20
//       steps of 574 to 1792 outer iterations): continued from step 10 with Solid/Max outer
//       iterations = 1100 it stops at step 13 (1541 needed) after writing step 12, and continued
//       from that with the shipped limit it equals the uninterrupted run exactly.
#include <fvfsi/scenes/fsi_scene.h>
#include <fvfsi/scenes/solid_scene.h>

#include "../test_utilities.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

using namespace fvfsi_test;

/// Runs the case into `directory`; returns the error message ("" if it ran through).
std::string run(const std::vector<std::string>& extra, const std::string& directory)
{
  std::filesystem::create_directories(directory);
  std::vector<std::string> settings = {
    "Mesh/Generator arguments=12",
    "Solid mesh/Generator arguments=20: 2",
    "Fluid/Max pressure correctors=6", // as fsi3_coarse: a start from rest
    "Time/Time step=0.002",
    "Time/End time=0.04",
    "Coupling/Start time=0.01",
    "Fluid/Preconditioner update interval=1",
    "Fluid scene/Output interval=0",
    "Fluid scene/Progress interval=100",
    "Output directory=" + directory};
  settings.insert(settings.end(), extra.begin(), extra.end());
  auto p = shipped_case("turek_hron_fsi3", settings);
  try
  {
    fvfsi::FsiScene<2> scene(p->fsi_input(), MPI_COMM_WORLD, ".", directory);
    scene.set_checkpoints(p->run.checkpoint);
    scene.run();
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  return "";
}

/// The solid scene of (d), as run() does the FSI one.
std::string run_solid(const std::vector<std::string>& extra, const std::string& directory)
{
  std::filesystem::create_directories(directory);
  std::vector<std::string> settings = {"Mesh/Generator arguments=20: 2", "Time/Time step=0.01",
                                       "Time/End time=0.2", "Solid scene/Progress interval=100",
                                       "Output directory=" + directory};
  settings.insert(settings.end(), extra.begin(), extra.end());
  auto p = shipped_case("turek_hron_csm3", settings);
  try
  {
    fvfsi::SolidScene<2> scene(p->mesh, p->solid, p->solid_scene, p->time, MPI_COMM_WORLD, ".",
                               directory);
    scene.set_checkpoints(p->run.checkpoint);
    scene.run();
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  return "";
}

/// max over the entries of |a - b| / (largest |b| of the column); 1 if the shapes differ.
double table_difference(const std::vector<std::vector<double>>& a,
                        const std::vector<std::vector<double>>& b)
{
  double worst = a.size() == b.size() && !b.empty() ? 0 : 1;
  for (unsigned int j = 0; worst < 1 && j < b[0].size(); ++j)
  {
    double scale = 1e-300, difference = 0;
    for (unsigned int i = 0; i < b.size(); ++i)
    {
      scale = std::max(scale, std::abs(b[i][j]));
      difference = std::max(difference, std::abs(a[i][j] - b[i][j]));
    }
    worst = std::max(worst, difference / scale);
  }
  return worst;
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  const std::string limit = "Solid/Max outer iterations=150";
  run({}, "out_U");
  run({"Time/End time=0.02", "Checkpoint interval=10"}, "out_A");
  const std::string failure = run({limit, "Restart from=out_A"}, "out_F");
  run({"Restart from=out_F"}, "out_R");
  const std::string controlled =
    run({limit, "Time/Time step control=4", "Restart from=out_A"}, "out_T");
  run_solid({}, "out_solid_U");
  run_solid({"Time/End time=0.1", "Checkpoint interval=10"}, "out_solid_A");
  const std::string solid_failure =
    run_solid({"Solid/Max outer iterations=1100", "Restart from=out_solid_A"}, "out_solid_F");
  run_solid({"Restart from=out_solid_F"}, "out_solid_R");
  if (!root)
    return 0;

  // (a)
  const auto U = read_table("out_U/fsi_history.txt"), F = read_table("out_F/fsi_history.txt");
  const unsigned int failed_step = F.size() + 1;
  std::printf("F: %s\n", failure.c_str());
  std::printf("F stopped at time step %u\n", failed_step);
  out << "F stops with an error naming the time step and the solid's outer iterations: "
      << yes_no(failure.find("time step " + std::to_string(failed_step)) != std::string::npos &&
                failure.find("outer iterations did not converge") != std::string::npos)
      << "\n";
  std::ifstream pvd("out_F/fluid.pvd");
  const std::string record((std::istreambuf_iterator<char>(pvd)), std::istreambuf_iterator<char>());
  const double t_last = 0.002 * (failed_step - 1);
  out << "F stops at a coupled step after step 10 and wrote the state of the step before as VTU "
         "and a checkpoint: "
      << yes_no(failed_step > 10 && failed_step <= 20 &&
                std::filesystem::exists("out_F/checkpoint/state") &&
                record.find(format("timestep=\"%g\"", t_last)) != std::string::npos)
      << "\n";

  // (b)
  const double worst = table_difference(read_table("out_R/fsi_history.txt"), U);
  std::printf("R - U: max relative difference %.2e\n", worst);
  out << "restarted from what F wrote, the run equals the one that did not fail (1e-12): "
      << yes_no(worst <= 1e-12) << "\n";

  // (c) columns: t, coupling_iterations, ..., min_volume_ratio, dt
  const auto T = read_table("out_T/fsi_history.txt");
  bool retried = T.size() > failed_step;
  for (unsigned int i = failed_step - 1; retried && i < T.size(); ++i)
    retried = std::abs(T[i].back() - 0.001) < 1e-12;
  std::printf("T: %zu time steps, error \"%s\"\n", T.size(), controlled.c_str());
  out << "with Time step control the run reaches the end time, from F's failed step on with "
         "dt / 2 (dt column): "
      << yes_no(controlled.empty() && !T.empty() && std::abs(T.back()[0] - 0.04) < 1e-9 && retried)
      << "\n";

  // (d)
  const auto solid_U = read_table("out_solid_U/solid_history.txt");
  const double solid_difference =
    table_difference(read_table("out_solid_R/solid_history.txt"), solid_U);
  std::printf("solid: %s\nsolid R - U: max relative difference %.2e\n", solid_failure.c_str(),
              solid_difference);
  out << "solid scene: stops at time step 13 after writing step 12, and continued from that it "
         "equals the run that did not fail (1e-12): "
      << yes_no(solid_failure.find("time step 13") != std::string::npos &&
                read_table("out_solid_F/solid_history.txt").size() == 12 &&
                solid_difference <= 1e-12)
      << "\n";
}
