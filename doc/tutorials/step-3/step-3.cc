/* ---------------------------------------------------------------------
 * fvfsi tutorial step-3: incompressible flow past the cylinder by the PISO algorithm.
 *
 * The Turek-Hron channel (doc/reference/benchmarks.md section 2): [0, 2.5] x [0, 0.41] m, the rigid
 * cylinder of radius 0.05 m at (0.2, 0.2) with the rigid flag behind it (y in [0.19, 0.21], up
 * to x = 0.6), a parabolic inflow of mean velocity U, no slip on the walls, the cylinder and
 * the flag, and p = 0 at the outlet. rho = 1000 kg/m^3, nu = 1e-3 m^2/s. With U = 0.2 m/s the
 * Reynolds number Re = U D / nu (D = 0.1 m) is 20: the flow is steady (Turek and Hron's CFD1;
 * their drag and lift on cylinder + flag are 14.29 N/m and 1.119 N/m per unit depth). The
 * second part starts the flow at Re = 100 (U = 1 m/s) from rest and follows it for 20 time steps.
 *
 * The equations (paper section 2.1, Eqs 1-2), with p the kinematic pressure p/rho [m^2/s^2]:
 *   div u = 0,
 *   du/dt + div(u u) - div(nu grad u) = -grad p.
 * Velocity and pressure live at the same points, the cell centres (a collocated, cell-centred
 * finite-volume method: one value per cell, FE_DGQ(0) in deal.II terms). fvfsi::FluidSolver is
 * the full solver (BDF2, moving meshes, symmetry planes, 3D, outer correctors); this program
 * writes out its core for a fixed 2D mesh with inlet, outlet and walls in one class, with step-1's
 * and step-2's pieces (FVGeometry, VertexInterpolation, GaussGreenGradient, Laplacian,
 * LinearSolver) plus the face-stored matrix FaceMatrix, and then checks that both give the same
 * forces, steady and transient.
 *
 * The algorithm, one (pseudo) time step:
 *   1. boundary values, vertex values and Gauss-Green gradients of u and p;
 *   2. momentum predictor: assemble and solve the momentum equation with the latest face fluxes
 *      F_f and the latest pressure gradient (convection linear-upwind and the non-orthogonal
 *      part of the viscous term by deferred correction);
 *   3. PISO correctors, twice: the momentum equation without its pressure term gives a predicted
 *      face flux F*_f (the consistent Rhie-Chow interpolation); continuity sum_f F_f = 0 turns
 *      into a Laplace equation for p; its solution corrects the fluxes (which then conserve mass
 *      exactly) and the cell velocities.
 * --------------------------------------------------------------------- */

// @sect3{Include files}
// Those of step-2, plus face_matrix.h (the matrix stored by faces, with its off-diagonal product
// that the pressure-velocity coupling needs) and fluid_solver.h for the comparison at the end.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include "../tutorial.h"
#include <fvfsi/base/time_levels.h>
#include <fvfsi/fluid/fluid_parameters.h>
#include <fvfsi/fluid/fluid_solver.h>
#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/fv/face_matrix.h>
#include <fvfsi/fv/fv_operators.h>
#include <fvfsi/fv/ghost_faces.h>
#include <fvfsi/fv/gradients.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/linear_solver.h>
#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_builder.h>
#include <fvfsi/mesh/mesh_parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace Step3
{
using namespace dealii;
using namespace fvfsi;
constexpr int dim = 2;

// @sect3{The data}
// The case in SI units. The patches (boundary ids) are those of the mesh generator
// fvfsi_turek_hron_channel.
constexpr double rho = 1000; // density [kg/m^3] (only for the forces)
constexpr double nu = 1e-3;  // kinematic viscosity [m^2/s]
constexpr double H = 0.41;   // channel height [m]
constexpr unsigned int inlet = 0, outlet = 1, walls = 2, cylinder = 3, flag = 4;

// The inflow: u_x = 1.5 U 4 y (H - y) / H^2, mean U [m/s]; U = 0.2 m/s gives Re = U D / nu = 20,
// U = 1 m/s Re = 100.
double inflow(const Point<dim>& x, const double U)
{
  return 1.5 * U * 4 * x[1] * (H - x[1]) / (H * H);
}

// @sect3{The CylinderFlow class}
// The state is that of fvfsi::FluidSolver (fluid_solver.h): the cell velocity u and kinematic
// pressure p, the volumetric face fluxes F_f = S_f . u_f [m^2/s per unit depth] of this and of
// the two previous (pseudo) time steps (BDF2 needs both), and what is derived from them (vertex
// values, Gauss-Green gradients, boundary values). The momentum equation of the current step is
// kept, because the PISO correctors re-use it: its matrix (FaceMatrix: the diagonal A_P and, per
// face, the two off-diagonal coefficients), its explicit source B_rest and its time source B_time.
class CylinderFlow
{
public:
  /// dt = 0: steady, by local pseudo time steps set by alpha; dt > 0: time accurate (BDF2).
  CylinderFlow(unsigned int n, double U, double alpha, bool consistent = true, double dt = 0);
  /// Steady: iterate to convergence. Transient: n_time_steps steps, drag and lift every
  /// `interval` steps into `history` (t, drag, lift).
  void run(unsigned int n_time_steps = 0, unsigned int interval = 1,
           std::vector<std::array<double, 3>>* history = nullptr);
  Tensor<1, dim> force() const; // of the fluid on cylinder + flag [N/m]
  unsigned int n_steps() const { return step; }
  unsigned int n_cells() const { return fv->n_global_cells(); }

private:
  void make_grid();
  void setup_system();
  void update_velocity_boundary_values();
  void update_velocity_gradients();
  void update_pressure_boundary_values();
  void update_pressure_gradient();
  void assemble_momentum();
  void solve_momentum();
  void assemble_pressure_equation();
  void compute_predicted_fluxes();
  void solve_pressure();
  void correct_fluxes_and_velocity();
  double solve_time_step();
  void solve();
  void output_results() const;

  const unsigned int n;  // cells on a quarter of the cylinder
  const double U;        // mean inflow velocity [m/s]
  const double alpha;    // momentum relaxation, sets the local pseudo time step
  const double dt;       // time step [s], 0 for steady
  const bool consistent; // consistent (true) or classic Rhie-Chow face flux
  MPI_Comm mpi_communicator;
  ConditionalOStream pcout;
  parallel::distributed::Triangulation<dim> triangulation;
  std::unique_ptr<FVGeometry<dim>> fv;
  // step-1's and step-2's pieces (vertex values, Gauss-Green gradient, Laplacian), as the library
  // bundles them.
  std::unique_ptr<FVOperators<dim>> operators;

  ScalarBoundaryConditions<dim> velocity_bc, pressure_bc;
  FaceVector nu_f; // Gamma_f of the viscous Laplacian

  std::unique_ptr<FaceMatrix<dim>> momentum, pressure_equation;
  TrilinosWrappers::SparseMatrix momentum_matrix, pressure_matrix;
  std::unique_ptr<LinearSolver> momentum_solver, pressure_solver;

  // The present u and F and their old levels u^o, u^oo (u_levels.o, u_levels.oo): the library's
  // TimeLevels, which every solver of fvfsi keeps its history in.
  CellVectorField<dim> u;
  TimeLevels<CellVectorField<dim>> u_levels;
  CellVector p;
  FaceVector F;
  TimeLevels<FaceVector> F_levels;
  unsigned int step = 0;
  void time_coefficients(double& c0, double& c1, double& c2) const;

  std::array<CellGradient<dim>, dim> grad_u;
  CellGradient<dim> grad_p;
  std::array<std::vector<double>, dim> vertex_u;
  std::vector<double> vertex_p;
  std::vector<Tensor<1, dim>> boundary_u;
  FaceVector boundary_p;

  std::array<std::vector<double>, dim> B_time;
  std::array<CellVector, dim> B_rest;
  CellVector a, a_star, c0_cell_ghosted;
  CellVectorField<dim> h;
  std::vector<double> c0_cell;
  FaceVector a_star_f, c0_face, gamma_p, F_star;
  CellVector pressure_rhs;
};

CylinderFlow::CylinderFlow(const unsigned int n, const double U, const double alpha,
                           const bool consistent, const double dt)
    : n(n), U(U), alpha(alpha), dt(dt), consistent(consistent), mpi_communicator(MPI_COMM_WORLD),
      pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0),
      triangulation(mpi_communicator)
{
  if (!consistent && dt > 0)
    throw std::logic_error("the classic flux is written out for steady runs only");
}

