#pragma once
// The solid solver (paper sections 2.2, 3.2, 3.3): total Lagrangian, displacement u at the cell
// centres of the (never moving) reference mesh, momentum Eq. 8 discretised as Eq. 16 and solved
// segregated, component by component (Eq. 25):
//
//   A_j du_j = R_j(u*),   u_j <- u*_j + du_j,
//
// where R is the full residual of Eq. 16 (inertia by BDF2, Eqs 17-18; face forces n.(Sigma.F^T) S_f
// from the face gradient; body force) evaluated at the current iterate u*, and A_j the implicit
// part: the Laplacian with K = 2 mu + lambda and the orthogonal face coefficients of Eqs 26-27,
// plus the BDF2 mass term. At convergence of these outer iterations u solves Eq. 16 exactly; each
// linear solve only needs about one order of residual reduction (section 3.3).
//
// With `Solid/Hessian correction` (present variant; an extension of the paper) the vertex values
// and the boundary values extrapolated at traction and symmetry faces also carry their
// second-order Taylor terms, with per-cell Hessians (QuadraticFit): without them the max
// displacement error converges like h^2 log(1/h) where two traction boundaries meet (see
// solid_gradients.templates.h).
//
// The solver knows nothing about coupling: an external traction per boundary face can be set
// (set_external_traction) and the displacement read (displacement, boundary_displacement). It
// reads the scene's clock (TimeControl) and has the life cycle of every solver of a scene: the
// scene advances the clock, then begin_time_step(), solve_current_step() (repeatable, e.g. with
// new external tractions), end_time_step().
//
// The code is in three files: solid_solver.cc (set-up, time steps, outer iterations),
// solid_face_forces.templates.h (face gradients, boundary values, tractions, the residual) and
// solid_gradients.templates.h (the sweeps of boundary values, vertex values and gradients; the Hessian
// correction).

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <deal.II/lac/la_parallel_block_vector.h>

#include <fvfsi/base/time_control.h>
#include <fvfsi/base/time_levels.h>
#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/fv/gradients.h>
#include <fvfsi/fv/jacobian_solver.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/least_squares_model.h>
#include <fvfsi/fv/linear_solver.h>
#include <fvfsi/fv/point_probes.h>
#include <fvfsi/fv/probed_jacobian.h>
#include <fvfsi/fv/quadratic_fit.h>
#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/io/checkpoint.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_parameters.h>
#include <fvfsi/solid/constitutive.h>
#include <fvfsi/solid/solid_parameters.h>

