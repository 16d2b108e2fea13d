// np = 2 equals np = 1 for the fluid solver over 20 transient PISO + BDF2 time steps: the fields
// computed on all ranks are gathered by cell centroid and compared with a run on rank 0 alone
// (MPI_COMM_SELF), as in tests/core/solid_parallel.cc (with np > 1, the reference of (a) runs on
// rank 0 while that of (b) runs on the last rank):
//   (a) Turek-Hron channel (fvfsi_turek_hron_channel, n = 12: 1921 cells), Re = 200, parabolic
//       inflow with mean velocity 2 m/s from a parabolic initial field, outlet p = 0, no-slip
//       cylinder and flag, dt = 0.002 s (Courant number 1.3 at the cylinder); also drag and lift,
//       and u, p at two point probes (`Fluid scene/Probes`);
//   (b) Kovasznay flow (prm/kovasznay.prm made transient, 768 cells randomly distorted by 0.25 of
//       the local edge) from u = (1, 0), dt = 0.01 s, exact velocity on the whole boundary: no
//       outlet, so the pressure level is fixed in global cell 0.
// Asserted: every cell matched, max |u_np - u_1| / max |u_1|, max |p_np - p_1| / max |p_1| (and
// the relative drag and lift differences) < 1e-8. Every linear solve is converged by 1e-10, so
// what is left is the partition dependence of the ILU (block Jacobi) and AMG preconditioners at
// that level: measured 2e-14 ... 6e-12 relative with np = 2 (np = 1: 0). Only yes/no verdicts are
// printed, so that NAME.output and NAME.mpirun=2.output are the same file and numdiff's default
// tolerance is irrelevant. (A mesh of 1921 + 768 cells keeps the np = 2 run near 10 s on a loaded
// 2-core machine, where every MPI message waits for the other rank to be scheduled.)
#include <fvfsi/scenes/fluid_scene.h>

#include "../test_utilities.h"

#include <cstdio>
#include <filesystem>
#include <map>

using namespace fvfsi_test;

using Values = std::vector<std::pair<std::array<double, 2>, std::array<double, 3>>>; // x -> u, v, p

struct Run
{
  Values values;
  dealii::Tensor<1, 2> force;
  std::vector<std::array<double, 3>> probes; // u, v, p [Pa] at each probe
};

Run run(const fvfsi::AllParameters& p, MPI_Comm comm, const std::string& directory)
{
  std::filesystem::create_directories(directory);
  fvfsi::FluidScene<2> scene(p.mesh, p.fluid, p.fluid_scene, p.time, comm, ".", directory);
  scene.run();
  Run r;
  const auto& fv = scene.geometry();
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
    r.values.emplace_back(
      std::array<double, 2>{{fv.centroid[c][0], fv.centroid[c][1]}},
      std::array<double, 3>{{scene.solver().velocity()[c][0], scene.solver().velocity()[c][1],
                             scene.solver().kinematic_pressure().local_element(c)}});
  if (!p.fluid_scene.force_patches.empty())
    r.force = scene.body_force();
  for (unsigned int i = 0; i < scene.point_probes().size(); ++i)
  {
    const auto [u, pressure] = scene.probe_values(i);
    r.probes.push_back({{u[0], u[1], pressure / p.fluid.rho}});
  }
  return r;
}

