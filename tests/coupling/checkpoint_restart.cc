// Checkpoint and restart (`Checkpoint interval`, `Restart from`): a run continued from a checkpoint
// reproduces the run that was not interrupted. For each scene, three runs of 20 time steps:
//   C  uninterrupted;
//   A  to step 10 with Checkpoint interval = 10 (its checkpoint holds step 10);
//   B  Restart from = A's output directory, written into another directory, to step 20.
// The scenes, coarse versions of shipped cases, each with a state beyond the current fields:
//   - FSI: prm/turek_hron_fsi3.prm as in fsi3_coarse (1921 + 40 cells, dt = 2 ms, the fluid alone
//     to step 5, then IQN-ILS), with the columns of 2 earlier time steps reused (kept in the
//     checkpoint) and the moved fluid mesh with its old geometry (BDF2 mesh fluxes);
//   - fluid: prm/turek_hron_moving_flag.prm (Laplace mesh motion, PISO with BDF2) at n = 8;
//   - solid: prm/turek_hron_csm3.prm (St. Venant-Kirchhoff, BDF2) on a 20 x 2 flag.
// Asserted for each: B's history file (A's first 10 lines, then its own) equals C's, every number
// of every line, to 1e-12 relative to the column's largest magnitude. Restarted, the next step
// rebuilds the preconditioners, which C also does at step 11 (Fluid/Preconditioner update
// interval = 10), so the two do the same arithmetic: measured differences are exactly 0. For the
// FSI run also: B's .pvd lists A's VTU files (steps 5, 10) before its own (15, 20), and they exist.
// For the solid also: a restart whose .prm file sets another time step (0.02 s) runs on at the
// checkpoint's (0.01 s) to the end time and equals C to 1e-12.
// With np = 2 also a restart on another number of ranks: A on rank 0 alone, B on both, against C
// on both. The partition changes the preconditioners, so every solve is converged tightly there
// (as in fsi3_coarse (c)) and the force (drag, lift) and u(A) are compared as vectors, to 1e-8 of
// their largest magnitude: measured force 1.3e-10 and u(A) 2.9e-10, the level at which A's steps
// 1-10 on one rank already differ from C's on two (the coupling iterations of a step by one).
// A damaged checkpoint (the solid's A copied, then its largest file cut to half, or one byte of it
// changed) stops the restart with a message that names `Restart from` and the file, on every rank,
// before p4est or Boost read it (the manifest of sizes and CRC-32s written with the checkpoint).
#include <fvfsi/scenes/fluid_scene.h>
#include <fvfsi/scenes/fsi_scene.h>
#include <fvfsi/scenes/solid_scene.h>

#include "../test_utilities.h"
#include "fsi_case.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace fvfsi_test;

/// max over the entries of |a - b| / (largest |b| of the column); 1 if the shapes differ.
double table_difference(const std::vector<std::vector<double>>& a,
                        const std::vector<std::vector<double>>& b)
{
  if (a.size() != b.size() || a.empty())
    return 1;
  double worst = 0;
  for (unsigned int j = 0; j < b[0].size(); ++j)
  {
    double scale = 1e-300, difference = 0;
    for (unsigned int i = 0; i < b.size(); ++i)
    {
      if (a[i].size() != b[i].size())
        return 1;
      scale = std::max(scale, std::abs(b[i][j]));
      difference = std::max(difference, std::abs(a[i][j] - b[i][j]));
    }
    worst = std::max(worst, difference / scale);
  }
  return worst;
}

/// One scene kind: its shipped case, overrides and history file.
struct Case
{
  std::string name, prm, history;
  std::vector<std::string> settings;
};

const Case fsi = {"FSI",
                  "turek_hron_fsi3",
                  "fsi_history.txt",
                  {"Mesh/Generator arguments=12", "Solid mesh/Generator arguments=20: 2",
                   "Fluid/Max pressure correctors=6", // as fsi3_coarse: a start from rest
                   "Time/Time step=0.002", "Coupling/Start time=0.01",
                   "Coupling/Reuse time steps=2", "Fluid scene/Output interval=5",
                   "Fluid scene/Progress interval=100"}};
