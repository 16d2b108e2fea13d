// A short, coarse Turek-Hron FSI3 (prm/turek_hron_fsi3.prm on a 1921-cell channel, n = 12, and a
// 20 x 2 flag, dt = 2 ms, 20 time steps), in the paper's set-up: full inflow from the first step,
// the fluid alone on the fixed mesh until Coupling/Start time = 0.01 s, then IQN-ILS.
// Asserted:
//   (a) the coupling start time: steps 1-5 are the fluid alone (0 coupling iterations in
//       fsi_history.txt, u(A) exactly 0, a drag), steps 6-20 are coupled (iterations, u(A) != 0);
//       the same run with Coupling/Start time = 0 (an impulsive start: the fluid at rest meets
//       the full inflow, a pressure of the order rho U L / dt ~ 5e5 Pa on a flag with E = 5.6e6 Pa)
//       stops at time step 1 with an error that names the step and points to Coupling/Start time;
//   (b) recorded values at t = 0.04 s of the run of (c) (deterministic to 1e-9): drag, lift,
//       u(A) with 6 (u_y(A): 5) significant digits, which numdiff's default -r 1e-8 then checks
//       to the printed digits (recorded anew with the self-converging PISO correctors, which take
//       5 correctors on the first step's start from rest and 2 after: the drag moved from 531.788
//       to 518.84 N/m, the value of a run with 12 correctors in every step, 518.85, where two in
//       every step leave 2.5%); the total coupling iterations of the tightly converged run of
//       (c) on rank 0 alone within 10% of the recorded 124 (the coupling's own convergence, free
//       of the linear solvers' noise: 124 both before and after the momentum GMRES moved from
//       AztecOO to deal.II's SolverGMRES); and those of the run with the shipped solver
//       settings on one rank within 10% of the recorded 93. The shipped count is where each
//       step's residual crosses the tolerance 1e-5 with the momentum solved to only 1e-3, and
//       IQN-ILS builds on those iterates: it moves with any change of the linear solvers at the
//       level of their tolerances. Measured, Fluid momentum solver/Residual reduction 5e-4, 1e-3,
//       2e-3, 1e-4, 1e-6: with AztecOO's GMRES (19539d6) 83, 83, 114, 95, 91; with deal.II's
//       (1e-3, 1e-6, 2e-6, 5e-7): 93, 106, 96, 106: the same scatter, so the recorded value was
//       moved from 83 to 93 with that change (doc/results/performance.md, section 8); the check
//       is a tripwire that makes such a change look at the count. With np = 2 the shipped run is
//       repeated on rank 0 alone for this count (np = 2 measured 97 at 19539d6: printed, not
//       asserted);
//   (d) a fluid probe P (Fluid scene/Probes, behind the flag's tip) in fsi_history.txt: its
//       velocity and pressure every step (the mesh it is found in moves with the flag), printed at
//       t = 0.04 s of the run of (c) with 6 significant digits;
//   (c) np ranks equal one rank: the run again with every linear solve converged to 1e-10, the
//       solid outer iterations to 1e-13 and the coupling to 1e-9 (at the shipped settings the
//       two stop at different points of the same convergence, 1e-7 apart), on all ranks and on
//       rank 0 alone (MPI_COMM_SELF): the force (drag, lift) and u(A) of every time step, as
//       vectors, within 1e-8 of the largest |force| and |u(A)|. What is left is the partition
//       dependence of the preconditioners, amplified by the coupling: measured with np = 2,
//       force 1e-10, u(A) 4e-10. (The coupling iterations of a step may differ by one or two:
//       at 1e-9 the residual reaches the tolerance at the level of that noise.)
// With np = 1 (c) compares two identical runs. Verdicts and 6-digit values only, so that
// NAME.output and NAME.mpirun=2.output are the same file.
#include "fsi_case.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

using namespace fvfsi_test;

// The shipped file holds two PISO correctors in every step (its run costs 18% less so,
// doc/results/hard_cases.md, section 4); this start from rest at full inflow keeps the defaults'
// self-converging correctors (Max pressure correctors = 6), which it needs.
const std::vector<std::string> coarse = {"Mesh/Generator arguments=12",
                                         "Fluid/Max pressure correctors=6",
                                         "Solid mesh/Generator arguments=20: 2",
                                         "Time/Time step=0.002",
                                         "Time/End time=0.04",
                                         "Coupling/Start time=0.01",
                                         "Fluid scene/Output interval=0",
                                         "Fluid scene/Progress interval=5",
                                         "Fluid scene/Probes=P: 0.7, 0.2"};

/// For (c): every solve converged far below 1e-8.
const std::vector<std::string> tight = converged_solves("1e-10", "1e-9");