// @sect4{CylinderFlow::make_grid}
// The block-structured channel mesh of fvfsi (source/mesh/turek_hron_channel.cc): an O-grid
// around the cylinder graded towards it, the flag cut out, cells stretched towards the outlet.
// n = 8 cells on a quarter of the cylinder give a coarse mesh of about a thousand cells; the
// prm/turek_hron_cfd2.prm run uses n = 32. The O-grid cells are not parallelograms and the
// block joins are not orthogonal: the k_P, k_N of Eqs 21-22 do not vanish, and the deferred
// non-orthogonal correction of Eq. 19 is needed, for the viscous term as for the pressure.
void CylinderFlow::make_grid()
{
  MeshParameters mesh;
  mesh.generator = "fvfsi_turek_hron_channel";
  mesh.generator_arguments = std::to_string(n);
  mesh.n_global_refinements = 0;
  make_mesh(mesh, triangulation);
  fv = std::make_unique<FVGeometry<dim>>(triangulation);
}

// @sect4{CylinderFlow::setup_system}
// Sizes every field and sets the boundary types of the two Laplacians this program uses:
// - the viscous term -div(nu grad u_j): u given (Dirichlet) on inlet, walls, cylinder and flag;
//   zero normal gradient (Neumann) at the outlet;
// - the pressure equation: p given at the outlet (Dirichlet); elsewhere the face flux is given
//   by the velocity boundary condition, so the pressure is not needed there (Neumann).
// The pressure solver is CG + AMG (the pressure matrix is symmetric), the momentum solver GMRES +
// ILU (convection makes the momentum matrix unsymmetric). Momentum needs only 3 orders of
// residual reduction: its right-hand side is lagged anyway.
void CylinderFlow::setup_system()
{
  operators = std::make_unique<FVOperators<dim>>(*fv);
  momentum = std::make_unique<FaceMatrix<dim>>(*fv);
  pressure_equation = std::make_unique<FaceMatrix<dim>>(*fv);
  momentum->reinit();
  pressure_equation->reinit();
  operators->laplacian.reinit_matrix(momentum_matrix);
  operators->laplacian.reinit_matrix(pressure_matrix);

  for (const unsigned int patch : {inlet, outlet, walls, cylinder, flag})
  {
    velocity_bc.patch_type[patch] =
      patch == outlet ? BoundaryType::neumann : BoundaryType::dirichlet;
    pressure_bc.patch_type[patch] =
      patch == outlet ? BoundaryType::dirichlet : BoundaryType::neumann;
  }
  const unsigned int n_faces = fv->faces.size();
  velocity_bc.value.assign(n_faces, 0.0);
  pressure_bc.value.assign(n_faces, 0.0); // p = 0 at the outlet
  nu_f.assign(n_faces, nu);

  LinearSolverParameters momentum_parameters, pressure_parameters;
  momentum_parameters.method = LinearSolverParameters::Method::gmres;
  momentum_parameters.preconditioner = LinearSolverParameters::Preconditioner::ilu;
  momentum_parameters.reduction = 1e-3;
  momentum_parameters.absolute_tolerance = 1e-15;
  pressure_parameters.method = LinearSolverParameters::Method::cg;
  pressure_parameters.preconditioner = LinearSolverParameters::Preconditioner::amg;
  pressure_parameters.reduction = 1e-6;
  pressure_parameters.absolute_tolerance = 1e-15;
  momentum_solver = std::make_unique<LinearSolver>(momentum_parameters);
  pressure_solver = std::make_unique<LinearSolver>(pressure_parameters);

  u = h = CellVectorField<dim>(*fv);
  u_levels.start(u);
  for (unsigned int j = 0; j < dim; ++j)
  {
    grad_u[j] = CellGradient<dim>(*fv);
    vertex_u[j].assign(fv->vertices().size(), 0.0);
    B_rest[j] = fv->make_cell_vector();
    B_time[j].assign(fv->n_owned_cells(), 0.0);
  }
  grad_p = CellGradient<dim>(*fv);
  vertex_p.assign(fv->vertices().size(), 0.0);
  p = fv->make_cell_vector();
  a = fv->make_cell_vector();
  a_star = fv->make_cell_vector();
  c0_cell_ghosted = fv->make_cell_vector();
  pressure_rhs = fv->make_cell_vector();
  for (auto* field : {&F, &F_star, &gamma_p, &a_star_f, &c0_face, &boundary_p})
    field->assign(n_faces, 0.0);
  boundary_u.assign(n_faces, Tensor<1, dim>());
  c0_cell.assign(fv->n_owned_cells(), 0.0);

  // The initial state: fluid at rest, and the face fluxes of it; only the inlet faces carry
  // their given flux S_f . u_b. (The initial fluxes are not divergence free; the first pressure
  // equation fixes that.)
  update_velocity_boundary_values();
  for (unsigned int f = 0; f < n_faces; ++f)
    if (fv->faces[f].N == invalid_cell)
      F[f] = fv->faces[f].S * boundary_u[f];
  F_levels.start(F);
}