const Case fluid = {
  "fluid",
  "turek_hron_moving_flag",
  "fluid_history.txt",
  {"Mesh/Generator arguments=8", "Time/Time step=0.005", "Fluid scene/Progress interval=100"}};
const Case solid = {
  "solid",
  "turek_hron_csm3",
  "solid_history.txt",
  {"Mesh/Generator arguments=20: 2", "Time/Time step=0.01", "Solid scene/Progress interval=100"}};

/// Every solve converged far below 1e-8 (a restart on another number of ranks).
const std::vector<std::string> tight = converged_solves("1e-10", "1e-9");

/// Run `c` for `steps` time steps on `comm` into `directory` with `extra` overrides.
void run(const Case& c, const unsigned int steps, const std::vector<std::string>& extra,
         MPI_Comm comm, const std::string& directory)
{
  std::filesystem::create_directories(directory);
  auto settings = c.settings;
  settings.insert(settings.end(), extra.begin(), extra.end());
  settings.push_back("Output directory=" + directory);
  auto p = shipped_case(c.prm, settings);
  p->time.end_time = steps * p->time.time_step;
  const std::string prm = std::string(FVFSI_SOURCE_DIR) + "/prm";
  if (c.name == "FSI")
  {
    fvfsi::FsiScene<2> scene(p->fsi_input(), comm, prm, directory);
    scene.set_checkpoints(p->run.checkpoint);
    scene.run();
  }
  else if (c.name == "fluid")
  {
    fvfsi::FluidScene<2> scene(p->mesh, p->fluid, p->fluid_scene, p->time, comm, prm, directory);
    scene.set_checkpoints(p->run.checkpoint);
    scene.run();
  }
  else
  {
    fvfsi::SolidScene<2> scene(p->mesh, p->solid, p->solid_scene, p->time, comm, prm, directory);
    scene.set_checkpoints(p->run.checkpoint);
    scene.run();
  }
}

