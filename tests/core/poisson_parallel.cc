// np = 2 equals np = 1: the Poisson solution on a randomly distorted mesh (distortion 0.25 of the
// refined mesh, hashed from vertex coordinates so that it does not depend on the partition),
// computed on all ranks, is gathered by cell centroid and compared with a run on rank 0 alone
// (MPI_COMM_SELF). Both runs converge the deferred correction to 1e-13 and each linear solve by
// 1e-10, so what remains is the partition-dependent AMG round-off: asserted below 1e-10 relative
// (max over cells of |phi_np2 - phi_np1| / max |phi|). Run with mpirun=2 (and serially, where it
// compares a run with itself). 2D and 3D, with the linear (Eq. 19) and the quadratic face normal
// gradient (Poisson/Face gradient): the quadratic one reads the Hessian of the ghost neighbours and
// fits over vertex-neighbour stencils that reach into the ghost layer, so it checks that the ghost
// layer and the ghost updates of g and H are complete.
#include <fvfsi/scenes/poisson.h>

#include "../test_utilities.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>

using namespace fvfsi_test;

template <int dim>
std::vector<std::pair<std::array<double, dim>, double>>
centroid_values(const fvfsi::PoissonProblem<dim>& p)
{
  std::vector<std::pair<std::array<double, dim>, double>> values;
  const auto& fv = p.geometry();
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
  {
    std::array<double, dim> x;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] = fv.centroid[c][d];
    values.emplace_back(x, p.solution().local_element(c));
  }
  return values;
}

template <int dim>
void compare(std::ofstream& out, const std::string& face_gradient)
{
  fvfsi::MeshParameters mesh;
  mesh.generator = "hyper_cube";
  mesh.generator_arguments = "0: 1: true";
  mesh.n_global_refinements = dim == 2 ? 5 : 3;
  mesh.distortion = 0.25;
  fvfsi::PoissonParameters parameters = manufactured_poisson<dim>();
  parameters.correction_tolerance = 1e-13;
  parameters.solver.reduction = 1e-10;
  parameters.face_gradient = face_gradient == "quadratic"
                               ? fvfsi::PoissonParameters::FaceGradient::quadratic
                               : fvfsi::PoissonParameters::FaceGradient::linear;

  fvfsi::PoissonProblem<dim> parallel(mesh, parameters, MPI_COMM_WORLD);
  parallel.run();
  const auto gathered = dealii::Utilities::MPI::gather(MPI_COMM_WORLD, centroid_values(parallel));
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return;

  fvfsi::PoissonProblem<dim> serial(mesh, parameters, MPI_COMM_SELF);
  serial.run();
  std::map<std::array<double, dim>, double> reference;
  double max_phi = 0;
  for (const auto& [x, v] : centroid_values(serial))
  {
    reference[x] = v;
    max_phi = std::max(max_phi, std::abs(v));
  }
  double max_difference = 0;
  unsigned int n_matched = 0;
  for (const auto& rank_values : gathered)
    for (const auto& [x, v] : rank_values)
    {
      const auto it = reference.find(x); // the geometry is bitwise identical on any partition
      if (it == reference.end())
        continue;
      ++n_matched;
      max_difference = std::max(max_difference, std::abs(v - it->second));
    }
  const std::string name = std::to_string(dim) + "D, " + face_gradient + " face gradient: ";
  out << name << reference.size()
      << " cells, all matched by centroid: " << yes_no(n_matched == reference.size()) << "\n";
  out << name << "max |phi(np) - phi(np=1)| / max |phi| < 1e-10: "
      << yes_no(max_difference / max_phi < 1e-10) << "\n";
  if (std::getenv("FVFSI_TEST_VERBOSE") != nullptr)
    std::cerr << "  [" << name
              << "max |phi(np) - phi(np=1)| / max |phi| = " << max_difference / max_phi
              << std::endl;
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  for (const std::string face_gradient : {"linear", "quadratic"})
  {
    compare<2>(out, face_gradient);
    compare<3>(out, face_gradient);
  }
}