// @sect4{Boundary values and gradients}
// u_b per boundary face: the inflow profile at the inlet, zero on the walls, and at the outlet
// the value at the face centre extrapolated from the cell, u_P + k_P . (grad u)_P, which makes the
// normal gradient zero in the sense of Eq. 23. p_b: zero at the outlet, elsewhere the linear
// extrapolation p_P + (r_f - r_P) . (grad p)_P of the paper's section 3.2. Then, as in step-1 and
// step-2, vertex values by least squares (Appendix B) and the vertex-based Gauss-Green cell
// gradient (Eq. 37), exact for linear fields on any mesh.
void CylinderFlow::update_velocity_boundary_values()
{
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
  {
    const auto& face = fv->faces[f];
    if (face.kind != FaceKind::boundary)
      continue;
    if (face.patch == inlet)
      boundary_u[f] = Tensor<1, dim>({inflow(face.centre, U), 0.});
    else if (face.patch == outlet)
      for (unsigned int j = 0; j < dim; ++j)
        boundary_u[f][j] = u[face.P][j] + face.k_P * grad_u[j][face.P];
    else
      boundary_u[f] = Tensor<1, dim>();
  }
  update_ghost_boundary_faces(*fv, boundary_u);
}

void CylinderFlow::update_velocity_gradients()
{
  FaceVector values(fv->faces.size());
  for (unsigned int j = 0; j < dim; ++j)
  {
    for (unsigned int f = 0; f < fv->faces.size(); ++f)
      values[f] = boundary_u[f][j];
    operators->gradient(u.components[j], values, vertex_u[j], grad_u[j]);
  }
}

void CylinderFlow::update_pressure_boundary_values()
{
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
  {
    const auto& face = fv->faces[f];
    if (face.kind == FaceKind::boundary)
      boundary_p[f] =
        face.patch == outlet ? 0.0 : p.local_element(face.P) + face.d * grad_p[face.P];
  }
  update_ghost_boundary_faces(*fv, boundary_p);
}

void CylinderFlow::update_pressure_gradient()
{
  operators->gradient(p, boundary_p, vertex_p, grad_p);
}

