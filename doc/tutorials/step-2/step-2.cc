/* ---------------------------------------------------------------------
 * fvfsi tutorial step-2: a linear-elastic solid by the segregated finite-volume method.
 *
 * The plate with a circular hole under remote tension (paper section 4.1): the quarter plate
 * [0,2]^2 minus the disc of radius a = 0.5, symmetry planes x = 0 and y = 0, the exact (Kirsch)
 * traction on x = 2 and y = 2, a traction-free hole; plane stress, E = 1e7 Pa, nu = 0.3,
 * T = 10 kPa. We build the solid solver of Tukovic et al. (sections 2.2, 3.2, 3.3, Appendices
 * A-B; equation numbers refer to the paper) from step-1's pieces, now for a vector unknown with
 * coupled components and non-Dirichlet boundaries. fvfsi::SolidSolver is the full version
 * (transient, St. Venant-Kirchhoff, accelerated); here it is written out for the linear,
 * static case.
 *
 * The model. Eq. 4 is momentum balance in total Lagrangian form, on the reference configuration,
 * with the second Piola-Kirchhoff stress Sigma (Eqs 5-7). For small strains F = I + grad(u)^T ~ I,
 * the Green-Lagrange strain (Eq. 7) loses its quadratic term, and Sigma, the Cauchy stress and
 * the first Piola stress coincide: sigma = mu (G + G^T) + lambda tr(G) I, with G = grad u
 * (G_ij = d u_j / d x_i). Steady and without body force, Eq. 8 becomes
 *   - oint n . (2 mu + lambda) grad u dS = oint n . q dS,
 *   q = mu G^T + lambda tr(G) I - (mu + lambda) G,
 * Eq. 9 without its three quadratic terms: sigma = K G + q with K = 2 mu + lambda.
 * --------------------------------------------------------------------- */

