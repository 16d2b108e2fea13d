// CellMatrixProduct (the Krylov solvers' y = A x on the cell vectors, Epetra's rows read in
// place) gives Trilinos' own product to the last bit: every row sums its entries in Epetra's
// order. Checked on a non-symmetric FV matrix (face coefficients made unequal in the two rows of
// a face, as convection makes them) on distorted 2D and 3D meshes, serially and on two ranks,
// where the rows next to the other rank's cells read the exchanged ghost values: for an x
// without ghost values (as the solvers' vectors are; they must stay without, or every later
// vector operation exchanges them again) and for one whose ghosts are set (they must stay set).
// The assertion is exact equality (tolerance 0): any difference means another summation.
// FVFSI_TEST_VERBOSE=1 also times both products on a 2D mesh of 65 536 cells (stderr).
#include <deal.II/base/timer.h>

#include <fvfsi/fv/cell_matrix_product.h>
#include <fvfsi/fv/face_matrix.h>
#include <fvfsi/fv/laplacian.h>

#include "fv_core_test_tools.h"

#include <cmath>

using namespace fvfsi_core_test;

// A non-symmetric matrix with the FV sparsity, its coefficients functions of the geometry, and
// the field x_P = cos(3 x) + y^2 (owned entries only).
template <int dim>
void make_system(const fvfsi::FVGeometry<dim>& fv, TrilinosWrappers::SparseMatrix& A,
                 fvfsi::CellVector& x)
{
  fvfsi::Laplacian<dim>(fv).reinit_matrix(A);
  fvfsi::FaceMatrix<dim> coefficients(fv);
  for (unsigned int f = 0; f < fv.faces.size(); ++f)
    if (fv.faces[f].N != fvfsi::invalid_cell)
    {
      const auto& r = fv.faces[f].centre;
      coefficients.add_face_diffusion(f, 1.0 + 0.5 * std::sin(7 * r[0] + 3 * r[1]));
      coefficients.upper[f] -= 0.25 * std::cos(5 * r[1]); // convection-like: upper != lower
    }
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
    coefficients.diagonal[c] += 1.0 + fv.cell_volume[c];
  coefficients.copy_to(A);
  x = fv.make_cell_vector();
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
    x.local_element(c) = std::cos(3 * fv.centroid[c][0]) + fv.centroid[c][1] * fv.centroid[c][1];
}

double max_difference(const fvfsi::CellVector& a, const fvfsi::CellVector& b)
{
  double d = 0;
  for (unsigned int i = 0; i < a.locally_owned_size(); ++i)
    d = std::max(d, std::abs(a.local_element(i) - b.local_element(i)));
  return d;
}

template <int dim>
void test(std::ostream& out, const std::string& generator, const std::string& arguments,
          const unsigned int refinements)
{
  TestMesh<dim> mesh(out, generator, arguments, refinements);
  TrilinosWrappers::SparseMatrix A;
  fvfsi::CellVector x;
  make_system(*mesh.fv, A, x);
  fvfsi::CellMatrixProduct product;
  product.reinit(A, x);
  check(out, "the product is CellMatrixProduct's own", product.own_product());

  auto y_trilinos = mesh.fv->make_cell_vector(), y = y_trilinos;
  A.vmult(y_trilinos, x);
  x.zero_out_ghost_values();
  product.vmult(y, x);
  check(out, "x without ghost values: equal to Trilinos' product to the bit",
        max_difference(y, y_trilinos), 0.0);
  check(out, "x still without ghost values", !x.has_ghost_elements());

  x.update_ghost_values();
  product.vmult(y, x);
  check(out, "x with ghost values: equal to Trilinos' product to the bit",
        max_difference(y, y_trilinos), 0.0);
  check(out, "x's ghost values still set", x.has_ghost_elements());
}

// FVFSI_TEST_VERBOSE: seconds per product, Trilinos' and this one, on a larger 2D mesh.
void time_products()
{
  parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
  make_test_mesh(tria, "hyper_cube", "0 : 1 : true", 8, 0.25);
  const fvfsi::FVGeometry<2> fv(tria);
  TrilinosWrappers::SparseMatrix A;
  fvfsi::CellVector x, y = fv.make_cell_vector();
  make_system(fv, A, x);
  fvfsi::CellMatrixProduct product;
  product.reinit(A, x);
  const unsigned int n = 2000;
  for (unsigned int round = 0; round < 3; ++round)
  {
    Timer timer;
    for (unsigned int i = 0; i < n; ++i)
      A.vmult(y, x);
    const double trilinos = timer.wall_time() / n;
    timer.restart();
    for (unsigned int i = 0; i < n; ++i)
      product.vmult(y, x);
    const double own = timer.wall_time() / n;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cerr << "  " << fv.n_global_cells() << " cells: Trilinos "
                << format("%.1f", 1e6 * trilinos) << " us, CellMatrixProduct "
                << format("%.1f", 1e6 * own) << " us per product" << std::endl;
  }
}

int main(int argc, char** argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  test<2>(out, "hyper_cube", "-0.5 : 1.5 : true", 4);
  test<2>(out, "hyper_L", "-1 : 1 : false", 3);
  test<3>(out, "hyper_cube", "-0.5 : 1.5 : true", 3);
  test<3>(out, "hyper_L", "-1 : 1 : false", 2);
  if (verbose())
    time_products();
}
