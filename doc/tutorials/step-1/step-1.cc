/* ---------------------------------------------------------------------
 * fvfsi tutorial step-1: the cell-centred finite-volume Poisson solver, piece by piece.
 *
 * We solve  -laplace(phi) = s  on the unit square, with phi = exp(x) sin(pi y), on a randomly
 * distorted, distributed mesh, using the finite-volume (FV) building blocks of fvfsi: the FV
 * geometry, the weighted-least-squares vertex values, the vertex-based Gauss-Green gradient and
 * the Laplacian with deferred non-orthogonal correction. These are the discretisation of
 * Tukovic, Karac, Cardiff, Jasak, Ivankovic, "OpenFOAM finite volume solver for fluid-solid
 * interaction" (sections 3.1-3.2, Appendices A and B; equation numbers below refer to it).
 * The same Laplacian is used by every equation of the FSI method (solid momentum, fluid pressure
 * and viscous terms, mesh motion), so this is the place to learn it.
 * --------------------------------------------------------------------- */

// @sect3{Include files}
// deal.II provides the distributed mesh (p4est), parallel vectors, Trilinos matrices and the
// table class; fvfsi provides the FV pieces. Each fvfsi header says which equation it implements.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include "../tutorial.h"
#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/gradients.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/linear_solver.h>
#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_builder.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

namespace Step1
{
using namespace dealii;
using namespace fvfsi;

// @sect3{The manufactured solution}
// phi = exp(x) sin(pi y) is not a polynomial, so no part of the scheme is exact for it and the
// error shows the true order of the method. Its source is s = -laplace(phi) = (pi^2 - 1) phi.
// The gradient gives the Neumann data n . grad(phi) on the right side of the square.
template <int dim>
class ExactSolution : public Function<dim>
{
public:
  double value(const Point<dim>& p, const unsigned int = 0) const override
  {
    return std::exp(p[0]) * std::sin(numbers::PI * p[1]);
  }
  Tensor<1, dim> gradient(const Point<dim>& p, const unsigned int = 0) const override
  {
    Tensor<1, dim> g;
    g[0] = std::exp(p[0]) * std::sin(numbers::PI * p[1]);
    g[1] = numbers::PI * std::exp(p[0]) * std::cos(numbers::PI * p[1]);
    return g;
  }
  double source(const Point<dim>& p) const { return (numbers::PI * numbers::PI - 1) * value(p); }
};

// @sect3{The PoissonFV class}
// The structure is that of deal.II's step-40. The FV objects depend on the mesh, so they live in
// unique_ptrs that make_grid() recreates on every refinement cycle. Vectors are fvfsi::CellVector
// (a LinearAlgebra::distributed::Vector): one value per locally owned cell, then one per ghost
// cell, the ghosts filled from their owners by update_ghost_values().
template <int dim>
class PoissonFV
{
public:
  PoissonFV();
  void run(const unsigned int n_cycles);

private:
  void make_grid(const unsigned int n_refinements);
  void setup_system();
  void assemble_system();
  void solve();
  double max_error() const;
  void output_results(const unsigned int cycle) const;

  MPI_Comm mpi_communicator;
  ConditionalOStream pcout;
  parallel::distributed::Triangulation<dim> triangulation;

  std::unique_ptr<FVGeometry<dim>> fv;
  std::unique_ptr<VertexInterpolation<dim>> vertex_interpolation;
  std::unique_ptr<GaussGreenGradient<dim>> gauss_green;
  std::unique_ptr<Laplacian<dim>> laplacian;
  ExactSolution<dim> exact;

  ScalarBoundaryConditions<dim> bc;
  FaceVector gamma; // diffusivity per face
  TrilinosWrappers::SparseMatrix system_matrix;
  CellVector phi, rhs_fixed;
  CellGradient<dim> grad;         // (grad phi)_P, owned + ghost cells
  std::vector<double> vertex_phi; // phi at the mesh vertices
  unsigned int n_corrections = 0, n_cg = 0;
  double uncorrected_error = 0;
  ConvergenceTable table;
};

template <int dim>
PoissonFV<dim>::PoissonFV()
    : mpi_communicator(MPI_COMM_WORLD),
      pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0),
      triangulation(mpi_communicator)
{
}