// @sect3{Include files}
// Those of step-1, plus constitutive.h (the Lame parameters and the stress of a gradient) and
// ghost_faces.h (boundary-face values of ghost cells, for the vertex stencils in parallel).
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include "../tutorial.h"
#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/fv/fv_operators.h>
#include <fvfsi/fv/ghost_faces.h>
#include <fvfsi/fv/gradients.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/linear_solver.h>
#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_builder.h>
#include <fvfsi/solid/constitutive.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace Step2
{
using namespace dealii;
using namespace fvfsi;
constexpr int dim = 2; // true 2D, plane stress

// @sect3{The Kirsch solution}
// The infinite plate with a hole (doc/reference/benchmarks.md section 1), in polar coordinates
// (r, t) about the hole centre. Plane stress: kappa = (3 - nu)/(1 + nu), and the 2D lambda is the
// reduced E nu / (1 - nu^2). Checks: sigma_xx(0, a) = 3 T and u_x(a, 0) = 3 a T / E = 1.5e-3 m.
namespace Kirsch
{
constexpr double E = 1e7, nu = 0.3, T = 1e4, a = 0.5;
constexpr double mu = E / (2 * (1 + nu)), lambda = E * nu / (1 - nu * nu),
                 kappa = (3 - nu) / (1 + nu);

Tensor<1, dim> displacement(const Point<dim>& p)
{
  const double r = p.norm(), t = std::atan2(p[1], p[0]), c = a * T / (8 * mu), s = a / r;
  Tensor<1, dim> u;
  u[0] =
    c * ((kappa + 1) / s * std::cos(t) + 2 * s * ((1 + kappa) * std::cos(t) + std::cos(3 * t)) -
         2 * s * s * s * std::cos(3 * t));
  u[1] =
    c * ((kappa - 3) / s * std::sin(t) + 2 * s * ((1 - kappa) * std::sin(t) + std::sin(3 * t)) -
         2 * s * s * s * std::sin(3 * t));
  return u;
}

Tensor<2, dim> stress(const Point<dim>& p)
{
  const double t = std::atan2(p[1], p[0]), s2 = a * a / p.norm_square(), s4 = 1.5 * s2 * s2;
  Tensor<2, dim> sigma;
  sigma[0][0] = T * (1 - s2 * (1.5 * std::cos(2 * t) + std::cos(4 * t)) + s4 * std::cos(4 * t));
  sigma[1][1] = T * (-s2 * (0.5 * std::cos(2 * t) - std::cos(4 * t)) - s4 * std::cos(4 * t));
  sigma[0][1] = sigma[1][0] =
    T * (-s2 * (0.5 * std::sin(2 * t) + std::sin(4 * t)) + s4 * std::sin(4 * t));
  return sigma;
}
} // namespace Kirsch

// The patches (boundary ids) of the generator fvfsi_quarter_plate_with_hole.
constexpr unsigned int hole = 0, right = 1, top = 2, left = 3, bottom = 4;
bool is_symmetry(const FaceGeometry<dim>& face)
{
  return face.patch == left || face.patch == bottom;
}

// @sect3{The PlateWithHole class}
// As in step-1, plus the state of the outer iterations: u (one CellVector per component), the
// cell gradients grad u_j and vertex values of each component, and per boundary face u_b and the
// face gradient G_b of the traction faces (Eq. 24 needs the previous one).
class PlateWithHole
{
public:
  PlateWithHole();
  void run(const std::vector<unsigned int>& n_values);

private:
  void make_grid(unsigned int n);
  void setup_system();
  void assemble_system();
  void update_boundary_values();
  void update_gradients();
  Tensor<2, dim> q(const Tensor<2, dim>& G) const;
  Tensor<2, dim> cell_gradient(unsigned int c) const;
  Tensor<2, dim> tangential_part(unsigned int f) const;
  Tensor<2, dim> face_gradient(unsigned int f) const;
  Tensor<1, dim> face_traction(unsigned int f) const;
  void compute_residual(std::array<CellVector, dim>& residual) const;
  unsigned int solve();
  std::pair<double, double> errors() const;
  void output_results(unsigned int cycle) const;

  MPI_Comm mpi_communicator;
  ConditionalOStream pcout;
  parallel::distributed::Triangulation<dim> triangulation;
  std::unique_ptr<FVGeometry<dim>> fv;
  // step-1's pieces (vertex values, Gauss-Green gradient, Laplacian), as the library bundles them.
  std::unique_ptr<FVOperators<dim>> operators;
  LameParameters lame;

  std::vector<Tensor<1, dim>> given_traction;             // Cauchy traction per traction face
  std::map<unsigned int, Tensor<1, dim>> symmetry_normal; // vertex -> normal of its plane
  std::array<TrilinosWrappers::SparseMatrix, dim> matrix;
  std::array<std::unique_ptr<LinearSolver>, dim> linear_solver;

  CellVectorField<dim> u;
  std::array<CellGradient<dim>, dim> grad_u;     // grad_u[j] = grad u_j
  std::array<std::vector<double>, dim> vertex_u; // vertex values of u_j
  std::vector<Tensor<1, dim>> boundary_u;        // u_b per boundary face
  std::vector<Tensor<2, dim>> boundary_G;        // G_b per traction face
  ConvergenceTable table;
};

PlateWithHole::PlateWithHole()
    : mpi_communicator(MPI_COMM_WORLD),
      pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0),
      triangulation(mpi_communicator), lame{Kirsch::mu, Kirsch::lambda, /*nonlinear=*/false}
{
}

// @sect4{PlateWithHole::make_grid}
// fvfsi's benchmark mesh: two blocks of n x n quadrilaterals between the hole and the outer
// edges, graded towards the hole, 2 n^2 cells. The hole vertices lie on the circle; the hole
// faces are chords. The cells are not parallelograms, so k_P, k_N do not vanish: the
// non-orthogonal correction of step-1 is needed here too.
void PlateWithHole::make_grid(const unsigned int n)
{
  operators.reset(); // the FV objects refer to the old mesh: release them first
  fv.reset();
  triangulation.clear();
  MeshParameters mesh;
  mesh.generator = "fvfsi_quarter_plate_with_hole";
  mesh.generator_arguments = "0.5: 2: " + std::to_string(n); // a: b: n
  mesh.n_global_refinements = 0;
  make_mesh(mesh, triangulation);
  fv = std::make_unique<FVGeometry<dim>>(triangulation);
  pcout << "  " << fv->n_global_cells() << " cells" << std::endl;
}

