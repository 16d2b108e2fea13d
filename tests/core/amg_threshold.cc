// The AMG aggregation threshold (`AMG aggregation threshold` of every linear solver subsection)
// reaches ML and does what it is for. The Poisson problem on 32 x 128 cells of the unit square
// (cells four times as wide as high): the face coefficients S_f / d_fn are 4 across the long
// faces and 1/4 across the short ones, so the weak connections have |a_ij| / sqrt(a_ii a_jj) =
// 0.25 / 8.5 = 0.029. The default threshold 0.02 keeps them, and ML aggregates as if the mesh were
// isotropic; 0.05 drops them and the aggregates follow the strong direction. Asserted: 0.05 needs
// at most two thirds of the CG iterations of 0.02 (summed over the deferred correction's three
// solves: 11 against 20 on one rank, 10 against 22 on two), and both give the same solution (max
// cell error equal to 1e-8 relative: each solve converges to 1e-10 and the deferred correction to
// 1e-10). Serial and on two ranks (ML aggregates within each rank). The iteration counts are
// printed and compared exactly, as in tests/app/poisson_2d: ML's aggregation is deterministic.
#include <fvfsi/scenes/poisson.h>

#include "../test_utilities.h"

#include <cmath>

using namespace fvfsi_test;

fvfsi::PoissonResults run(const double threshold)
{
  fvfsi::MeshParameters mesh;
  mesh.generator = "subdivided_hyper_rectangle";
  mesh.generator_arguments = "32, 128: 0, 0: 1, 1: true";
  mesh.n_global_refinements = 0;
  fvfsi::PoissonParameters parameters = manufactured_poisson<2>();
  parameters.solver.reduction = 1e-10;
  parameters.solver.amg_aggregation_threshold = threshold;
  fvfsi::PoissonProblem<2> problem(mesh, parameters, MPI_COMM_WORLD);
  problem.run();
  return problem.results();
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const fvfsi::PoissonResults isotropic = run(0.02), directed = run(0.05);
  out << "CG iterations, threshold 0.02: " << isotropic.linear_iterations << "\n";
  out << "CG iterations, threshold 0.05: " << directed.linear_iterations << "\n";
  out << "threshold 0.05 needs at most 2/3 of the iterations of 0.02: "
      << yes_no(3 * directed.linear_iterations <= 2 * isotropic.linear_iterations) << "\n";
  out << "the same max cell error to 1e-8 relative: "
      << yes_no(std::abs(directed.max_cell_error - isotropic.max_cell_error) <=
                1e-8 * isotropic.max_cell_error)
      << "\n";
}