// @sect4{PoissonFV::make_grid}
// make_mesh() builds the coarse 8x8 square in a serial triangulation, moves every interior vertex
// by 25% of its shortest adjacent edge in a random direction (the same on every rank), copies it
// into the p4est triangulation and refines it. Refinement subdivides the distorted cells with
// straight lines, so the finer meshes stay non-orthogonal: the largest angle between the face
// normal n_f and the line d_f joining the cell centres does not go to zero (31 to 41 degrees on
// the three meshes here), and a scheme that ignores it is not consistent.
//
// FVGeometry then computes everything the FV method needs from the vertex coordinates alone
// (paper section 3.1, Fig. 2):
// - per cell P: the centroid r_P and the volume V_P. The cell is cut into pyramids from its
//   vertex average to the pieces of its faces (in 2D the faces are segments; in 3D each quad
//   face is cut into 4 triangles tau about its vertex average, Appendix A). Summed, this is
//   Eq. 38, V_P = 1/dim sum_tau n_tau . r_tau S_tau (1/3 in 3D), and r_P is the volume-weighted
//   mean of the pyramid centroids.
// - per face f: the centre r_f, the area vector S_f n_f (pointing out of P), d_f = r_N - r_P,
//   d_fn = n_f . d_f (Eq. 20) and the correction vectors k_P = (I - n n).(r_f - r_P) (Eq. 21)
//   and k_N = (I - n n).(r_N - r_f) (Eq. 22). On an orthogonal mesh k_P = k_N = 0.
// The geometry is stored, never recomputed inside face loops; a moving mesh calls fv->reinit().
//
// In parallel, each rank owns some cells and sees one layer of ghost cells around them. The cells
// are numbered by an FE_DGQ(0) DoFHandler (one dof per cell), local index c < n_owned_cells() for
// owned cells, then the ghosts. Each face is stored once per rank with a FaceKind: `interior`
// (both cells owned), `processor` (owned P, ghost N), `boundary`, and `ghost_boundary` (a
// boundary face of a ghost cell, needed only for vertex stencils). A processor face exists on
// both ranks; `counted_here` is true on exactly one of them (the lower rank), so global sums
// over faces, like the face count below, count each face once.
template <int dim>
void PoissonFV<dim>::make_grid(const unsigned int n_refinements)
{
  laplacian.reset(); // the FV objects refer to the old mesh: release them first
  vertex_interpolation.reset();
  gauss_green.reset();
  fv.reset();
  triangulation.clear();

  MeshParameters mesh;
  mesh.generator = "subdivided_hyper_cube";
  mesh.generator_arguments = "8: 0: 1: true"; // 8x8 cells, [0,1]^2, boundary ids 0..3
  mesh.n_global_refinements = n_refinements;
  mesh.distortion = 0.25;
  mesh.distort_coarse_mesh = true;
  make_mesh(mesh, triangulation);

  fv = std::make_unique<FVGeometry<dim>>(triangulation);

  // Three checks of the geometry: sum V_P is the area of the square (the decomposition is exact
  // for straight-sided cells); the number of faces; the largest angle between n_f and d_f.
  double volume = 0, max_angle = 0;
  unsigned int n_faces = 0;
  for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
    volume += fv->cell_volume[c];
  for (const auto& face : fv->faces)
    if (face.counted_here)
    {
      ++n_faces;
      max_angle = std::max(max_angle, std::acos(face.d_n / face.d.norm()) * 180 / numbers::PI);
    }
  volume = Utilities::MPI::sum(volume, mpi_communicator);
  n_faces = Utilities::MPI::sum(n_faces, mpi_communicator);
  max_angle = Utilities::MPI::max(max_angle, mpi_communicator);
  pcout << "  " << fv->n_global_cells() << " cells, " << n_faces << " faces, sum V_P = " << volume
        << ", max non-orthogonality " << max_angle << " degrees" << std::endl;
  table.add_value("cells", fv->n_global_cells());
  table.add_value("faces", n_faces);
  table.add_value("max angle", max_angle);
}