// @sect4{PlateWithHole::setup_system}
// The given traction n . sigma_exact at the centre of each face of the outer edges (zero on the
// hole), and the vertices on the symmetry planes with the plane's normal.
void PlateWithHole::setup_system()
{
  operators = std::make_unique<FVOperators<dim>>(*fv);
  u = CellVectorField<dim>(*fv);
  for (unsigned int j = 0; j < dim; ++j)
  {
    grad_u[j] = CellGradient<dim>(*fv);
    vertex_u[j].assign(fv->vertices().size(), 0.0);
  }
  boundary_u.assign(fv->faces.size(), Tensor<1, dim>());
  boundary_G.assign(fv->faces.size(), Tensor<2, dim>());
  given_traction.assign(fv->faces.size(), Tensor<1, dim>());
  symmetry_normal.clear();
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
  {
    const auto& face = fv->faces[f];
    if (face.N != invalid_cell)
      continue;
    if (is_symmetry(face)) // the planes meet at the origin, inside the hole: one per vertex
      for (const unsigned int v : face.vertices)
        symmetry_normal[v] = face.n;
    else if (face.patch != hole)
      given_traction[f] = face.n * Kirsch::stress(face.centre);
  }
}

// @sect4{PlateWithHole::assemble_system}
// Eq. 16 for cell P, steady: sum_f S_f n_f . sigma_f = 0. Split sigma_f = K G_f + q_f and take
// only the two-point part of K n_f . G_f = K (u_N - u_P)/d_fn + ... implicitly: that is step-1's
// Laplacian with Gamma = K, one matrix A_j per component (Eqs 25-27), the same for both
// components except at symmetry planes. Everything else - the non-orthogonal correction of
// Eq. 19, and q, which couples u_x and u_y - stays explicit.
//
// Why K = 2 mu + lambda. If u_N - u_P = delta n (a normal jump), the face traction is
// (2 mu + lambda) delta/d_fn n; for a tangential jump it is only mu delta/d_fn. So the true
// operator J lies between mu and 2 mu + lambda times the Laplacian, and (for Fourier modes) the
// error of the outer iteration below is multiplied by I - A^-1 J, with eigenvalues between
// 1 - (2 mu + lambda)/K and 1 - mu/K. K = 2 mu + lambda, the largest stiffness a face can show,
// puts as much of the operator as possible into the implicit part while keeping them in [0, 1): the
// iteration converges. With K = mu the dilatational modes get 1 - (2 mu + lambda)/mu < -1, and it
// diverges. This is the "maximised implicit part" of section 2.2 and of Jasak and Weller [24].
//
// Boundaries. A traction face adds nothing to A (a Neumann face: its force is known). A symmetry
// plane (u . n = 0) fixes the normal component: a Dirichlet face with weight n_j^2, so x = 0
// (n = -e_x) is Dirichlet for u_x only and y = 0 for u_y only. The rhs of assemble() is not used:
// we solve for increments, see solve().
void PlateWithHole::assemble_system()
{
  ScalarBoundaryConditions<dim> bc;
  for (const types::boundary_id id : triangulation.get_boundary_ids())
    bc.patch_type[id] =
      (id == left || id == bottom) ? BoundaryType::dirichlet : BoundaryType::neumann;
  bc.value.assign(fv->faces.size(), 0.0);
  CellVector unused_rhs = fv->make_cell_vector();
  LinearSolverParameters parameters;
  parameters.method = LinearSolverParameters::Method::cg; // A_j is symmetric, weakly diag. dominant
  parameters.preconditioner = LinearSolverParameters::Preconditioner::amg;
  parameters.reduction = 0.1; // one order of magnitude per solve (section 3.3)
  for (unsigned int j = 0; j < dim; ++j)
  {
    FaceVector gamma(fv->faces.size(), lame.K());
    for (unsigned int f = 0; f < fv->faces.size(); ++f)
      if (fv->faces[f].N == invalid_cell && is_symmetry(fv->faces[f]))
        gamma[f] *= fv->faces[f].n[j] * fv->faces[f].n[j];
    operators->laplacian.reinit_matrix(matrix[j]);
    operators->laplacian.assemble(gamma, bc, matrix[j], unused_rhs);
    matrix[j].compress(VectorOperation::add);
    linear_solver[j] = std::make_unique<LinearSolver>(parameters);
    linear_solver[j]->initialize(matrix[j]);
  }
}

// @sect4{Gradients}
// q of Eq. 9, linear terms only; sigma = K G + q. cell_gradient() assembles the tensor G_P from
// the component gradients, tangential_part() the surface gradient of each component on face f
// from the face's vertex values (Eq. 39, stored as weights by FVGeometry): (I - n n) . G_f.
Tensor<2, dim> PlateWithHole::q(const Tensor<2, dim>& G) const
{
  const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
  return lame.mu * transpose(G) + lame.lambda * trace(G) * I - (lame.mu + lame.lambda) * G;
}