#include <array>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace fvfsi
{
  template <int dim>
  class SolidSolver : public TimeSteppingSolver
  {
  public:
    /// `clock` is the scene's (a steady solid reads only its time, for the loads).
    SolidSolver(const FVGeometry<dim>& geometry, const MeshParameters& mesh_parameters,
                const SolidParameters& parameters, const TimeControl& clock);

    /// Move to the clock's time level: loads and boundary values at t, the matrices for its
    /// time step.
    void begin_time_step() override;
    /// Outer iterations from the current iterate until the relative change is below the outer
    /// tolerance (outer_iterations() tells how many). Repeatable (a coupling calls it again with
    /// new external tractions: each call starts from the last solution). Throws
    /// std::runtime_error naming the time step if the iterations diverge (non-finite values) or
    /// exceed the limit.
    void solve_current_step() override;
    /// Accept the step (transient: shift the time levels of u and v).
    void end_time_step() override;
    /// Outer iterations (Solid/Algorithm = coupled: Newton iterations) of the last
    /// solve_current_step().
    unsigned int outer_iterations() const { return last_outer_iterations; }
    /// Solid/Algorithm = coupled: Jacobian assemblies (Jacobian-free: base points) and residual
    /// evaluations so far.
    unsigned long jacobian_assemblies() const { return n_jacobians; }
    unsigned long residual_evaluations() const { return n_residuals; }
    /// ... and GMRES iterations of the Newton systems so far.
    unsigned long krylov_iterations() const { return n_krylov; }
    /// Solid/Algorithm = segregated: the linear solves of the component systems A_j so far and
    /// their Krylov iterations ({0, 0} for the coupled algorithm).
    std::pair<unsigned long, unsigned long> linear_solves_and_iterations() const;

    const LameParameters& material() const { return lame; }

    /// The smallest principal stretch of the face gradients at the end of any solve so far (St.
    /// Venant-Kirchhoff; 1 for the linear model). Below 1/sqrt(3) (solid_solver.cc) the model is
    /// past its limit point in compression.
    double least_stretch() const { return least_stretch_seen; }
    /// The largest max |u| / (body diameter + largest given displacement) after any solve so far:
    /// the divergence guard's ratio (Solid/Displacement bound).
    double largest_displacement_ratio() const { return largest_displacement_ratio_seen; }

    /// u at the cell centres [m] (ghost values up to date).
    const CellVectorField<dim>& displacement() const { return u; }
    /// grad u at cell c (G_ij = d u_j / d x_i).
    dealii::Tensor<2, dim> cell_gradient(unsigned int c) const;
    /// grad u at face f, as the chosen variant computes it for the face forces.
    dealii::Tensor<2, dim> face_gradient(unsigned int f) const;
    /// u on boundary face f [m] (fixed value, or extrapolated as in Eqs 23-24).
    const dealii::Tensor<1, dim>& boundary_displacement(unsigned int f) const
    {
      return boundary_u[f];
    }
    /// Cauchy stress at cell c and at face f [Pa].
    dealii::Tensor<2, dim> cell_stress(unsigned int c) const;
    dealii::Tensor<2, dim> face_stress(unsigned int f) const;
    /// The displacement [m] at probe point i: the linear reconstruction u_P + (x - r_P) . grad u
    /// in the cell that holds it (collective).
    dealii::Tensor<1, dim> probe_displacement(const PointProbes<dim>& probes, unsigned int i) const;
    /// Total force on a patch, sum over its faces of n.(Sigma.F^T) S_f [N] (2D: per unit depth).
    dealii::Tensor<1, dim> patch_force(unsigned int patch) const;

    /// u at the vertices of the locally owned cells [m], indexed like the triangulation's
    /// vertices (App. B reconstruction; other entries zero).
    std::vector<dealii::Tensor<1, dim>> vertex_displacements() const;

    /// Displacement u [m], Cauchy stress components sigma_ij [Pa] and the von Mises stress [Pa]
    /// (2D: of the in-plane stress) as output fields.
    void add_output_fields(OutputFields<dim>& fields) const;
    /// Save or load the state a run continues from between two time steps (the time levels of
    /// u and v, the boundary values and gradients the outer iterations start from); see
    /// io/checkpoint.h.
    void checkpoint(MeshArchive<dim>& archive);

    /// Cauchy traction [Pa] on the faces of `external traction` patches, indexed like
    /// FVGeometry::faces (entries of other faces are ignored).
    void set_external_traction(const std::vector<dealii::Tensor<1, dim>>& traction);

  private:
    using Type = SolidBoundaryCondition::Type;
    using Variant = SolidParameters::Variant;
    /// The outer iterations' unknowns (dim blocks of owned cells) for the acceleration.
    using BlockVector = dealii::LinearAlgebra::distributed::BlockVector<double>;

    void setup_boundary_conditions(const MeshParameters& mesh_parameters);
    void setup_hessian_correction();
    void assemble_matrices(double mass_coefficient);
    /// One outer iteration: residual, component solves, accelerated update; returns the relative
    /// change max |du| / max |u|.
    double outer_iteration(unsigned int k);
    /// Why the outer iterations may have diverged, for the message of a failed solve (collective):
    /// a boundary displacement gradient on traction faces far beyond any real strain says that
    /// the traction is too large for the boundary condition's iteration (Eq. 24). "" otherwise.
    std::string divergence_hint() const;
    /// The divergence guard (fv/divergence_guard.h): throws a DivergenceError if max |u| exceeds
    /// Displacement bound x (body diameter + largest given displacement so far).
    void check_bounded_displacement();
    double body_size = 0;          ///< the body's diameter [m]
    double given_displacement = 0; ///< the largest given boundary displacement so far [m]
    double largest_displacement_ratio_seen = 0; ///< largest_displacement_ratio()
    void update_gradients();
    /// `with_ghosts = false`: the present variant's gradients of owned cells only (the boundary
    /// sweeps read no other); the other variants always update the ghosts.
    void update_cell_gradients(bool with_ghosts = true);
    dealii::Tensor<2, dim> tangential_part(unsigned int f) const;
    void update_boundary_values();
    void find_constrained_vertices();
    void impose_vertex_constraints();
    void update_hessians();
    dealii::Tensor<1, dim> boundary_traction(unsigned int f, const dealii::Tensor<2, dim>& G) const;
    dealii::Tensor<1, dim> face_force_density(unsigned int f) const;
    void compute_residual(std::array<CellVector, dim>& residual) const;
    void shift_time_levels();

    // Solid/Algorithm = coupled (solid_coupled.templates.h): Newton's method on the unknowns x =
    // (u per cell; u_b per symmetry and traction face; g_n = n . grad u per traction face).
    using NewtonVector = dealii::LinearAlgebra::distributed::Vector<double>;
    void setup_coupled();
    void solve_coupled();
    /// Newton's method from x at the current load factor; false (with `failure` saying why) if
    /// it does not converge.
    bool newton(NewtonVector& x, std::string& failure);
    /// The damped step x += lambda dx (returns lambda, 0: none found) and the simplified Newton
    /// correction dx_bar at the new x.
    double damped_step(NewtonVector& x, NewtonVector& F, const NewtonVector& dx,
                       NewtonVector& dx_bar);
    double newton_norm(const NewtonVector& v) const;
    void assemble_jacobian(const NewtonVector& x, const NewtonVector& F);
    /// J dx = rhs with the Jacobian of the last assemble_jacobian() (`reduction` >= 0: GMRES's
    /// residual reduction for this solve).
    void solve_newton_system(NewtonVector& dx, const NewtonVector& rhs, double reduction = -1);
    /// Jacobian-free Newton-Krylov (solid_jacobian_free.templates.h): the base point of the
    /// directional differences, and the segregated preconditioner for the clock's c0.
    void setup_jacobian_free(const NewtonVector& x, const NewtonVector& F);
    void apply_segregated_preconditioner(NewtonVector& y, const NewtonVector& r) const;
    NewtonVector jfnk_x, jfnk_F;
    std::array<dealii::TrilinosWrappers::PreconditionAMG, dim> jfnk_amg;
    double jfnk_mass_coefficient = -1;
    NewtonVector jfnk_diagonal; ///< of the boundary rows (1 on the cell rows)
    /// x from the solver's state.
    void coupled_state(NewtonVector& x) const;
    /// F(x): sets the state (u, boundary values, vertex values, gradients) from x, computes one
    /// update of the boundary values and the residual of Eq. 16.
    void coupled_residual(const NewtonVector& x, NewtonVector& F);
    void set_fixed_boundary_values();
    double relative_change(const NewtonVector& dx, const NewtonVector& x) const;

    /// The loads (tractions, body force, fixed displacements) are scaled by this (load stepping
    /// of the coupled algorithm; 1 otherwise).
    double load_factor = 1;
    std::unique_ptr<ProbedJacobian<dim>> probing;
    /// Per face: the local Newton node of its u_b and of its g_n (invalid_cell: none).
    std::vector<unsigned int> ub_node, gn_node;
    double cell_size = 0; ///< (volume / cells)^(1/dim)
    dealii::TrilinosWrappers::SparseMatrix jacobian;
    std::unique_ptr<JacobianSolver> jacobian_solver;
    double jacobian_mass_coefficient = -1; ///< c0^2 of the linear-elastic Jacobian, -1: none
    std::array<CellVector, dim> coupled_cell_residual;
    unsigned long n_jacobians = 0, n_residuals = 0, n_krylov = 0;
    double least_stretch_seen = 1;
    /// smallest_stretch() after a solve; a warning the first time it is below 1/sqrt(3).
    void check_stretch();
    double smallest_stretch() const;

    const FVGeometry<dim>& geometry;
    SolidParameters parameters;
    const TimeControl& clock;
    LameParameters lame;
    dealii::ConditionalOStream pcout;
    VertexInterpolation<dim> vertex_interpolation;
    LeastSquaresGradient<dim> least_squares;
    GaussGreenGradient<dim> gauss_green;
    Laplacian<dim> laplacian;

    FaceConditions<dim, SolidBoundaryCondition::Type> conditions; ///< per boundary face
    /// The traction (pressure: entry 0) expressions at the face centres at the current time, per
    /// face of a traction or pressure patch (evaluated once per time step, not per sweep).
    std::vector<dealii::Tensor<1, dim>> given_traction;
    void evaluate_given_tractions();
    dealii::FunctionParser<dim> body_force;
    std::array<std::vector<double>, dim>
      body_force_value; ///< b at the owned cell centres, this step
    std::vector<dealii::Tensor<1, dim>> external_traction;

    std::array<dealii::TrilinosWrappers::SparseMatrix, dim> matrix;
    std::array<std::unique_ptr<LinearSolver>, dim> linear_solver;
    double assembled_mass_coefficient = -1;
    unsigned int last_outer_iterations = 0;
    /// Anderson acceleration of the outer iterations: the least-squares model of the residual
    /// f = du over the iterates' images g = u + du (depth: Solid/Outer acceleration depth).
    LeastSquaresModel<BlockVector> acceleration;
    BlockVector f, g, f_previous, g_previous, correction;
    /// The outer iteration's R(u) and du per component, allocated once.
    std::array<CellVector, dim> residual, du;

    // State: u [m] and the old levels BDF2 reads (u^o, u^oo; v^o, v^oo, the velocities
    // v = c0 u - c1 u^o + c2 u^oo [m/s] of the two steps before; v: the last one computed).
    CellVectorField<dim> u, v;
    TimeLevels<CellVectorField<dim>> u_levels, v_levels;

    // Derived from u in update_gradients().
    std::array<CellGradient<dim>, dim> grad_u;      ///< grad_u[j] = grad u_j
    std::array<std::vector<double>, dim> vertex_u;  ///< vertex values of u_j
    std::vector<dealii::Tensor<1, dim>> boundary_u; ///< u_b per boundary face
    std::vector<dealii::Tensor<2, dim>> boundary_G; ///< grad u per boundary face (Eq. 24 iterate)
    /// Vertices on symmetry planes (with the plane's normal) and on displacement boundaries.
    std::vector<std::pair<unsigned int, dealii::Tensor<1, dim>>> symmetry_vertex_normals;
    std::map<unsigned int, const dealii::FunctionParser<dim>*> fixed_vertex_function;

    /// Hessian correction (present variant): per-cell Hessians of u_j and their fit.
    std::unique_ptr<QuadraticFit<dim>> cell_hessian;
    std::array<CellHessian<dim>, dim> hessian;
    std::vector<dealii::Tensor<1, dim>> boundary_g_n; ///< n . grad u on traction faces
    /// From the current Hessians: the quadratic terms of the vertex fit (subtracted from the
    /// linear fit's vertex values) and of the extrapolation to traction and symmetry faces.
    std::array<std::vector<double>, dim> vertex_quadratic_term;
    std::vector<dealii::Tensor<1, dim>> boundary_quadratic_term;
  };
} // namespace fvfsi