// @sect4{PoissonFV::setup_system}
// Boundary conditions are given per patch (boundary id) and stored per face: phi_b on Dirichlet
// faces, n . grad(phi) on Neumann faces (here the right side, id 1). The matrix gets the
// cell + face-neighbour sparsity; its rows are the owned cells of this rank.
//
// VertexInterpolation prepares the vertex values of Appendix B. Around each vertex phi is fitted
// by a linear function phi(r) = phi_0 + C . (r - r_0) (Eq. 40) to the values of all cells that
// share the vertex (and of the boundary faces that share it), with weights w_j = 1/|r_j - x_v|^2,
// the weighted means r_0, phi_0 of Eq. 41 and C from the normal equations of Eq. 42. The fit is
// exact for linear fields, which a simple average is not on a distorted mesh. Since it is linear
// in the data, the constructor stores one coefficient per stencil entry, phi_v = sum_j a_j phi_j,
// and each interpolation is a sparse product. In parallel the paper (Appendix B) needs an extra
// exchange because its stencils reach beyond the face neighbours; here the p4est ghost layer
// holds every cell that shares a *vertex* with an owned cell, so every stencil is complete on
// every rank that needs it, and the stencils are summed in global cell order so that two ranks
// get bit-identical values at a shared vertex.
template <int dim>
void PoissonFV<dim>::setup_system()
{
  vertex_interpolation = std::make_unique<VertexInterpolation<dim>>(*fv);
  gauss_green = std::make_unique<GaussGreenGradient<dim>>(*fv);
  laplacian = std::make_unique<Laplacian<dim>>(*fv);

  bc = ScalarBoundaryConditions<dim>();
  for (const types::boundary_id id : triangulation.get_boundary_ids())
    bc.patch_type[id] = (id == 1 ? BoundaryType::neumann : BoundaryType::dirichlet);
  bc.value.assign(fv->faces.size(), 0.0);
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
  {
    const auto& face = fv->faces[f];
    if (face.N != invalid_cell) // not a boundary face
      continue;
    bc.value[f] = bc.type(face) == BoundaryType::dirichlet ? exact.value(face.centre)
                                                           : face.n * exact.gradient(face.centre);
  }
  gamma.assign(fv->faces.size(), 1.0);

  laplacian->reinit_matrix(system_matrix);
  phi = fv->make_cell_vector();
  rhs_fixed = fv->make_cell_vector();
  // A zero gradient: the first solve has no correction. Its ghost entries are read at processor
  // faces, so they are marked valid (imported) like those of every field read across ranks.
  grad = CellGradient<dim>(*fv);
  grad.update_ghost_values();
}

// @sect4{PoissonFV::assemble_system}
// Integrate -div(grad phi) = s over cell P and apply Gauss' theorem and the midpoint rule:
//   - sum_f S_f n_f . (grad phi)_f = s_P V_P.
// The face normal gradient is Eq. 19 (with the sign of the correction fixed, see laplacian.h):
//   n_f . (grad phi)_f = (phi_N - phi_P)/d_fn - (k_N . (grad phi)_N + k_P . (grad phi)_P)/d_fn.
// It is exact for linear phi: phi_N - phi_P = grad(phi) . d_f, and d_f = d_fn n_f + k_P + k_N.
// The first term goes into the matrix: a_N = -S_f/d_fn and a_P = sum_f S_f/d_fn (Eqs 26-27
// without the time term), a symmetric, weakly diagonally dominant M-matrix. A Dirichlet face adds
// S_b/d_bn to a_P and S_b/d_bn phi_b to the right-hand side (Eq. 23); a Neumann face adds the
// given flux S_b g_b. The second term, the non-orthogonal correction, is added in solve().
//
// Who assembles what: an `interior` face adds to the rows of P and N; a `processor` face only to
// the row of its owned cell P, because the rank that owns N meets the same face (with P and N
// swapped) and adds that row itself, with the same coefficient computed from the same vertices.
template <int dim>
void PoissonFV<dim>::assemble_system()
{
  for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
    rhs_fixed.local_element(c) = exact.source(fv->centroid[c]) * fv->cell_volume[c];
  laplacian->assemble(gamma, bc, system_matrix, rhs_fixed);
  system_matrix.compress(VectorOperation::add);
}

// @sect4{PoissonFV::solve}
// Deferred correction: the correction term of Eq. 19 uses cell gradients of the unknown phi, so
// it is evaluated with the latest solution and moved to the right-hand side (Eq. 28). Each
// iteration
//   1. adds the correction -S_f (k_N . grad_N + k_P . grad_P)/d_fn of every face to the rhs,
//   2. solves the fixed matrix (CG with algebraic multigrid, Trilinos ML), from the last phi,
//   3. computes phi at the boundary faces (phi_b, or extrapolated on Neumann faces) and at the
//      vertices by least squares (Appendix B),
//   4. computes the vertex-based Gauss-Green gradient (Eq. 37):
//        (grad phi)_P = 1/V_P sum_tau n_tau phi_tau S_tau
//      over the face pieces tau of cell P, phi_tau the mean of the piece's vertex values. It is
//      exact for linear fields on any mesh, hence second order "irrespective of the mesh
//      quality". FVGeometry stores it as one weight vector per face vertex.
// until phi changes by less than 1e-10 relative. The explicit correction is, relative to the
// implicit two-point flux, of the size of tan(angle between n_f and d_f); for the moderate angles
// of this mesh the fixed-point iteration converges in 12 to 20 iterations, on very skewed meshes
// it slows down or diverges. The paper notes that each linear solve need not be accurate; we
// reduce the residual by 1e-8 anyway so that the error after the first solve, the uncorrected
// solution we report, does not depend on the number of ranks. The solver copies the solution's
// ghost values; GaussGreenGradient::compute() updates grad's ghosts, which the next correction needs at
// processor faces.
template <int dim>
void PoissonFV<dim>::solve()
{
  LinearSolverParameters parameters;
  parameters.method = LinearSolverParameters::Method::cg;
  parameters.preconditioner = LinearSolverParameters::Preconditioner::amg;
  parameters.reduction = 1e-8;
  LinearSolver solver(parameters);
  solver.initialize(system_matrix);

  CellVector rhs = fv->make_cell_vector(), phi_old = fv->make_cell_vector();
  n_cg = 0;
  for (n_corrections = 1; n_corrections <= 200; ++n_corrections)
  {
    rhs = rhs_fixed;
    laplacian->add_correction(gamma, bc, grad, rhs);
    phi_old = phi;
    n_cg += solver.solve(system_matrix, phi, rhs, "phi");
    if (n_corrections == 1)
      uncorrected_error = max_error();

    vertex_interpolation->interpolate(phi, laplacian->boundary_values(phi, grad, bc), vertex_phi);
    gauss_green->compute(vertex_phi, grad);

    phi_old -= phi;
    if (phi_old.linfty_norm() < 1e-10 * phi.linfty_norm())
      return;
  }
  pcout << "  warning: deferred correction did not converge" << std::endl;
}