Tensor<2, dim> PlateWithHole::cell_gradient(const unsigned int c) const
{
  Tensor<2, dim> G;
  for (unsigned int j = 0; j < dim; ++j)
    for (unsigned int i = 0; i < dim; ++i)
      G[i][j] = grad_u[j].components[i].local_element(c);
  return G;
}

Tensor<2, dim> PlateWithHole::tangential_part(const unsigned int f) const
{
  Tensor<2, dim> G;
  for (unsigned int j = 0; j < dim; ++j)
  {
    const Tensor<1, dim> t = tangential_gradient(fv->faces[f], vertex_u[j]);
    for (unsigned int i = 0; i < dim; ++i)
      G[i][j] = t[i];
  }
  return G;
}

// @sect4{PlateWithHole::update_boundary_values}
// u_b on every boundary face, from the current iterate:
// - symmetry: the value at the face centre extrapolated from P, u_P + k_P . G_P, with its normal
//   component removed: u_b = (I - n n) . (u_P + k_P . G_P).
// - traction: Eq. 24 gives the normal derivative from the traction, K n . G_b = t - n . q_b,
//   with q_b from the previous G_b (t S'/S = t for small strains); G_b is that normal part plus
//   the vertex-based tangential part, and u_b follows from Eq. 23 solved for u_b:
//   u_b = u_P + k_P . G_P + d_bn n . G_b.
// At convergence n . sigma(G_b) = t exactly. Ghost cells' boundary faces get the values of their
// owners, since the vertex fits of owned cells' vertices include them.
void PlateWithHole::update_boundary_values()
{
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
  {
    const auto& face = fv->faces[f];
    if (face.kind != FaceKind::boundary)
      continue;
    const Tensor<1, dim> extrapolated = u[face.P] + face.k_P * cell_gradient(face.P);
    if (is_symmetry(face))
      boundary_u[f] = extrapolated - (extrapolated * face.n) * face.n;
    else
    {
      const Tensor<1, dim> g_n = (given_traction[f] - face.n * q(boundary_G[f])) / lame.K();
      boundary_G[f] = outer_product(face.n, g_n) + tangential_part(f);
      boundary_u[f] = extrapolated + face.d_n * g_n;
    }
  }
  update_ghost_boundary_faces(*fv, boundary_u);
}

// @sect4{PlateWithHole::update_gradients}
// For each component as in step-1: vertex values by least squares (App. B), then the vertex-based
// Gauss-Green gradient (Eq. 37). In between, the symmetry constraint: the linear fit does not
// know that u . n = 0 on a symmetry plane, and its O(h^2) error there differs between the vertex
// at the corner with the hole and its neighbours; the tangential gradient of Eq. 39 on the hole
// face at that corner would then drop to first order (and with it the hole stress: order 0.9
// without the loop below). So the vertices on a plane get u . n = 0.
void PlateWithHole::update_gradients()
{
  update_boundary_values();
  FaceVector values(fv->faces.size());
  for (unsigned int j = 0; j < dim; ++j)
  {
    for (unsigned int f = 0; f < fv->faces.size(); ++f)
      values[f] = boundary_u[f][j];
    operators->vertex_interpolation.interpolate(u.components[j], values, vertex_u[j]);
  }
  for (const auto& [v, n] : symmetry_normal)
  {
    const double u_n = vertex_u[0][v] * n[0] + vertex_u[1][v] * n[1];
    for (unsigned int j = 0; j < dim; ++j)
      vertex_u[j][v] -= u_n * n[j];
  }
  for (unsigned int j = 0; j < dim; ++j)
    operators->gauss_green.compute(vertex_u[j], grad_u[j]);
}