// @sect4{CylinderFlow::assemble_momentum}
// The momentum equation of cell P, integrated over V_P (Gauss: volume integrals of divergences
// become sums over the faces f of P, S_f n_f the face area vector out of P):
//
//   V_P (du/dt)_P + sum_f phi_f u_f - sum_f nu S_f (n . grad u)_f = -V_P (grad p)_P,
//
// with phi_f = F_f, the volumetric flux of the last corrector (on a moving mesh the mesh flux is
// subtracted; not here). Component by component this is
//
//   A_P u_P + sum_N A_PN u_N = B_P - V_P (grad p)_P,
//
// one matrix for both components (they differ only in their sources). Each term:
//
// - Viscous, Eq. 19: nu S_f (u_N - u_P)/d_fn implicit (FaceMatrix::add_face_diffusion with
//   a = nu S_f / d_fn, Eq. 27), the non-orthogonal part -nu S_f (k_N.grad u_N + k_P.grad u_P)/d_fn
//   explicit with the gradients of the last iterate (Laplacian::add_correction; the sign
//   convention of k_N is step-1's). At a wall or inlet, Eq. 23: nu S_f (u_b - u_P - k_P.grad
//   u_P)/d_n, u_b into the source, the k_P part again in add_correction.
// - Convection, linear upwind by deferred correction: u_f = u_U + (r_f - r_U) . (grad u)_U, U the
//   upwind cell. Second order, and bounded in practice because its implicit part is pure upwind:
//   phi_f u_U goes into the matrix (diagonally dominant: an M-matrix, so GMRES + ILU converge and
//   the predictor cannot oscillate), the difference phi_f (u_f - u_U) to the source with the
//   gradient of the last iterate. At convergence the lagged part is the current one: the
//   converged solution is that of the second-order scheme. (Central differencing would be
//   unbounded where the cell Peclet number |u| h / nu exceeds 2, i.e. near the cylinder.)
// - Outlet: outflow carries u_P implicitly, corrected to u_b explicitly; zero viscous flux.
// - Time: steady, by local pseudo time steps: c0_P = a*_P (1 - alpha) / alpha, with a*_P = A_P /
//   V_P of the spatial terms assembled so far. Then A_P / V_P = a*_P / alpha: this is exactly
//   SIMPLE's implicit under-relaxation of the momentum equation with factor alpha, written as a
//   time step (each cell gets its own "Courant number" of about alpha / (1 - alpha)). The time
//   source B_time = V_P c0_P u_P^old. A transient run (dt > 0) uses the same code with BDF2
//   (Eq. 17): du/dt ~ c0 u - c1 u^o + c2 u^oo with c0 = 3/(2 dt), c1 = 2/dt, c2 = 1/(2 dt),
//   backward Euler (c0 = c1 = 1/dt, c2 = 0) on the first step, the same in all cells, and
//   B_time = V_P (c1 u^o - c2 u^oo).
void CylinderFlow::assemble_momentum()
{
  momentum->zero();
  for (unsigned int j = 0; j < dim; ++j)
    B_rest[j] = 0;
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
  {
    const auto& face = fv->faces[f];
    if (face.kind == FaceKind::ghost_boundary)
      continue;
    const double phi = F[f];
    const double a_diffusion = nu * face.area / face.d_n;
    const unsigned int P = face.P;
    if (face.N != invalid_cell)
    {
      momentum->add_face_diffusion(f, a_diffusion);
      // phi u_f leaves P and enters N; its upwind part:
      momentum->diagonal[P] += std::max(phi, 0.0);
      momentum->upper[f] += std::min(phi, 0.0);
      if (face.kind == FaceKind::interior)
      {
        momentum->diagonal[face.N] += std::max(-phi, 0.0);
        momentum->lower[f] -= std::max(phi, 0.0);
      }
      // ... and the deferred linear-upwind correction phi (u_f - u_U).
      const unsigned int U_cell = phi >= 0 ? face.P : face.N;
      const Tensor<1, dim> to_face = face.centre - fv->centroid[U_cell];
      for (unsigned int j = 0; j < dim; ++j)
      {
        const double correction = phi * (to_face * grad_u[j][U_cell]);
        B_rest[j].local_element(P) -= correction;
        if (face.kind == FaceKind::interior)
          B_rest[j].local_element(face.N) += correction;
      }
    }
    else if (face.patch == outlet)
    {
      momentum->diagonal[P] += std::max(phi, 0.0);
      for (unsigned int j = 0; j < dim; ++j)
        B_rest[j].local_element(P) -=
          std::min(phi, 0.0) * boundary_u[f][j] + std::max(phi, 0.0) * (boundary_u[f][j] - u[P][j]);
    }
    else // inlet and walls: u_b given
    {
      momentum->diagonal[P] += a_diffusion;
      for (unsigned int j = 0; j < dim; ++j)
        B_rest[j].local_element(P) += (a_diffusion - phi) * boundary_u[f][j];
    }
  }
  for (unsigned int j = 0; j < dim; ++j)
    operators->laplacian.add_correction(nu_f, velocity_bc, grad_u[j], B_rest[j]);

  double c0, c1, c2;
  time_coefficients(c0, c1, c2);
  for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
  {
    const double V = fv->cell_volume[c];
    c0_cell[c] = dt > 0 ? c0 : momentum->diagonal[c] / V * (1 - alpha) / alpha;
    const double c1_P = dt > 0 ? c1 : c0_cell[c];
    momentum->diagonal[c] += c0_cell[c] * V;
    for (unsigned int j = 0; j < dim; ++j)
      B_time[j][c] = V * (c1_P * u_levels.o.components[j].local_element(c) -
                          c2 * u_levels.oo.components[j].local_element(c));
  }
}

// The BDF2 coefficients of a transient run (zero when steady).
void CylinderFlow::time_coefficients(double& c0, double& c1, double& c2) const
{
  if (dt == 0)
    c0 = c1 = c2 = 0;
  else if (step == 1)
  {
    c0 = c1 = 1 / dt;
    c2 = 0;
  }
  else
  {
    c0 = 1.5 / dt;
    c1 = 2 / dt;
    c2 = 0.5 / dt;
  }
}

// @sect4{CylinderFlow::solve_momentum}
// The momentum predictor: A u_j = B_rest_j + B_time_j - V (grad p)_j with the pressure of the
// last step. Its u does not conserve mass; it is what the correctors start from (the off-diagonal
// part of the first h below uses it). The ILU preconditioner is rebuilt every 10 steps only:
// the matrix changes slowly, and an old preconditioner costs a few iterations, not accuracy.
void CylinderFlow::solve_momentum()
{
  momentum->copy_to(momentum_matrix);
  if ((step - 1) % 10 == 0)
    momentum_solver->initialize(momentum_matrix);
  CellVector rhs = fv->make_cell_vector();
  for (unsigned int j = 0; j < dim; ++j)
  {
    for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
      rhs.local_element(c) =
        B_rest[j].local_element(c) + B_time[j][c] - fv->cell_volume[c] * grad_p[c][j];
    momentum_solver->solve(momentum_matrix, u.components[j], rhs, "momentum");
  }
  u.update_ghost_values();
}

