// Quadratic exactness of the quadratic reconstruction and of the quadratic face normal gradient
// (FaceGradient::quadratic) on randomly distorted meshes (distortion 0.25 of the refined mesh),
// 2D and 3D, serial and mpirun=2.
//
// For phi = a + b.x + 1/2 x.A.x (A symmetric) sampled exactly (cell values phi(r_P), boundary
// values phi(r_f) on every boundary and ghost_boundary face), asserts:
//  - QuadraticFit::compute (the Poisson face gradient's data) gives g_P = b + A r_P and H_P = A, on the owned cells and,
//    after its ghost update, on the ghost cells (the vertex-neighbour stencil of every owned cell
//    is complete on every rank);
//  - Laplacian::normal_gradient (quadratic) equals n.grad phi(r_f) on interior and processor faces
//    and, all patches Dirichlet, on boundary and ghost_boundary faces; and, for contrast, that the
//    linear Eq. 19 with the same exact g does not (its error is O(h) on these meshes);
//  - Laplacian::boundary_values (quadratic), all patches Neumann with n.grad phi(r_f), returns
//    phi(r_f) on boundary and ghost_boundary faces;
//  - the assembled operator: (A_h phi - b_h)_P, with A_h, b_h from Laplacian::assemble and the
//    quadratic add_correction, equals -sum_f S_f n_f.grad phi(r_f) on every owned cell (the
//    explicit correction enters with the right sign and on both sides of each face).
//
// Each is exact for quadratic fields up to round-off. Errors are relative to |b| (gradients) or
// |A| (Hessian) or max_P sum_f S_f |grad phi(r_f)| (the operator). A Hessian divides differences of
// O(1) values by h^2 (h = 1/8 .. 1/16, distorted), a gradient by h, so round-off is amplified by up
// to ~1e3. Measured (FVFSI_TEST_VERBOSE=1, serial and mpirun=2): <= 1.2e-13 (the Hessian; face
// normal gradients <= 1.3e-14); tolerance 1e-10 (margin > 800). A first-order inconsistency would
// give errors ~ h |A| ~ 0.1.

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/quadratic_fit.h>
#include <fvfsi/mesh/fv_geometry.h>

#include "fv_core_test_tools.h"

#include <cmath>
#include <limits>

using namespace dealii;
using namespace fvfsi_core_test;

constexpr double tolerance = 1e-10;

/// phi = a + b.x + 1/2 x.A.x.
template <int dim>
struct QuadraticField
{
  LinearField<dim> linear;
  SymmetricTensor<2, dim> A;
  QuadraticField()
  {
    const double a[3][3] = {{1.1, 0.3, -0.2}, {0.3, -0.8, 0.5}, {-0.2, 0.5, 0.6}};
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        A[i][j] = a[i][j];
  }
  double operator()(const Point<dim>& x) const { return linear(x) + 0.5 * (x * (A * x)); }
  Tensor<1, dim> gradient(const Point<dim>& x) const { return linear.b + A * x; }
};

/// max(error, e) that keeps a NaN as infinity.
inline void record(double& error, const double e)
{
  error = std::isfinite(e) ? std::max(error, e) : std::numeric_limits<double>::infinity();
}

template <int dim>
void check_reconstruction(std::ostream& out, const fvfsi::FVGeometry<dim>& fv,
                          const QuadraticField<dim>& field, const fvfsi::CellGradient<dim>& g,
                          const fvfsi::CellHessian<dim>& H)
{
  double g_owned = 0, g_ghost = 0, H_owned = 0, H_ghost = 0;
  for (unsigned int c = 0; c < fv.n_relevant_cells(); ++c)
  {
    const bool owned = c < fv.n_owned_cells();
    record(owned ? g_owned : g_ghost,
           (g[c] - field.gradient(fv.centroid[c])).norm() / field.linear.b.norm());
    record(owned ? H_owned : H_ghost, (H[c] - field.A).norm() / field.A.norm());
  }
  check(out, "quadratic fit: g = b + A r_P on owned cells", g_owned, tolerance);
  check(out, "quadratic fit: g = b + A r_P on ghost cells", g_ghost, tolerance);
  check(out, "quadratic fit: H = A on owned cells", H_owned, tolerance);
  check(out, "quadratic fit: H = A on ghost cells", H_ghost, tolerance);
}