/// C, A, B of `c` with `extra` overrides, A on `comm_A`; returns the history tables of B and C.
std::pair<std::vector<std::vector<double>>, std::vector<std::vector<double>>>
restart_and_full(const Case& c, const std::vector<std::string>& extra, MPI_Comm comm_A,
                 const std::string& tag)
{
  const std::string a = "out_" + tag + "_A", b = "out_" + tag + "_B", full = "out_" + tag + "_C";
  run(c, 20, extra, MPI_COMM_WORLD, full);
  if (comm_A != MPI_COMM_NULL)
  {
    auto with_checkpoints = extra;
    with_checkpoints.push_back("Checkpoint interval=10");
    run(c, 10, with_checkpoints, comm_A, a);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  auto restarted = extra;
  restarted.push_back("Restart from=" + a);
  run(c, 20, restarted, MPI_COMM_WORLD, b);
  return {read_table(b + "/" + c.history), read_table(full + "/" + c.history)};
}

/// Prints the difference of two history tables to the log and writes to `out`, on rank 0, whether
/// it is within 1e-12 (the same arithmetic): "`claim` (1e-12): yes".
void report_equal(std::ostream& out, const unsigned int rank, const std::string& claim,
                  const double difference)
{
  if (rank != 0)
    return;
  std::printf("%s: max relative difference %.2e\n", claim.c_str(), difference);
  out << claim << " (1e-12): " << yes_no(difference <= 1e-12) << "\n";
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const bool parallel = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;

  for (const Case* c : {&fsi, &fluid, &solid})
  {
    const auto [restarted, full] = restart_and_full(*c, {}, MPI_COMM_WORLD, c->name);
    report_equal(out, rank, c->name + ": the restarted run's history equals the uninterrupted one",
                 table_difference(restarted, full));
  }

  // A restart continues at the checkpoint's time step whatever the .prm file sets: the solid's B
  // again from A's checkpoint (dt = 0.01 s, step 10), its .prm now with dt = 0.02 s and the same end
  // time (10 x 0.02 = 0.2 s). The run's step count comes from the restored clock, so it takes the
  // 10 steps of 0.01 s left and equals C; counted from the .prm's clock it would stop at once.
  {
    run(solid, 10, {"Time/Time step=0.02", "Restart from=out_solid_A"}, MPI_COMM_WORLD,
        "out_solid_dt");
    report_equal(out, rank,
                 "solid: a restart whose .prm sets dt = 0.02 s continues at the checkpoint's "
                 "0.01 s to the end time and equals the uninterrupted run",
                 table_difference(read_table("out_solid_dt/" + solid.history),
                                  read_table("out_solid_C/" + solid.history)));
  }

  // The .pvd of the restarted FSI run: A's files first.
  if (rank == 0)
  {
    std::ifstream pvd("out_FSI_B/fluid.pvd");
    std::string line;
    std::vector<std::string> files;
    while (std::getline(pvd, line))
      if (const auto i = line.find("file=\""); i != std::string::npos)
        files.push_back(line.substr(i + 6, line.find('"', i + 6) - i - 6));
    bool found = files.size() == 4;
    for (const auto& f : files)
      found = found && std::filesystem::exists("out_FSI_B/" + f);
    out << "FSI: the restarted run's fluid.pvd lists the 2 earlier and 2 new VTU files, which "
           "exist: "
        << yes_no(found && files[0].find("out_FSI_A") != std::string::npos) << "\n";
  }

  // Damaged checkpoints: cut short, and changed at the same size.
  for (const bool cut : {true, false})
  {
    const std::string damaged = cut ? "out_damaged_cut" : "out_damaged_byte";
    std::string file;
    if (rank == 0)
    {
      std::filesystem::remove_all(damaged);
      std::filesystem::create_directories(damaged);
      std::filesystem::copy("out_solid_A/checkpoint", damaged + "/checkpoint");
      std::uintmax_t largest = 0;
      for (const auto& entry : std::filesystem::directory_iterator(damaged + "/checkpoint"))
        if (entry.file_size() > largest)
          largest = entry.file_size(), file = entry.path().string();
      if (cut)
        std::filesystem::resize_file(file, largest / 2);
      else
      {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(largest / 2);
        const char byte = static_cast<char>(f.get() ^ 0x5a);
        f.seekp(largest / 2);
        f.put(byte);
      }
      file = std::filesystem::path(file).filename().string();
    }
    MPI_Barrier(MPI_COMM_WORLD);
    std::string message;
    try
    {
      run(solid, 20, {"Restart from=" + damaged}, MPI_COMM_WORLD, damaged + "_B");
    }
    catch (const std::exception& e)
    {
      message = e.what();
    }
    if (rank == 0)
    {
      std::printf("damaged checkpoint: %s\n", message.c_str());
      out << "solid: a restart from a checkpoint whose largest file is "
          << (cut ? "cut to half its size" : "changed in one byte")
          << " stops with a message naming Restart from and the file: "
          << yes_no(message.find("Restart from") != std::string::npos &&
                    message.find("`" + file + "`") != std::string::npos)
          << "\n";
    }
  }

  if (parallel)
  {
    // A on rank 0 alone, B and C on both ranks.
    MPI_Comm self_on_rank_0;
    MPI_Comm_split(MPI_COMM_WORLD, rank == 0 ? 0 : MPI_UNDEFINED, 0, &self_on_rank_0);
    const auto [restarted, full] = restart_and_full(fsi, tight, self_on_rank_0, "ranks");
    if (self_on_rank_0 != MPI_COMM_NULL)
      MPI_Comm_free(&self_on_rank_0);
    // The force (drag, lift) and u(A) as vectors, as fsi3_coarse (c) compares 1 and 2 ranks.
    const double force = vector_difference(restarted, full, {3, 4}),
                 u_A = vector_difference(restarted, full, {5, 6});
    if (rank == 0)
    {
      std::printf("FSI, checkpoint on 1 rank, restart on 2: max relative differences force "
                  "%.2e, u(A) %.2e\n",
                  force, u_A);
      out << "FSI: a checkpoint of 1 rank continued on 2 equals the uninterrupted run on 2 "
             "(tight solves; force and u(A) every step to 1e-8): "
          << yes_no(std::max(force, u_A) <= 1e-8) << "\n";
    }
  }
}