/// The columns t, coupling_iterations, residual, drag, lift, ux_A, uy_A, Ux_P, Uy_P, p_P,
/// min_volume_ratio, dt of fsi_history.txt.
std::vector<std::vector<double>> read_history(const std::string& directory)
{
  return read_table(directory + "/fsi_history.txt");
}

/// Runs the case on `comm` into `directory`; returns the error message ("" if it ran through).
std::string run(const std::vector<std::string>& overrides, MPI_Comm comm,
                const std::string& directory)
{
  return run_fsi_case<2>("turek_hron_fsi3", coarse, overrides, comm, directory);
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const MPI_Comm comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;

  const std::string error = run_shipped_and_one_rank<2>("turek_hron_fsi3", coarse, tight, comm);
  const std::string impulsive =
    run({"Coupling/Start time=0", "Time/End time=0.004"}, comm, "out_impulsive");
  const bool parallel = dealii::Utilities::MPI::n_mpi_processes(comm) > 1;
  if (!root)
    return 0;
  std::printf("impulsive start: %s\n", impulsive.c_str());
  const auto h = read_history("out_shipped");
  out << "run through: " << yes_no(error.empty() && h.size() == 20) << "\n";

  // (a)
  bool alone = true, coupled = true;
  for (unsigned int i = 0; i < h.size(); ++i)
    if (i < 5)
      alone = alone && h[i][1] == 0 && h[i][5] == 0 && h[i][6] == 0 && h[i][3] != 0;
    else
      coupled = coupled && h[i][1] >= 1 && h[i][5] != 0 && h[i][6] != 0;
  out << "steps 1-5 fluid alone (0 coupling iterations, u(A) = 0, a drag): " << yes_no(alone)
      << "\nsteps 6-20 coupled (coupling iterations, u(A) != 0): " << yes_no(coupled) << "\n";
  out << "impulsive start: stops at time step 1 naming it and Coupling/Start time: "
      << yes_no(impulsive.find("time step 1 ") != std::string::npos &&
                impulsive.find("Coupling/Start time") != std::string::npos)
      << "\n";

  // (b) the values of the tight run (deterministic to 1e-9), the iterations of the shipped one on
  // one rank.
  const auto hn = read_history("out_np"), h1 = read_history("out_1");
  const auto total_iterations = [](const std::vector<std::vector<double>>& history)
  {
    unsigned int n = 0;
    for (const auto& row : history)
      n += static_cast<unsigned int>(row[1]);
    return n;
  };
  const unsigned int iterations = total_iterations(parallel ? read_history("out_shipped_1") : h);
  std::printf("shipped settings: %u coupling iterations on one rank, %u on all ranks\n", iterations,
              total_iterations(h));
  if (!hn.empty())
  {
    const auto& last = hn.back();
    out << format("t = %.3f s: drag %.6g N/m, lift %.6g N/m, u_x(A) %.6g m, u_y(A) %.5g m", last[0],
                  last[3], last[4], last[5], last[6])
        << "\n";
  }
  // (d)
  if (!hn.empty())
  {
    const auto& last = hn.back();
    out << format("fluid probe P every step; at t = %.3f s: U = (%.6g, %.6g) m/s, p = %.6g Pa",
                  last[0], last[7], last[8], last[9])
        << "\n";
  }
  const unsigned int tight_iterations = total_iterations(h1);
  std::printf("tight run, one rank: %u coupling iterations\n", tight_iterations);
  out << "tight run, one rank: total coupling iterations within 10% of 124 (recorded): "
      << yes_no(std::abs(double(tight_iterations) - 124) <= 12.4) << "\n";
  out << "shipped settings, one rank: total coupling iterations within 10% of 93 (recorded): "
      << yes_no(std::abs(double(iterations) - 93) <= 9.3) << "\n";

  // (c) the force (drag, lift) and u(A) as vectors, each against its largest magnitude.
  bool equal = hn.size() == 20 && h1.size() == 20;
  const double force = vector_difference(hn, h1, {3, 4}), u_A = vector_difference(hn, h1, {5, 6});
  std::printf("np - 1 rank, max relative differences: force %.2e, u(A) %.2e\n", force, u_A);
  unsigned int iteration_difference = 0;
  for (unsigned int i = 0; equal && i < hn.size(); ++i)
    iteration_difference =
      std::max<unsigned int>(iteration_difference, std::abs(int(hn[i][1]) - int(h1[i][1])));
  std::printf("coupling iterations per step differ by at most %u\n", iteration_difference);
  equal = equal && std::max(force, u_A) <= 1e-8;
  out << "np ranks equal one rank (force and u(A) every step to 1e-8): " << yes_no(equal) << "\n";
}