/// (A_h phi - b_h)_P + sum_f S_f n_f.grad phi(r_f), relative, max over owned cells.
template <int dim>
double operator_error(const fvfsi::FVGeometry<dim>& fv, const QuadraticField<dim>& field,
                      const fvfsi::Laplacian<dim>& laplacian,
                      const fvfsi::ScalarBoundaryConditions<dim>& bc, const fvfsi::CellVector& phi,
                      const fvfsi::CellGradient<dim>& g, const fvfsi::CellHessian<dim>& H)
{
  const fvfsi::FaceVector gamma(fv.faces.size(), 1.0);
  TrilinosWrappers::SparseMatrix matrix;
  laplacian.reinit_matrix(matrix);
  fvfsi::CellVector rhs = fv.make_cell_vector();
  laplacian.assemble(gamma, bc, matrix, rhs);
  matrix.compress(VectorOperation::add);
  laplacian.add_correction(gamma, bc, g, rhs, &H);

  TrilinosWrappers::MPI::Vector x(matrix.locally_owned_domain_indices(), fv.comm()), Ax(x);
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
    x(fv.global_index(c)) = phi.local_element(c);
  x.compress(VectorOperation::insert);
  matrix.vmult(Ax, x);

  std::vector<double> exact(fv.n_owned_cells(), 0.0), scale(fv.n_owned_cells(), 0.0);
  for (const auto& face : fv.faces)
  {
    if (face.kind == fvfsi::FaceKind::ghost_boundary)
      continue;
    const double flux = face.S * field.gradient(face.centre); // out of P
    exact[face.P] -= flux;
    scale[face.P] += std::abs(flux);
    if (face.kind == fvfsi::FaceKind::interior)
    {
      exact[face.N] += flux;
      scale[face.N] += std::abs(flux);
    }
  }
  double error = 0, max_scale = 0;
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
  {
    record(error, std::abs(Ax(fv.global_index(c)) - rhs.local_element(c) - exact[c]));
    max_scale = std::max(max_scale, scale[c]);
  }
  return error / Utilities::MPI::max(max_scale, fv.comm());
}

template <int dim>
void test(std::ostream& out, const std::string& generator, const std::string& arguments,
          const unsigned int refinements)
{
  const TestMesh<dim> mesh(out, generator, arguments, refinements);
  const fvfsi::FVGeometry<dim>& fv = *mesh.fv;
  fvfsi::QuadraticFitData data; // the Poisson scene's: all boundary faces, weights (L/|s|)^6
  data.value_faces.assign(fv.faces.size(), false);
  for (unsigned int f = 0; f < fv.faces.size(); ++f)
    data.value_faces[f] = fv.faces[f].N == fvfsi::invalid_cell;
  const fvfsi::QuadraticFit<dim> reconstruction(fv, data);
  const fvfsi::Laplacian<dim> laplacian(fv);
  const auto& faces = fv.faces;
  const QuadraticField<dim> field;

  fvfsi::CellVector phi;
  fvfsi::FaceVector boundary;
  exact_values(fv, field, phi, boundary);

  fvfsi::CellGradient<dim> g(fv);
  fvfsi::CellHessian<dim> H(fv);
  reconstruction.compute(phi, boundary, fvfsi::FaceVector(), g, H);
  check_reconstruction(out, fv, field, g, H);

  // Face normal gradients, all patches Dirichlet with the exact value at r_f.
  fvfsi::ScalarBoundaryConditions<dim> dirichlet, neumann;
  dirichlet.value = boundary;
  neumann.value.assign(faces.size(), 0.0);
  for (unsigned int f = 0; f < faces.size(); ++f)
    if (faces[f].N == fvfsi::invalid_cell)
    {
      dirichlet.patch_type[faces[f].patch] = fvfsi::BoundaryType::dirichlet;
      neumann.patch_type[faces[f].patch] = fvfsi::BoundaryType::neumann;
      neumann.value[f] = faces[f].n * field.gradient(faces[f].centre);
    }
  double interior_error = 0, boundary_error = 0, linear_error = 0;
  const double scale = field.linear.b.norm();
  for (unsigned int f = 0; f < faces.size(); ++f)
  {
    const double exact = faces[f].n * field.gradient(faces[f].centre);
    const double e = std::abs(laplacian.normal_gradient(f, phi, g, dirichlet, &H) - exact) / scale;
    record(faces[f].N == fvfsi::invalid_cell ? boundary_error : interior_error, e);
    if (faces[f].N != fvfsi::invalid_cell)
      record(linear_error,
             std::abs(laplacian.normal_gradient(f, phi, g, dirichlet) - exact) / scale);
  }
  check(out, "quadratic normal gradient = n.grad phi(r_f) on interior and processor faces",
        interior_error, tolerance);
  check(out,
        "quadratic normal gradient = n.grad phi(r_f) on Dirichlet boundary and ghost_boundary "
        "faces",
        boundary_error, tolerance);
  check(out, "contrast: linear normal gradient (Eq. 19) with the same g errs by more than 1e-3",
        Utilities::MPI::max(linear_error, MPI_COMM_WORLD) > 1e-3);

  // Neumann boundary values.
  const fvfsi::FaceVector values = laplacian.boundary_values(phi, g, neumann, &H);
  double value_error = 0;
  for (unsigned int f = 0; f < faces.size(); ++f)
    if (faces[f].N == fvfsi::invalid_cell)
      record(value_error, std::abs(values[f] - boundary[f]) / scale);
  check(out, "quadratic Neumann boundary values = phi(r_f) on boundary and ghost_boundary faces",
        value_error, tolerance);

  check(out,
        "assembled operator with quadratic correction = -sum_f S_f n.grad phi(r_f) (Dirichlet)",
        operator_error(fv, field, laplacian, dirichlet, phi, g, H), tolerance);
}

int main(int argc, char** argv)
{
  return exactness_main<test<2>, test<3>>(argc, argv);
}