// @sect4{Face gradients and tractions}
// The face gradient is built from its normal and tangential parts separately (section 3.2):
// G_f = n (n . G_f) + (I - n n) . G_f. The normal part is the central difference with the
// non-orthogonal correction, Eq. 19 (sign convention of step-1), or Eq. 23 on a symmetry face;
// the tangential part comes from the vertex values of the face itself (Eq. 39). Traction faces
// keep the G_b of update_boundary_values().
//
// This is where the present method differs from Demirdzic-Muzaferija and Jasak-Weller, which
// take the tangential part from the cell gradient G_P at r_P, half a cell away: an O(h) error at
// the face. On the traction-free hole sigma_rr = sigma_rt = 0 is imposed by Eq. 24, so the only
// stress left, sigma_tt = E eps_tt, is the tangential derivative of u along the hole: its error
// IS the error of the tangential gradient. The vertex values come from fits that are exact for
// linear fields, so Eq. 39 is second order, like the vertex-based cell gradient of step-1, and so
// is the hole stress (the normal part there follows from the traction through Eq. 24). Replace
// tangential_part(f) by (I - n n) . G_P on the traction faces and the order drops to 0.9 (README).
Tensor<2, dim> PlateWithHole::face_gradient(const unsigned int f) const
{
  const auto& face = fv->faces[f];
  if (face.N == invalid_cell && !is_symmetry(face))
    return boundary_G[f];
  const Tensor<2, dim> G_P = cell_gradient(face.P);
  const Tensor<1, dim> g_n =
    face.N == invalid_cell
      ? (boundary_u[f] - u[face.P] - face.k_P * G_P) / face.d_n
      : (u[face.N] - u[face.P] - face.k_N * cell_gradient(face.N) - face.k_P * G_P) / face.d_n;
  return outer_product(face.n, g_n) + tangential_part(f);
}

// The force per unit area on face f, out of P: n . sigma_f, with sigma = K G + q. A traction
// face carries the given traction; a symmetry face only the normal part (no shear on a plane
// of symmetry).
Tensor<1, dim> PlateWithHole::face_traction(const unsigned int f) const
{
  const auto& face = fv->faces[f];
  if (face.N == invalid_cell && !is_symmetry(face))
    return given_traction[f];
  const Tensor<2, dim> G = face_gradient(f);
  const Tensor<1, dim> t = face.n * (lame.K() * G + q(G));
  return face.N == invalid_cell ? (t * face.n) * face.n : t;
}

// @sect4{PlateWithHole::compute_residual}
// R_P = sum_f S_f n_f . sigma_f, the residual of Eq. 16 at the current iterate, with the face
// ownership rule of step-1 (interior faces act on P and N, processor faces on P only).
void PlateWithHole::compute_residual(std::array<CellVector, dim>& residual) const
{
  for (auto& r : residual)
    r = 0;
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
  {
    const auto& face = fv->faces[f];
    if (face.kind == FaceKind::ghost_boundary)
      continue;
    const Tensor<1, dim> force = face.area * face_traction(f);
    for (unsigned int j = 0; j < dim; ++j)
    {
      residual[j].local_element(face.P) += force[j];
      if (face.kind == FaceKind::interior)
        residual[j].local_element(face.N) -= force[j];
    }
  }
}

// @sect4{PlateWithHole::solve}
// The segregated algorithm of section 3.3. The paper writes each outer iteration as
// A_j u_j^new = b_j(u*), the explicit terms (non-orthogonal correction, q, boundary values) from
// the last iterate u*. Since A_j u*_j - R_j(u*) is exactly those terms, this is
//   A_j du_j = R_j(u*),  u_j = u*_j + du_j,
// the form we use: R vanishes at the solution, so the converged u solves the discrete Eq. 16
// whatever the matrix, and the components are solved one after the other (A is that of a
// Laplacian, not of the coupled elasticity operator). Each outer iteration updates the boundary
// values, vertex values and gradients, computes R, and solves once per component.
//
// Why one order of residual reduction per solve is enough: R is computed from u*, so the next
// iteration changes the right-hand side by as much as the lagged terms change - a far larger
// error than the linear solver's. Solving to 1e-8 would buy nothing; any error the solver leaves
// is still in R at the next iteration and gets corrected there. The outer iteration itself
// converges linearly (its rate set by the explicit part: q, and the traction boundary values,
// lagged by one iteration), so it needs hundreds of iterations; SolidSolver accelerates them
// (Anderson mixing), this tutorial does not. We stop at max|du| < 1e-8 max|u|.
unsigned int PlateWithHole::solve()
{
  std::array<CellVector, dim> residual, du;
  for (unsigned int j = 0; j < dim; ++j)
  {
    residual[j] = fv->make_cell_vector();
    du[j] = fv->make_cell_vector();
  }
  for (unsigned int k = 1; k <= 20000; ++k)
  {
    update_gradients();
    compute_residual(residual);
    double max_du = 0, max_u = 0;
    for (unsigned int j = 0; j < dim; ++j)
    {
      du[j] = 0;
      linear_solver[j]->solve(matrix[j], du[j], residual[j], "u_" + std::to_string(j));
      for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
      {
        u.components[j].local_element(c) += du[j].local_element(c);
        max_du = std::max(max_du, std::abs(du[j].local_element(c)));
        max_u = std::max(max_u, std::abs(u.components[j].local_element(c)));
      }
    }
    u.update_ghost_values();
    max_du = Utilities::MPI::max(max_du, mpi_communicator);
    max_u = Utilities::MPI::max(max_u, mpi_communicator);
    if (max_du < 1e-8 * max_u)
    {
      update_gradients(); // boundary values and gradients of the final u
      return k;
    }
  }
  throw std::runtime_error("the outer iterations did not converge");
}

