// A short elastic tube (prm/elastic_tube.prm as shipped, paper section 4.4) in 3D: 3 840 fluid
// cells, 16 x 4 x 48 = 3 072 wall cells, dt = 0.1 ms, 5 time steps (the inlet overpressure on
// throughout), IQN-ILS. A second wall probe B sits at 5 mm from the inlet, where the pulse
// arrives first. The shipped case hands the fluid the wall's interface-face displacements
// averaged to the vertices (`Coupling/Face average displacement`, see (d)).
// Asserted:
//   (a) the run goes through with the shipped solver settings, and its physics: the pressure on
//       the axis falls along the tube (p at 5 mm > p at 10 mm > 0: the pulse enters), the wall at
//       B moves outwards (u_y(B) > 0, B on the +y side: radial), more than at the midsection A;
//   (b) recorded values at t = 1 ms of the run of (c): p at 5 and 10 mm, u_y(B) with 6
//       significant digits (numdiff's default -r 1e-8 checks the printed digits; deterministic to
//       1e-9; recorded anew with the self-converging PISO correctors, 3 on the first two steps
//       and 2 after: p(10 mm) 233.943 -> 239.303 Pa. On this coarse tube at dt = 0.1 ms PISO's
//       correctors do not settle with their count: 2, 12 and 30 in every step give p(10 mm) =
//       234, 278 and 243 Pa, so these digits record the algorithm, not a converged value), and the coupling iterations of the shipped run within 10% of the recorded count;
//   (c) np ranks equal one rank over 10 steps (1 ms) of the tube one refinement less (480 fluid
//       + 384 wall cells, the mesh of (d)), as tests/coupling/fsi3_coarse (c): every linear solve
//       to 1e-12, the solid to 1e-13, the coupling to 1e-11, the fluid and the wall decomposed
//       independently; the axis pressures and u(A), u(B) of every step, as vectors, within 1e-8
//       of their largest magnitude.
//   (d) the displacement transfer at small time steps, one rank: one refinement less (8 faces
//       round the tube, 2 wall cells through its thickness) at dt = 0.1 ms for 12 steps. With the
//       solid's vertex values (App. B) the coupled solution oscillates from step to step with a
//       growing amplitude: the odd-even part of p(5 mm) over the last 4 steps, max |p^(n+1) -
//       2 p^n + p^(n-1)| / max |p|, is above 0.5 (measured 2.2); with `Coupling/Face average
//       displacement` (interface vertices from the interface faces' displacements, the
//       displacement the traction works on) it stays below 0.05 (measured 0.01: the smooth
//       rise of the pulse).
// With np = 1 (c) compares two identical runs. Verdicts and 6-digit values only, so that
// NAME.output and NAME.mpirun=2.output are the same file.
#include "fsi_case.h"

#include <cmath>
#include <cstdio>
#include <limits>

using namespace fvfsi_test;

const unsigned int n_steps = 5, n_steps_parallel = 10;
const std::vector<std::string> coarse = {
  "Time/End time=0.0005", "Fluid scene/Output interval=0", "Fluid scene/Progress interval=5",
  "Solid scene/Probes=A: 0.025, 0.005, 0 | B: 0.005, 0.005, 0"};

