// Linear exactness of fvfsi's gradient operators on randomly distorted meshes (distortion 0.25 of
// the refined mesh), 2D and 3D, serial and mpirun=2.
//
// For phi = a + b.x sampled exactly (cell values phi(r_P), boundary values phi(r_f) on every
// boundary and ghost_boundary face), asserts:
//  - GaussGreenGradient (Eq. 37) equals b, from the vertex values that VertexInterpolation
//    computes (exact for a linear field) and from the exact vertex values;
//  - LeastSquaresGradient::compute equals b;
//  - both on the owned cells and, after the update_ghost_values() these functions do, on the ghost
//    cells;
//  - tangential_gradient (Eq. 39) equals (I - n n) b on every face: on interior, processor and
//    boundary faces from the interpolated vertex values (all their vertices are vertices of owned
//    cells), on every face including ghost_boundary faces from the exact vertex values;
//  - Laplacian::normal_gradient (Eq. 19) equals n.b on interior and processor faces and, with all
//    patches Dirichlet and phi_b = phi(r_f) (Eq. 23), on boundary and ghost_boundary faces; with
//    the Gauss-Green and with the least-squares cell gradients.
//
// Each of these is exact for linear fields up to round-off. Errors are measured relative to |b|.
// Gradients divide differences of O(1) values by lengths ~ h/2 (h = 1/8 .. 1/16, distorted), so
// round-off in the values is amplified by |phi|/(h |b|) ~ 50. Measured (FVFSI_TEST_VERBOSE=1):
//  - from exact data (cell values, exact vertex values): <= 3e-14; tolerance 1e-11 (margin > 300);
//  - from interpolated vertex values (Gauss-Green and tangential gradients): <= 7e-13, because
//    the interpolated values carry round-off of up to 1e-13 at the domain corners, where the
//    vertex value is extrapolated from one cell and dim boundary faces; tolerance 1e-10 (> 100).
// Any first-order inconsistency would give errors ~ h |b| ~ 0.1, nine orders above.

#include <deal.II/base/utilities.h>

#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/gradients.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/mesh/fv_geometry.h>

#include "fv_core_test_tools.h"

#include <cmath>
#include <limits>

using namespace dealii;
using namespace fvfsi_core_test;

constexpr double tolerance = 1e-11;              // from exact data
constexpr double tolerance_interpolated = 1e-10; // from VertexInterpolation's vertex values

/// max over owned cells and max over ghost cells of |g_c - b| / |b|.
template <int dim>
std::pair<double, double> gradient_errors(const fvfsi::FVGeometry<dim>& fv,
                                          const fvfsi::CellGradient<dim>& g,
                                          const Tensor<1, dim>& b)
{
  double owned = 0, ghost = 0;
  for (unsigned int c = 0; c < fv.n_relevant_cells(); ++c)
  {
    double& error = c < fv.n_owned_cells() ? owned : ghost;
    const double e = (g[c] - b).norm() / b.norm();
    error = std::isfinite(e) ? std::max(error, e) : std::numeric_limits<double>::infinity();
  }
  return {owned, ghost};
}

template <int dim>
void check_gradient(std::ostream& out, const std::string& name, const fvfsi::FVGeometry<dim>& fv,
                    const fvfsi::CellGradient<dim>& g, const Tensor<1, dim>& b, const double tol)
{
  const auto [owned, ghost] = gradient_errors(fv, g, b);
  check(out, name + " = b on owned cells", owned, tol);
  check(out, name + " = b on ghost cells", ghost, tol);
}

