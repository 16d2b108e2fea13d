// np = 2 equals np = 1 for the solid solver: the displacement field, gathered by cell centroid,
// of (a) the linear-elastic plate with a hole (968 cells, steady, symmetry + traction boundaries)
// and (b) five BDF2 steps of the St. Venant-Kirchhoff Turek-Hron flag under gravity (280 cells,
// clamped + traction boundaries), also with Solid/Hessian correction (which plate_hole.prm sets
// too), agrees with a run on rank 0 alone to 1e-8 relative
// (max |u_np - u_1| / max |u_1|). Outer iterations converge to 1e-12 in both runs, so what is
// left is round-off and partition-dependent AMG/Anderson differences. (c) The flag of (b) with
// Solid linear solver/Preconditioner = direct (the whole matrix A_j factorised on every rank):
// the same agreement, and every linear solve takes at most one Krylov iteration on any number of
// ranks (the preconditioner is the exact inverse of A_j, which changes only with the time step
// size), at least one in all.
#include <fvfsi/scenes/solid_scene.h>

#include "../test_utilities.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <tuple>

using namespace fvfsi_test;

using Values = std::vector<std::pair<std::array<double, 2>, std::array<double, 2>>>;

/// Linear solves and their Krylov iterations of the last run() (the solid's A_j systems).
unsigned long n_solves = 0, n_iterations = 0;

Values run(const fvfsi::AllParameters& p, MPI_Comm comm)
{
  std::filesystem::create_directories("out");
  fvfsi::SolidScene<2> scene(p.mesh, p.solid, p.solid_scene, p.time, comm, ".", "out");
  scene.run();
  std::tie(n_solves, n_iterations) = scene.solver().linear_solves_and_iterations();
  Values values;
  const auto& fv = scene.geometry();
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
    values.push_back({{fv.centroid[c][0], fv.centroid[c][1]},
                      {scene.solver().displacement()[c][0], scene.solver().displacement()[c][1]}});
  return values;
}

/// Returns the linear solves and iterations of the run on all ranks (on rank 0).
std::pair<unsigned long, unsigned long> compare(std::ofstream& out, const std::string& title,
                                                const fvfsi::AllParameters& p)
{
  const auto gathered = dealii::Utilities::MPI::gather(MPI_COMM_WORLD, run(p, MPI_COMM_WORLD));
  const std::pair<unsigned long, unsigned long> counts{n_solves, n_iterations};
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return counts;
  std::map<std::array<double, 2>, std::array<double, 2>> reference;
  double max_u = 0;
  for (const auto& [x, u] : run(p, MPI_COMM_SELF))
  {
    reference[x] = u;
    max_u = std::max({max_u, std::abs(u[0]), std::abs(u[1])});
  }
  double max_difference = 0;
  unsigned int matched = 0;
  for (const auto& part : gathered)
    for (const auto& [x, u] : part)
      if (const auto it = reference.find(x); it != reference.end())
      {
        ++matched;
        max_difference = std::max(
          {max_difference, std::abs(u[0] - it->second[0]), std::abs(u[1] - it->second[1])});
      }
  out << title << ": " << reference.size()
      << " cells, all matched: " << yes_no(matched == reference.size())
      << ", max |u_np - u_1| / max |u_1| < 1e-8: " << yes_no(max_difference / max_u < 1e-8) << "\n";
  return counts;
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  compare(out, "plate with a hole", *shipped_case("plate_hole", {"Solid/Outer tolerance=1e-12"}));
  compare(out, "Turek-Hron flag, 5 BDF2 steps",
          *shipped_case("turek_hron_csm1", {"Mesh/Generator arguments=70: 4",
                                            "Solid/Transient=true", "Time/Time step=0.01",
                                            "Time/End time=0.05", "Solid/Outer tolerance=1e-12"}));
  compare(out, "Turek-Hron flag, 5 BDF2 steps, Hessian correction",
          *shipped_case("turek_hron_csm1",
                        {"Mesh/Generator arguments=70: 4", "Solid/Transient=true",
                         "Time/Time step=0.01", "Time/End time=0.05", "Solid/Outer tolerance=1e-12",
                         "Solid/Hessian correction=true"}));
  const auto [solves, iterations] =
    compare(out, "Turek-Hron flag, 5 BDF2 steps, direct preconditioner",
            *shipped_case("turek_hron_csm1", {"Mesh/Generator arguments=70: 4",
                                              "Solid/Transient=true", "Time/Time step=0.01",
                                              "Time/End time=0.05", "Solid/Outer tolerance=1e-12",
                                              "Solid linear solver/Preconditioner=direct"}));
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return 0;
  const bool one_rank_solves = n_iterations <= n_solves && n_iterations > 0; // rank 0 alone
  out << "direct preconditioner: at most one iteration per linear solve, on all ranks and on one: "
      << yes_no(iterations <= solves && iterations > 0 && one_rank_solves) << "\n";
  if (std::getenv("FVFSI_TEST_VERBOSE") != nullptr)
    std::cerr << "  [direct: " << solves << " solves, " << iterations << " iterations; one rank "
              << n_solves << ", " << n_iterations << "]" << std::endl;
}