// @sect4{CylinderFlow::assemble_pressure_equation}
// Divide the momentum equation by V_P: a_P u_P = h_P + B_time_P / V_P - (grad p)_P, with
// a_P = A_P / V_P and h_P = (B_rest_P - sum_N A_PN u_N) / V_P. Split a_P = c0_P + a*_P into its
// time part and its spatial part a*_P. The face flux is defined by the same equation "at the
// face" (the consistent Rhie-Chow interpolation of Tukovic and Jasak, the paper's refs [20, 21]):
//
//   (c0_f + a*_f) F_f = c0_f F_f^old + a*_f S_f . (h / a*)_f - S_f (n . grad p)_f,
//
// with a*_f = 1 / (1 / a*)_f, (1 / a*)_f and (h / a*)_f interpolated linearly between P and N,
// (n . grad p)_f by Eq. 19 and c0_f = a*_f (1 - alpha) / alpha like c0_P. So
//
//   F_f = F*_f - Gamma_f S_f (n . grad p)_f,   Gamma_f = 1 / (c0_f + a*_f),
//   F*_f = Gamma_f (c0_f F_f^old + a*_f S_f . (h / a*)_f),
//
// and continuity, sum_f F_f = 0, becomes the pressure equation
//
//   - sum_f Gamma_f S_f (n . grad p)_f = - sum_f F*_f,
//
// step-1's Laplacian with diffusivity Gamma_f: its orthogonal part is the matrix assembled here,
// its non-orthogonal part is deferred (solve_pressure()). The face flux is driven by the pressure
// difference across the face, (p_N - p_P) / d_fn, not by interpolated cell gradients: a
// checkerboard pressure, invisible to (grad p)_P, is seen by the faces and removed. That is the
// point of Rhie-Chow interpolation on collocated meshes.
//
// Why "consistent": at a steady state F_f = F_f^old, and the c0_f terms cancel:
//
//   a*_f F_f = a*_f S_f . (h / a*)_f - S_f (n . grad p)_f,
//
// the face version of the steady cell equation a*_P u_P = h_P - (grad p)_P, with no c0 in it.
// The converged solution does not depend on the time step (here: on alpha). The classic
// Rhie-Chow flux interpolates 1 / a_f = 1 / (c0 + a*)_f instead and drops the F^old term, so its
// pressure-smoothing term scales with 1 / (c0 + a*), and the converged velocity and forces change
// with dt or the relaxation factor: with alpha = 0.95 and 0.5 the consistent flux gives the same
// forces, the classic one (this class with consistent = false) forces that differ by up to 5e-4
// (see the table of run()). The classic flux is
//   F_f = S_f . ((h + c0 u^o) / a)_f - (1 / a)_f S_f (n . grad p)_f;
// at a steady state (h + c0 u) / a = u + (grad p) / a in each cell, so its pressure term,
// (1 / a)_f S_f . [(grad p)_interpolated - n (n . grad p)_f], is weighted by 1 / a = alpha / a*.
// Interpolating h / a* (a velocity) rather than h keeps F*_f second order where a*_P jumps
// from cell to cell (graded meshes), and (h / a*)_f is corrected for skewness with the velocity
// gradient (h / a* = u + (grad p) / a* at steady state; the point of linear interpolation on
// the line P-N misses the face centre by m_f).
//
// Inlet and wall faces have a given flux and no pressure term (Gamma_f = 0); outlet faces see
// p_b = 0 through Eq. 23 (a Dirichlet face: only the diagonal).
void CylinderFlow::assemble_pressure_equation()
{
  double c0, c1, c2;
  time_coefficients(c0, c1, c2);
  for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
  {
    a.local_element(c) = momentum->diagonal[c] / fv->cell_volume[c];
    a_star.local_element(c) = a.local_element(c) - c0_cell[c];
    c0_cell_ghosted.local_element(c) = c0_cell[c];
  }
  a.update_ghost_values();
  a_star.update_ghost_values();
  c0_cell_ghosted.update_ghost_values();
  pressure_equation->zero();
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
  {
    const auto& face = fv->faces[f];
    if (face.kind == FaceKind::ghost_boundary)
      continue;
    if (face.N == invalid_cell && face.patch != outlet)
    {
      gamma_p[f] = 0;
      continue;
    }
    const double inverse_a_star =
      face.N == invalid_cell
        ? 1 / a_star.local_element(face.P)
        : face.interpolate_reciprocal(a_star.local_element(face.P), a_star.local_element(face.N));
    a_star_f[f] = 1 / inverse_a_star;
    c0_face[f] = dt > 0 ? c0 : a_star_f[f] * (1 - alpha) / alpha;
    gamma_p[f] = 1 / (c0_face[f] + a_star_f[f]);
    if (!consistent) // classic: Gamma_f = (1 / a)_f, a = c0 + a*
      gamma_p[f] = face.N == invalid_cell ? 1 / a.local_element(face.P)
                                          : face.interpolate_reciprocal(a.local_element(face.P),
                                                                        a.local_element(face.N));
    const double coefficient = gamma_p[f] * face.area / face.d_n;
    if (face.N == invalid_cell)
      pressure_equation->diagonal[face.P] += coefficient;
    else
      pressure_equation->add_face_diffusion(f, coefficient);
  }
  pressure_equation->copy_to(pressure_matrix);
  if ((step - 1) % 10 == 0)
    pressure_solver->initialize(pressure_matrix);
}

// @sect4{CylinderFlow::compute_predicted_fluxes}
// h_P from the latest velocity (the predictor's at the first corrector, the first corrector's at
// the second: this is what makes PISO more than SIMPLE, the neighbour velocities sum_N A_PN u_N
// are updated between the corrections), then F*_f of the formula above. FaceMatrix gives
// sum_N A_PN u_N directly, from its stored face coefficients.
void CylinderFlow::compute_predicted_fluxes()
{
  std::vector<double> off_diagonal;
  for (unsigned int j = 0; j < dim; ++j)
  {
    momentum->off_diagonal_product(u.components[j], off_diagonal);
    for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
      h.components[j].local_element(c) =
        (B_rest[j].local_element(c) - off_diagonal[c]) / fv->cell_volume[c];
  }
  h.update_ghost_values();
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
  {
    const auto& face = fv->faces[f];
    if (face.kind == FaceKind::ghost_boundary)
      continue;
    if (face.N == invalid_cell && face.patch != outlet)
    {
      F_star[f] = face.S * boundary_u[f]; // inlet: the inflow; walls: zero
      continue;
    }
    const unsigned int P = face.P, N = face.N;
    Tensor<1, dim> h_by_a, m; // (h / a*)_f; from the interpolation point to r_f
    std::array<Tensor<1, dim>, dim> grad;
    if (!consistent) // classic: F*_f = S_f . ((h + c0 u^o) / a)_f
    {
      const auto h_by_a_cell = [&](const unsigned int c)
      {
        Tensor<1, dim> value = h[c];
        for (unsigned int j = 0; j < dim; ++j)
          value[j] += c0_cell_ghosted.local_element(c) * u_levels.o.components[j].local_element(c);
        return value / a.local_element(c);
      };
      h_by_a =
        N == invalid_cell ? h_by_a_cell(P) : face.interpolate(h_by_a_cell(P), h_by_a_cell(N));
      m = face.centre - (N == invalid_cell ? fv->centroid[P]
                                           : face.interpolate(fv->centroid[P], fv->centroid[N]));
      for (unsigned int j = 0; j < dim; ++j)
        h_by_a[j] +=
          m * (N == invalid_cell ? grad_u[j][P] : face.interpolate(grad_u[j][P], grad_u[j][N]));
      F_star[f] = face.S * h_by_a;
      continue;
    }
    if (N == invalid_cell)
    {
      h_by_a = h[P] / a_star.local_element(P);
      m = face.centre - fv->centroid[P];
      for (unsigned int j = 0; j < dim; ++j)
        grad[j] = grad_u[j][P];
    }
    else
    {
      h_by_a =
        face.w * h[P] / a_star.local_element(P) + (1 - face.w) * h[N] / a_star.local_element(N);
      m = face.centre - face.interpolate(fv->centroid[P], fv->centroid[N]);
      for (unsigned int j = 0; j < dim; ++j)
        grad[j] = face.interpolate(grad_u[j][P], grad_u[j][N]);
    }
    for (unsigned int j = 0; j < dim; ++j)
      h_by_a[j] += m * grad[j];
    // Steady: c1_f = c0_f, c2 = 0; transient: BDF2 as in the cell equation.
    double c0, c1, c2;
    time_coefficients(c0, c1, c2);
    const double c1_f = dt > 0 ? c1 : c0_face[f];
    F_star[f] =
      gamma_p[f] * (c1_f * F_levels.o[f] - c2 * F_levels.oo[f] + a_star_f[f] * (face.S * h_by_a));
  }
}