template <int dim>
void test(std::ostream& out, const std::string& generator, const std::string& arguments,
          const unsigned int refinements)
{
  const TestMesh<dim> mesh(out, generator, arguments, refinements);
  const fvfsi::FVGeometry<dim>& fv = *mesh.fv;
  const fvfsi::VertexInterpolation<dim> interpolation(fv);
  const fvfsi::LeastSquaresGradient<dim> least_squares(fv);
  const fvfsi::Laplacian<dim> laplacian(fv);
  const auto& faces = fv.faces;

  const LinearField<dim> field;
  const Tensor<1, dim> b = field.b;
  fvfsi::CellVector phi;
  fvfsi::FaceVector boundary;
  exact_values(fv, field, phi, boundary);

  std::vector<double> vertex_values(fv.vertices().size(), std::numeric_limits<double>::quiet_NaN());
  interpolation.interpolate(phi, boundary, vertex_values);
  std::vector<double> exact_vertex_values(fv.vertices().size());
  for (unsigned int v = 0; v < fv.vertices().size(); ++v)
    exact_vertex_values[v] = field(fv.vertices()[v]);

  // Cell gradients.
  fvfsi::CellGradient<dim> gauss_green(fv), gauss_green_exact_vertices(fv), lsq(fv);
  const fvfsi::GaussGreenGradient<dim> gauss_green_operator(fv);
  gauss_green_operator.compute(vertex_values, gauss_green);
  gauss_green_operator.compute(exact_vertex_values, gauss_green_exact_vertices);
  least_squares.compute(phi, boundary, lsq);
  check_gradient(out, "Gauss-Green gradient (interpolated vertex values)", fv, gauss_green, b,
                 tolerance_interpolated);
  check_gradient(out, "Gauss-Green gradient (exact vertex values)", fv, gauss_green_exact_vertices,
                 b, tolerance);
  check_gradient(out, "least-squares gradient", fv, lsq, b, tolerance);

  // Face tangential gradients.
  double tangential_error = 0, tangential_error_exact = 0;
  for (const auto& face : faces)
  {
    const Tensor<1, dim> exact = b - (face.n * b) * face.n;
    const double e_exact =
      (fvfsi::tangential_gradient(face, exact_vertex_values) - exact).norm() / b.norm();
    tangential_error_exact = std::isfinite(e_exact) ? std::max(tangential_error_exact, e_exact)
                                                    : std::numeric_limits<double>::infinity();
    if (face.kind == fvfsi::FaceKind::ghost_boundary)
      continue;
    const double e = (fvfsi::tangential_gradient(face, vertex_values) - exact).norm() / b.norm();
    tangential_error =
      std::isfinite(e) ? std::max(tangential_error, e) : std::numeric_limits<double>::infinity();
  }
  check(out,
        "tangential gradient = (I - n n) b on interior, processor, boundary faces "
        "(interpolated vertex values)",
        tangential_error, tolerance_interpolated);
  check(out, "tangential gradient = (I - n n) b on all faces (exact vertex values)",
        tangential_error_exact, tolerance);

  // Face normal gradients, all patches Dirichlet with the exact value at r_f.
  fvfsi::ScalarBoundaryConditions<dim> bc;
  bc.value = boundary;
  for (const auto& face : faces)
    if (face.N == fvfsi::invalid_cell)
      bc.patch_type[face.patch] = fvfsi::BoundaryType::dirichlet;
  for (const auto& [name, gradient] : {std::make_pair(std::string("Gauss-Green"), &gauss_green),
                                       std::make_pair(std::string("least-squares"), &lsq)})
  {
    double interior_error = 0, boundary_error = 0;
    unsigned int n_processor = 0;
    for (unsigned int f = 0; f < faces.size(); ++f)
    {
      const double e =
        std::abs(laplacian.normal_gradient(f, phi, *gradient, bc) - faces[f].n * b) / b.norm();
      double& error = faces[f].N == fvfsi::invalid_cell ? boundary_error : interior_error;
      error = std::isfinite(e) ? std::max(error, e) : std::numeric_limits<double>::infinity();
      n_processor += faces[f].kind == fvfsi::FaceKind::processor ? 1 : 0;
    }
    check(out,
          "normal gradient = n.b on interior and processor faces (" + name + " cell gradients)",
          interior_error, tolerance);
    check(out,
          "normal gradient = n.b on Dirichlet boundary and ghost_boundary faces (" + name +
            " cell gradients)",
          boundary_error, tolerance);
    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1 && name == "Gauss-Green")
      check(out, "parallel: there are processor faces on every rank", n_processor > 0);
  }
}

int main(int argc, char** argv)
{
  return exactness_main<test<2>, test<3>>(argc, argv);
}