/// Relative differences of `gathered` (all ranks' cells) from `reference` (one rank alone), and
/// the verdict line.
void compare(std::ofstream& out, const std::string& title, const std::vector<Values>& gathered,
             const Run& reference_run, const Run& parallel, const bool forces)
{
  std::map<std::array<double, 2>, std::array<double, 3>> reference;
  double max_u = 0, max_p = 0;
  for (const auto& [x, v] : reference_run.values)
  {
    reference[x] = v;
    max_u = std::max(max_u, std::hypot(v[0], v[1]));
    max_p = std::max(max_p, std::abs(v[2]));
  }
  double du = 0, dp = 0;
  unsigned int matched = 0;
  for (const auto& part : gathered)
    for (const auto& [x, v] : part)
      if (const auto it = reference.find(x); it != reference.end())
      {
        ++matched;
        du = std::max(du, std::hypot(v[0] - it->second[0], v[1] - it->second[1]));
        dp = std::max(dp, std::abs(v[2] - it->second[2]));
      }
  for (unsigned int i = 0; i < reference_run.probes.size(); ++i)
  {
    const auto &a = parallel.probes[i], &b = reference_run.probes[i];
    du = std::max(du, std::hypot(a[0] - b[0], a[1] - b[1]));
    dp = std::max(dp, std::abs(a[2] - b[2]));
  }
  std::vector<double> differences = {du / max_u, dp / max_p};
  if (forces)
    for (unsigned int d = 0; d < 2; ++d)
      differences.push_back(std::abs(parallel.force[d] - reference_run.force[d]) /
                            std::abs(reference_run.force[d]));
  bool ok = true;
  std::printf("%s: relative differences", title.c_str());
  for (const double d : differences)
  {
    std::printf(" %.2e", d);
    ok = ok && d < 1e-8;
  }
  std::printf("\n");
  out << title << ": " << reference.size()
      << " cells, all matched: " << yes_no(matched == reference.size()) << ", u and p"
      << (parallel.probes.empty() ? "" : " (cells and probes)") << (forces ? ", drag and lift" : "")
      << " of np equal np = 1 to 1e-8 relative: " << yes_no(ok) << "\n";
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const std::string inflow = "1.5*2*4*y*(0.41-y)/0.41^2; 0";
  const std::vector<std::string> tight = {"Fluid momentum solver/Residual reduction=1e-10",
                                          "Fluid pressure solver/Residual reduction=1e-10",
                                          "Fluid scene/Output interval=0",
                                          "Fluid scene/Analysis window=0"};
  std::vector<std::string> channel = {"Mesh/Generator arguments=12",
                                      "Time/Time step=0.002",
                                      "Time/End time=0.04",
                                      "Fluid/Initial velocity=" + inflow,
                                      "Fluid/Velocity inlet=inlet: " + inflow,
                                      "Fluid scene/Probes=wake: 0.8, 0.2 | above: 0.4, 0.3"};
  channel.insert(channel.end(), tight.begin(), tight.end());
  std::vector<std::string> kovasznay = {"Mesh/Global refinements=1", "Fluid/Transient=true",
                                        "Time/Time step=0.01", "Time/End time=0.2"};
  kovasznay.insert(kovasznay.end(), tight.begin(), tight.end());
  const std::array<std::unique_ptr<fvfsi::AllParameters>, 2> cases = {
    {shipped_case("turek_hron_cfd3", channel), shipped_case("kovasznay", kovasznay)}};

  // Both cases on all ranks, then the one-rank references: the first case on rank 0, the second
  // on the last rank (at the same time when np > 1), sent to rank 0.
  const MPI_Comm comm = MPI_COMM_WORLD;
  const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm),
                     last = dealii::Utilities::MPI::n_mpi_processes(comm) - 1;
  std::array<Run, 2> parallel, reference;
  std::array<std::vector<Values>, 2> gathered;
  for (unsigned int i = 0; i < 2; ++i)
  {
    parallel[i] = run(*cases[i], comm, "out_" + std::to_string(i));
    gathered[i] = dealii::Utilities::MPI::gather(comm, parallel[i].values);
  }
  if (rank == 0)
    reference[0] = run(*cases[0], MPI_COMM_SELF, "out_reference_0");
  if (rank == last)
    reference[1] = run(*cases[1], MPI_COMM_SELF, "out_reference_1");
  if (last > 0)
  {
    const auto all = dealii::Utilities::MPI::gather(comm, reference[1].values);
    if (rank == 0)
      reference[1].values = all[last];
  }
  if (rank != 0)
    return 0;
  compare(out, "Turek-Hron channel, 20 steps", gathered[0], reference[0], parallel[0], true);
  std::printf("drag %.10g, lift %.10g\n", reference[0].force[0], reference[0].force[1]);
  compare(out, "Kovasznay (distorted), 20 steps", gathered[1], reference[1], parallel[1], false);
}