// @sect4{CylinderFlow::solve_pressure}
// The pressure equation with the source -sum_f F*_f (F* leaves P and enters N) and the outlet's
// p_b through Eq. 23. The non-orthogonal part of Eq. 19 is explicit, with the gradient of the
// previous solve: solve, update grad p, solve again (two "non-orthogonal correctors", as in the
// library). They matter: the fluxes of the correction below must satisfy continuity with the
// full Eq. 19, not only with its orthogonal part, and the correction is computed with the grad p
// of the last solve but one, so each repetition shrinks the mismatch by a factor of about
// |k| / d_fn.
void CylinderFlow::solve_pressure()
{
  for (unsigned int k = 0; k <= 2; ++k)
  {
    pressure_rhs = 0;
    for (unsigned int f = 0; f < fv->faces.size(); ++f)
    {
      const auto& face = fv->faces[f];
      if (face.kind == FaceKind::ghost_boundary)
        continue;
      pressure_rhs.local_element(face.P) -= F_star[f];
      if (face.kind == FaceKind::interior)
        pressure_rhs.local_element(face.N) += F_star[f];
      if (face.N == invalid_cell && face.patch == outlet)
        pressure_rhs.local_element(face.P) += gamma_p[f] * face.area / face.d_n * boundary_p[f];
    }
    operators->laplacian.add_correction(gamma_p, pressure_bc, grad_p, pressure_rhs);
    pressure_solver->solve(pressure_matrix, p, pressure_rhs, "pressure");
    if (k < 2)
    {
      update_pressure_boundary_values();
      update_pressure_gradient();
    }
  }
}

// @sect4{CylinderFlow::correct_fluxes_and_velocity}
// F_f = F*_f - Gamma_f S_f (n . grad p)_f, with the same Eq. 19 (Laplacian::normal_gradient) and
// the same grad p as in the last pressure solve: these fluxes satisfy the discrete continuity
// equation to the pressure solver's tolerance. They are the fluxes the next momentum assembly
// convects with. The cell velocity follows from the cell momentum equation with the new pressure
// gradient: u_P = (h_P + B_time_P / V_P - (grad p)_P) / a_P. It is not exactly divergence free;
// the fluxes are.
void CylinderFlow::correct_fluxes_and_velocity()
{
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
    if (fv->faces[f].kind != FaceKind::ghost_boundary)
      F[f] = gamma_p[f] == 0
               ? F_star[f]
               : F_star[f] - gamma_p[f] * fv->faces[f].area *
                               operators->laplacian.normal_gradient(f, p, grad_p, pressure_bc);
  update_pressure_boundary_values();
  update_pressure_gradient();
  for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
    for (unsigned int j = 0; j < dim; ++j)
      u.components[j].local_element(c) =
        (h.components[j].local_element(c) + B_time[j][c] / fv->cell_volume[c] - grad_p[c][j]) /
        a.local_element(c);
  u.update_ghost_values();
}

// @sect4{CylinderFlow::solve_time_step}
// One PISO step, in the order of the header comment. Returns the relative change
// max|u - u^o| / max|u| of the step (max over cells of the Euclidean norm).
double CylinderFlow::solve_time_step()
{
  if (step > 0)
  {
    u_levels.shift(u); // u^oo <- u^o <- u
    u_levels.for_each([](auto& level) { level.update_ghost_values(); });
    F_levels.shift(F);
  }
  ++step;
  update_velocity_boundary_values();
  update_velocity_gradients();
  update_pressure_boundary_values();
  update_pressure_gradient();
  assemble_momentum();
  solve_momentum();
  assemble_pressure_equation();
  for (unsigned int corrector = 0; corrector < 2; ++corrector)
  {
    compute_predicted_fluxes();
    solve_pressure();
    correct_fluxes_and_velocity();
  }
  update_velocity_boundary_values();
  update_velocity_gradients();

  double max_du = 0, max_u = 0;
  for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
  {
    max_du = std::max(max_du, (u[c] - u_levels.o[c]).norm());
    max_u = std::max(max_u, u[c].norm());
  }
  max_du = Utilities::MPI::max(max_du, mpi_communicator);
  max_u = Utilities::MPI::max(max_u, mpi_communicator);
  if (!std::isfinite(max_du))
    throw std::runtime_error("the velocity is not finite at step " + std::to_string(step));
  return max_du / max_u;
}