/// For (c), on the tube of (d) for 10 steps: every solve converged far below 1e-8. The coupling to 1e-11: the added mass is
/// extreme here (a wall displacement pushes fluid out of both ends of a tube ten radii long), and
/// the axis pressures answer an interface residual of 1e-9 with relative differences of 2e-8.
const std::vector<std::string> tight = []
{
  auto overrides = converged_solves("1e-12", "1e-11");
  overrides.insert(overrides.end(), {"Time/End time=0.001", "Mesh/Global refinements=1",
                                     "Solid mesh/Global refinements=1"});
  return overrides;
}();

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const MPI_Comm comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  const bool parallel = dealii::Utilities::MPI::n_mpi_processes(comm) > 1;
  const std::string error = run_shipped_and_one_rank<3>("elastic_tube", coarse, tight, comm);
  if (!root)
    return 0;
  if (!error.empty())
    std::printf("shipped run: %s\n", error.c_str());

  // Columns of fsi_history.txt: t, coupling_iterations, relative_residual, drag, lift, u(A) (3),
  // u(B) (3), then U (3) and p of each of the nine axis probes p05 ... p45, min_volume_ratio, dt.
  const unsigned int uA = 5, uB = 8, axis = 11;
  const auto p_at = [](const unsigned int probe) { return axis + 4 * probe + 3; };
  const auto h = read_table("out_shipped/fsi_history.txt");
  out << "run through (" << n_steps << " steps): " << yes_no(error.empty() && h.size() == n_steps)
      << "\n";
  if (h.size() == n_steps)
  {
    const auto& last = h.back();
    out << "the pulse enters: p(5 mm) > p(10 mm) > 0 on the axis: "
        << yes_no(last[p_at(0)] > last[p_at(1)] && last[p_at(1)] > 0) << "\n"
        << "the wall at B (5 mm) moves outwards, more than at the midsection A: "
        << yes_no(last[uB + 1] > 0 && last[uB + 1] > std::abs(last[uA + 1])) << "\n";
  }

  const auto hn = read_table("out_np/fsi_history.txt"), h1 = read_table("out_1/fsi_history.txt");
  if (!hn.empty())
  {
    const auto& last = hn.back();
    out << format("t = %.4f s: p(5 mm) %.6g Pa, p(10 mm) %.6g Pa, u_y(B) %.6g m", last[0],
                  last[p_at(0)], last[p_at(1)], last[uB + 1])
        << "\n";
  }
  unsigned int iterations = 0;
  for (const auto& row : parallel ? read_table("out_shipped_1/fsi_history.txt") : h)
    iterations += static_cast<unsigned int>(row[1]);
  const unsigned int recorded = 66; // measured with the face average (61 with the vertex values)
  std::printf("shipped settings: %u coupling iterations on one rank\n", iterations);
  out << "shipped settings, one rank: total coupling iterations within 10% of " << recorded
      << " (recorded): " << yes_no(std::abs(double(iterations) - recorded) <= 0.1 * recorded)
      << "\n";

  // (d): the odd-even part of p(5 mm) with either transfer.
  const auto odd_even = [&](const bool face_average)
  {
    const std::string directory = face_average ? "out_face_average" : "out_vertex_values";
    run_fsi_case<3>(
      "elastic_tube", coarse,
      {"Time/End time=0.0012", "Mesh/Global refinements=1", "Solid mesh/Global refinements=1",
       std::string("Coupling/Face average displacement=") + (face_average ? "true" : "false")},
      MPI_COMM_SELF, directory);
    const auto p = read_table(directory + "/fsi_history.txt");
    if (p.size() < 12)
      return std::numeric_limits<double>::quiet_NaN(); // the run stopped: fails both checks
    double largest = 0, jump = 0;
    for (unsigned int n = 0; n < p.size(); ++n)
      largest = std::max(largest, std::abs(p[n][p_at(0)]));
    for (unsigned int n = p.size() - 4; n + 1 < p.size(); ++n)
      jump = std::max(jump, std::abs(p[n + 1][p_at(0)] - 2 * p[n][p_at(0)] + p[n - 1][p_at(0)]));
    return jump / largest;
  };
  const double vertex_values = odd_even(false), face_average = odd_even(true);
  std::printf("odd-even part of p(5 mm), 8 faces round, dt = 0.1 ms: vertex values %.3f, face "
              "average %.3f\n",
              vertex_values, face_average);
  out << "8 faces round, dt = 0.1 ms: the vertex values' transfer oscillates (odd-even part > "
         "0.5): "
      << yes_no(vertex_values > 0.5) << "\n"
      << "8 faces round, dt = 0.1 ms: the face average's transfer is smooth (odd-even part < "
         "0.05): "
      << yes_no(face_average < 0.05) << "\n";

  std::vector<unsigned int> pressures;
  for (unsigned int i = 0; i < 9; ++i)
    pressures.push_back(p_at(i));
  const double p_difference = vector_difference(hn, h1, pressures),
               u_difference = vector_difference(hn, h1, {uA, uA + 1, uA + 2, uB, uB + 1, uB + 2});
  std::printf("np - 1 rank, max relative differences: axis pressures %.2e, u(A), u(B) %.2e\n",
              p_difference, u_difference);
  out << "np ranks equal one rank (axis pressures and u(A), u(B) every step to 1e-8): "
      << yes_no(hn.size() == n_steps_parallel && std::max(p_difference, u_difference) <= 1e-8)
      << "\n";
}