// @sect4{PoissonFV::max_error}
// The error at the cell centroids, where the FV value phi_P is a second-order approximation of
// phi(r_P). Each rank looks at its owned cells; the maximum is then taken over all ranks.
template <int dim>
double PoissonFV<dim>::max_error() const
{
  double error = 0;
  for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
    error = std::max(error, std::abs(phi.local_element(c) - exact.value(fv->centroid[c])));
  return Utilities::MPI::max(error, mpi_communicator);
}

// @sect4{PoissonFV::output_results}
// Cell fields go to one .vtu file per rank, a .pvtu record and a .pvd series (VtuOutput), here
// solution-<cycle>_0000.pvtu. OutputFields fills each field in the owned cells and updates its
// ghost values, which DataOut reads.
template <int dim>
void PoissonFV<dim>::output_results(const unsigned int cycle) const
{
  OutputFields<dim> fields(*fv);
  fields.add("phi", [&](const unsigned int c) { return phi.local_element(c); });
  fields.add("error", [&](const unsigned int c)
             { return phi.local_element(c) - exact.value(fv->centroid[c]); });
  VtuOutput<dim>(*fv, ".", "solution-" + std::to_string(cycle)).write(fields, 0, 0.0);
}

// @sect4{PoissonFV::run}
// The 8x8 mesh refined 0, 1, ..., n_cycles - 1 times (3 cycles unless the command line says
// otherwise). The table lists the mesh, the max error of the first solve (no non-orthogonal
// correction: grad = 0) and of the converged deferred correction, each with its observed order
// log(e_old/e)/log(h_old/h), h ~ (1/cells)^(1/dim). The corrected scheme converges with order 2;
// the uncorrected one is not consistent on this mesh and its error does not decrease at all.
template <int dim>
void PoissonFV<dim>::run(const unsigned int n_cycles)
{
  pcout << "Running with " << Utilities::MPI::n_mpi_processes(mpi_communicator) << " MPI rank(s)"
        << std::endl;
  for (unsigned int cycle = 0; cycle < n_cycles; ++cycle)
  {
    pcout << "Cycle " << cycle << ':' << std::endl;
    make_grid(cycle);
    setup_system();
    assemble_system();
    solve();
    const double error = max_error();
    pcout << "  " << n_corrections << " correction iterations, " << n_cg
          << " CG iterations, max error " << error << std::endl;
    table.add_value("uncorrected", uncorrected_error);
    table.add_value("max error", error);
    output_results(cycle);
  }

  table.set_precision("max angle", 2);
  for (const std::string key : {"uncorrected", "max error"})
  {
    table.set_scientific(key, true);
    table.set_precision(key, 3);
    table.evaluate_convergence_rates(key, "cells", ConvergenceTable::reduction_rate_log2, dim);
  }
  fvfsi_tutorial::write_table(table, mpi_communicator);
}
} // namespace Step1

// @sect3{The main function}
// MPI_InitFinalize also initialises p4est and Trilinos. `step-1 N` runs N refinement cycles.
// Errors end the program with a message.
int main(int argc, char* argv[])
{
  return fvfsi_tutorial::main_program(argc, argv, "step-1",
                                      [&]()
                                      {
                                        Step1::PoissonFV<2> problem;
                                        problem.run(argc > 1 ? std::stoi(argv[1]) : 3);
                                      });
}