// @sect4{CylinderFlow::solve}
// Pseudo time steps until the relative change per step is below 1e-9. The step-to-step change
// decays geometrically, so the iteration error left is about 1e-9 / (1 - rate) relative: far
// below the 5 digits printed.
void CylinderFlow::solve()
{
  for (unsigned int k = 1; k <= 5000; ++k)
  {
    const double change = solve_time_step();
    if (k % 100 == 0)
      pcout << "    step " << k << ": relative change " << change << std::endl;
    if (change < 1e-9)
      return;
  }
  throw std::runtime_error("the steady iteration did not converge");
}

// @sect4{CylinderFlow::force}
// The force of the fluid on the cylinder and the flag, per unit depth [N/m]: over their faces,
// rho S_f (p_b n_f - nu (n . grad u)_b), the pressure and the viscous traction, n_f out of the
// fluid, (n . grad u)_b by Eq. 23. (On a no-slip wall of an incompressible flow n . (grad u)^T
// = 0, so nu (n . grad u) is the full viscous traction.) Drag is its x component, lift its y
// component.
Tensor<1, dim> CylinderFlow::force() const
{
  Tensor<1, dim> force;
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
  {
    const auto& face = fv->faces[f];
    if (face.kind != FaceKind::boundary || (face.patch != cylinder && face.patch != flag))
      continue;
    Tensor<1, dim> du_dn = boundary_u[f] - u[face.P];
    for (unsigned int j = 0; j < dim; ++j)
      du_dn[j] -= face.k_P * grad_u[j][face.P];
    du_dn /= face.d_n;
    force += rho * face.area * (boundary_p[f] * face.n - nu * du_dn);
  }
  return Utilities::MPI::sum(force, mpi_communicator);
}

// @sect4{CylinderFlow::output_results}
// u, the pressure in Pa (rho p) and the vorticity dv/dx - du/dy [1/s] to
// cylinder-<100 alpha>_0000.pvtu, cylinder-classic-<100 alpha>_0000.pvtu (steady) or
// cylinder-transient_0000.pvtu.
void CylinderFlow::output_results() const
{
  OutputFields<dim> fields(*fv);
  fields.add_vector("u", [&](const unsigned int c) { return u[c]; });
  fields.add("p", [&](const unsigned int c) { return rho * p.local_element(c); });
  fields.add("vorticity", [&](const unsigned int c) { return grad_u[1][c][0] - grad_u[0][c][1]; });
  const std::string name = dt > 0 ? "cylinder-transient"
                                  : std::string(consistent ? "cylinder-" : "cylinder-classic-") +
                                      std::to_string(static_cast<int>(100 * alpha + 0.5));
  VtuOutput<dim>(*fv, ".", name).write(fields, 0, 0.0);
}

// @sect4{CylinderFlow::run}
void CylinderFlow::run(const unsigned int n_time_steps, const unsigned int interval,
                       std::vector<std::array<double, 3>>* history)
{
  make_grid();
  setup_system();
  if (dt == 0)
  {
    pcout << "  " << fv->n_global_cells() << " cells, steady, alpha = " << alpha << std::endl;
    solve();
    const Tensor<1, dim> f = force();
    pcout << "  steady after " << step << " PISO steps: drag " << f[0] << " N/m, lift " << f[1]
          << " N/m" << std::endl;
  }
  else
  {
    pcout << "  " << fv->n_global_cells() << " cells, dt = " << dt << " s" << std::endl;
    for (unsigned int k = 1; k <= n_time_steps; ++k)
    {
      solve_time_step();
      if (k % interval == 0 && history != nullptr)
      {
        const Tensor<1, dim> f = force();
        history->push_back(std::array<double, 3>{{k * dt, f[0], f[1]}});
        pcout << "  t = " << k * dt << " s: drag " << f[0] << " N/m, lift " << f[1] << " N/m"
              << std::endl;
      }
    }
  }
  output_results();
}

// @sect3{The same case with fvfsi::FluidSolver}
// The library solver on the same mesh, with the parameters a .prm file would set (as in
// prm/turek_hron_cfd2.prm and turek_hron_cfd3.prm, with this program's U). Its solve_time_step()
// is solve_time_step() above (source/fluid/fluid_solver.cc, source/fluid/fluid_piso.templates.h: the same
// steps by the same names), plus what this case does not need (symmetry planes, moving meshes,
// outer correctors, 3D). Steady (dt = 0): returns the converged force and sets n_steps.
// Transient: n_steps time steps, the force every `interval` steps into `history`.
Tensor<1, dim> library_force(const unsigned int n, const double U, const double alpha,
                             const double dt, unsigned int& n_steps,
                             const unsigned int interval = 1,
                             std::vector<std::array<double, 3>>* history = nullptr)
{
  parallel::distributed::Triangulation<dim> triangulation(MPI_COMM_WORLD);
  MeshParameters mesh;
  mesh.generator = "fvfsi_turek_hron_channel";
  mesh.generator_arguments = std::to_string(n);
  mesh.n_global_refinements = 0;
  mesh.patch_names = {
    {inlet, "inlet"}, {outlet, "outlet"}, {walls, "walls"}, {cylinder, "cylinder"}, {flag, "flag"}};
  make_mesh(mesh, triangulation);
  const FVGeometry<dim> fv(triangulation);

  FluidParameters prm;
  prm.rho = rho;
  prm.nu = nu;
  prm.transient = dt > 0;
  prm.momentum_relaxation = alpha;
  prm.steady_tolerance = 1e-9;
  prm.convection = FluidParameters::Convection::linear_upwind;
  prm.velocity_inlet = "inlet: 1.5*" + Utilities::to_string(U) + "*4*y*(0.41-y)/0.41^2; 0";
  prm.outlet = "outlet: 0";
  prm.wall = "walls, cylinder, flag";
  // FluidParameters::declare() sets these defaults for .prm files; set them here.
  prm.momentum_solver.method = LinearSolverParameters::Method::gmres;
  prm.momentum_solver.preconditioner = LinearSolverParameters::Preconditioner::ilu;
  prm.momentum_solver.reduction = 1e-3;
  prm.momentum_solver.absolute_tolerance = 1e-15;
  prm.pressure_solver.reduction = 1e-6;
  prm.pressure_solver.absolute_tolerance = 1e-15;
  // The library's default linearises each BDF2 step about the extrapolated state 2 u^n - u^(n-1),
  // 2 F^n - F^(n-1) (second order in time with one outer loop, tests/fluid/fluid_taylor_green);
  // this program linearises about u^n, F^n, as OpenFOAM's PISO does. Compare like with like:
  prm.flux_extrapolation = false;
  // ... and with this program's two pressure correctors in every step (the library adds
  // correctors where two leave the coupling unconverged, e.g. at large Courant numbers).
  prm.max_pressure_correctors = prm.pressure_correctors;

  TimeControl clock(dt > 0 ? dt : 1.0, dt * n_steps); // the scene's clock (steady: unused)
  FluidSolver<dim> fluid(fv, mesh, prm, clock);
  const auto force = [&]() { return fluid.patch_force(cylinder) + fluid.patch_force(flag); };
  if (dt == 0)
    n_steps = fluid.solve_steady();
  else
    for (unsigned int k = 1; k <= n_steps; ++k)
    {
      clock.advance();
      fluid.solve_time_step();
      if (k % interval == 0 && history != nullptr)
      {
        const Tensor<1, dim> f = force();
        history->push_back(std::array<double, 3>{{clock.time(), f[0], f[1]}});
        const double courant = fluid.courant_number(); // collective
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::cout << "  fvfsi: t = " << clock.time() << " s, Courant number " << courant
                    << std::endl;
      }
    }
  return force();
}