// @sect4{PlateWithHole::errors}
// The paper's two measures (section 4.1): the max cell-centre displacement error over both
// components, and the max error of the face-centre Cauchy stress (xx, yy, xy) on the hole faces,
// with sigma from G_b by constitutive.h (the small-strain stress, which is K G + q).
std::pair<double, double> PlateWithHole::errors() const
{
  double u_error = 0, stress_error = 0;
  for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
  {
    const Tensor<1, dim> error = u[c] - Kirsch::displacement(fv->centroid[c]);
    u_error = std::max({u_error, std::abs(error[0]), std::abs(error[1])});
  }
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
    if (fv->faces[f].kind == FaceKind::boundary && fv->faces[f].patch == hole)
    {
      const Tensor<2, dim> error =
        cauchy_stress(boundary_G[f], lame) - Kirsch::stress(fv->faces[f].centre);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          stress_error = std::max(stress_error, std::abs(error[i][j]));
    }
  return {Utilities::MPI::max(u_error, mpi_communicator),
          Utilities::MPI::max(stress_error, mpi_communicator)};
}

// @sect4{PlateWithHole::output_results}
// u, the cell stress sigma_yy (the field of the paper's Fig. 6) and the displacement error
// |u_P - u(r_P)|, to plate-<cycle>_0000.pvtu.
void PlateWithHole::output_results(const unsigned int cycle) const
{
  OutputFields<dim> fields(*fv);
  fields.add_vector("u", [&](const unsigned int c) { return u[c]; });
  fields.add("sigma_yy",
             [&](const unsigned int c) { return cauchy_stress(cell_gradient(c), lame)[1][1]; });
  fields.add("displacement_error", [&](const unsigned int c)
             { return (u[c] - Kirsch::displacement(fv->centroid[c])).norm(); });
  VtuOutput<dim>(*fv, ".", "plate-" + std::to_string(cycle)).write(fields, 0, 0.0);
}

// @sect4{PlateWithHole::run}
// n = 11, 22, 45: 242, 968, 4050 cells, each mesh about twice as fine as the last. The table
// gives both errors with their observed orders log(e_old/e)/log(h_old/h), h ~ cells^(-1/2).
void PlateWithHole::run(const std::vector<unsigned int>& n_values)
{
  for (unsigned int cycle = 0; cycle < n_values.size(); ++cycle)
  {
    pcout << "Cycle " << cycle << ", n = " << n_values[cycle] << ':' << std::endl;
    make_grid(n_values[cycle]);
    setup_system();
    assemble_system();
    const unsigned int n_outer = solve();
    const auto [u_error, stress_error] = errors();
    pcout << "  " << n_outer << " outer iterations, max displacement error " << u_error
          << " m, max hole stress error " << stress_error << " Pa" << std::endl;
    table.add_value("cells", fv->n_global_cells());
    table.add_value("max u error", u_error);
    table.add_value("max hole stress error", stress_error);
    output_results(cycle);
  }
  for (const std::string key : {"max u error", "max hole stress error"})
  {
    table.set_scientific(key, true);
    table.set_precision(key, 3);
  }
  // Observed orders log2(e_old / e) / (log2(N / N_old) / 2) of every error column (2D).
  table.omit_column_from_convergence_rate_evaluation("cells");
  table.evaluate_all_convergence_rates("cells", ConvergenceTable::reduction_rate_log2);
  fvfsi_tutorial::write_table(table, mpi_communicator);
}
} // namespace Step2

// @sect3{The main function}
int main(int argc, char* argv[])
{
  return fvfsi_tutorial::main_program(argc, argv, "step-2",
                                      []()
                                      {
                                        Step2::PlateWithHole problem;
                                        problem.run({11, 22, 45});
                                      });
}