// @sect3{The main program}
// The written-out solver with the consistent and the classic face flux, each at two relaxation
// factors, then the library. The table (written to the file `output` for the test) has drag and
// lift to 5 significant digits, and their relative differences from the first row, which are
// printed only above 1e-5 (below that they are iteration error, different on another machine).
std::string row(const std::string& name, const double alpha, const Tensor<1, dim>& force,
                const Tensor<1, dim>& first)
{
  const auto difference = [](const double x, const double x0)
  {
    char text[32];
    const double d = std::abs(x - x0) / std::abs(x0);
    if (d < 1e-5)
      std::snprintf(text, sizeof(text), "%9s", "< 1e-5");
    else
      std::snprintf(text, sizeof(text), "%9.1e", d);
    return std::string(text);
  };
  char line[160], alpha_text[16] = "    -";
  if (alpha > 0)
    std::snprintf(alpha_text, sizeof(alpha_text), "%5.2f", alpha);
  std::snprintf(line, sizeof(line), "%-20s %s %10.5g %10.5g %s %s\n", name.c_str(), alpha_text,
                force[0], force[1], difference(force[0], first[0]).c_str(),
                difference(force[1], first[1]).c_str());
  return line;
}

void run(const unsigned int n)
{
  ConditionalOStream pcout(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  std::ostringstream table;
  unsigned int n_cells = 0;
  Tensor<1, dim> first;
  table << "solver               alpha drag [N/m] lift [N/m] (relative difference from row 1)\n";
  for (const bool consistent : {true, false})
    for (const double alpha : {0.95, 0.5})
    {
      pcout << "step-3 PISO, " << (consistent ? "consistent" : "classic")
            << " Rhie-Chow flux, n = " << n << ":" << std::endl;
      CylinderFlow flow(n, 0.2, alpha, consistent);
      flow.run();
      n_cells = flow.n_cells();
      if (consistent && alpha == 0.95)
        first = flow.force();
      table << row(consistent ? "step-3" : "step-3, classic R-C", alpha, flow.force(), first);
    }
  pcout << "fvfsi::FluidSolver, n = " << n << ":" << std::endl;
  unsigned int n_steps = 0;
  const Tensor<1, dim> f = library_force(n, 0.2, 0.95, 0.0, n_steps);
  pcout << "  steady after " << n_steps << " PISO steps: drag " << f[0] << " N/m, lift " << f[1]
        << " N/m" << std::endl;
  table << row("fvfsi::FluidSolver", 0.95, f, first);
  table << row("Turek-Hron CFD1", 0, Tensor<1, dim>({14.29, 1.119}), first);

  // Re = 100 (U = 1 m/s), time accurate: the fluid at rest, the inflow switched on at t = 0, and
  // 20 PISO steps of dt = 5 ms (max Courant number dt sum_f |F_f| / (2 V_P) 0.8 to 0.9). In the first steps the
  // pressure accelerates the whole channel at once (the drag is large); then the boundary layers
  // and the wake grow. Written-out and library solver side by side.
  const double dt = 0.005;
  const unsigned int n_time_steps = 20, interval = 5;
  std::vector<std::array<double, 3>> history, library_history;
  pcout << "step-3 PISO, Re = 100, transient:" << std::endl;
  CylinderFlow transient(n, 1.0, 0.95, true, dt);
  transient.run(n_time_steps, interval, &history);
  unsigned int n_library_steps = n_time_steps;
  library_force(n, 1.0, 0.95, dt, n_library_steps, interval, &library_history);
  table << "\nRe = 100 from rest, BDF2, dt = " << dt << " s\n"
        << "t [s]     step-3: drag [N/m] lift [N/m]  fvfsi::FluidSolver: drag [N/m] lift [N/m]\n";
  for (unsigned int i = 0; i < history.size(); ++i)
  {
    char line[160];
    std::snprintf(line, sizeof(line), "%5.3f %18.5g %10.5g %31.5g %10.5g\n", history[i][0],
                  history[i][1], history[i][2], library_history[i][1], library_history[i][2]);
    table << line;
  }

  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {
    const std::string text = "Re = 20, " + std::to_string(n_cells) + " cells\n" + table.str();
    std::cout << text;
    std::ofstream("output") << text; // the file the test suite compares
  }
}
} // namespace Step3

int main(int argc, char* argv[])
{
  return fvfsi_tutorial::main_program(argc, argv, "step-3", []() { Step3::run(8); });
}
