#pragma once
// The incompressible flow solver (paper sections 2.1 and 3.2): velocity u and kinematic pressure
// p/rho collocated at the cell centres, momentum solved component by component, pressure from
// continuity by the PISO algorithm with a consistent Rhie-Chow face flux.
//
// Momentum of cell P (Eq. 2 integrated over V_P, BDF2 in time, Eqs 17-18 style):
//
//   V_P (c0 u_P - c1 u_P^o + c2 u_P^oo) + sum_f phi_f u_f - sum_f nu S_f (n.grad u)_f
//       = V_P g - V_P (grad p)_P,
//
// with phi_f = F_f - F_f^mesh the flux relative to the moving face (F_f = S_f . u_f, volumetric,
// m^3/s, m^2/s per unit depth in 2D), u_f by the convection scheme (upwind part implicit, the
// rest deferred), n.grad u by Eq. 19 (orthogonal part implicit). Written as
//
//   A_P u_P + sum_N A_PN u_N = B_P - V_P (grad p)_P,   B_P = B_P^time + B_P^rest,
//
// with B^time = V (c1 u^o - c2 u^oo) and B^rest every other explicit source. Dividing by V_P
// (a_P = A_P / V_P, h_P = (B^rest_P - sum_N A_PN u_N) / V_P) gives
//   u_P = (h_P + B^time_P / V_P - (grad p)_P) / a_P.
//
// Consistent Rhie-Chow flux (after Tukovic and Jasak; the paper's refs [20, 21]). Split
// a_P = c0 + a*_P into its time part c0 (the same in every cell) and its spatial part a*_P. At a
// steady state the cell equation is a*_P u_P = h_P - (grad p)_P, whatever the time step. The face
// flux is built to have the same property:
//
//   (c0 + a*_f) F_f = c1 F_f^o - c2 F_f^oo + a*_f [ S_f . (h / a*)_f - (1 / a*)_f S_f (n.grad p)_f ],
//
// with (h / a*)_f interpolated linearly and corrected for skewness with the velocity gradient
// (h / a* ~ u + grad p / a*, and the interpolation point on the line P-N misses the face centre by
// m_f on a distorted mesh), 1 / a*_f interpolated linearly, and (n.grad p)_f by Eq. 19. At a steady
// state (F = F^o = F^oo, c0 = c1 - c2) the time terms cancel exactly: the converged solution does
// not depend on the (pseudo) time step. Interpolating h / a* (a velocity) rather than h keeps the
// flux second order on meshes whose cell coefficients a*_P jump from cell to cell. Continuity
// sum_f F_f = 0 is the pressure equation, a Laplacian with Gamma_f = 1 / (c0 + a*_f).
//
// Moving meshes (ALE, after Tukovic and Jasak). The driver moves the vertices, recomputes the
// geometry and hands the solver the volume dV_f each face swept (move_mesh). The mesh flux is
// F_f^mesh = c0 dV_f^n - c2 dV_f^(n-1) (backward Euler: dV_f^n / dt), so that the space
// conservation law (Eq. 3) holds exactly in BDF2 form:
//   c0 V_P - c1 V_P^o + c2 V_P^oo = sum_f F_f^mesh.
// The time derivative is that of V_P u_P. With the SCL, c0 V_P u_P and the part -u_P sum_f F^mesh_f
// of the convection term combine to (c1 V_P^o - c2 V_P^oo) u_P, i.e. c0 V_P is replaced by
//   c0_P V_P,  c0_P = c1 r1_P - c2 r2_P,  r1 = V^o / V, r2 = V^oo / V,
// and sum_f F^mesh_f is added to the spatial diagonal, whose rows then sum to sum_f F_f (zero for a
// divergence-free flux): h / a* of a uniform flow is that flow. The Rhie-Chow flux uses the same
// split, c0_f = c1 r1_f - c2 r2_f with r interpolated linearly, and old fluxes carried to the new
// face, F^o' = F^o + u^o_f . (S_f - S_f^o):
//   (c0_f + a*_f) F_f = c1 r1_f F_f^o' - c2 r2_f F_f^oo' + a*_f [ ... as above ... ].
// A uniform flow then stays uniform whatever the mesh motion (tests/fluid/fluid_scl.cc). A wall
// moves with the mesh: u_b = (I - n n) v_f + n F_f^mesh / S_f, v_f the BDF2 velocity of the face
// centre. On a fixed mesh r = 1, F^mesh = 0, and all of this reduces to the formulation above.
//
// Linearisation (Fluid/Flux extrapolation, default true). The momentum equation of a PISO step is
// assembled once, so its convecting flux phi and its explicit parts (deferred convection and
// non-orthogonal corrections, boundary values) are evaluated at a known state. With the previous
// step's F^n, u^n (OpenFOAM's PISO) that lag is O(dt): plain PISO is first order in time. With
// the extrapolated state F = 2 F^n - F^(n-1), u = 2 u^n - u^(n-1) the lag is O(dt^2) and one
// outer loop is second order (tests/fluid/fluid_taylor_green). Outer correctors (PIMPLE)
// re-assemble with the latest F and u, until one changes the face velocities by less than Outer
// tolerance; every loop but the final one is under-relaxed (Outer relaxation alpha) as a pseudo
// time step a*_P (1 - alpha) / alpha added to c0_P and c0_f, whose old values are the previous
// loop's u and F, so that the converged step is PISO's (doc/results/hard_cases.md, section 6).
//
// The solver knows nothing about coupling or mesh motion drivers: it reads the geometry and the
// clock (TimeControl) it is given and exposes velocity, pressure, fluxes and patch forces. Its life
// cycle is that of every solver of a scene: the scene advances the clock, then
//   begin_time_step()  (move to the clock's new time level),
//   solve_current_step()  (repeatable: a coupling solves the step again after moving the mesh),
//   end_time_step()  (accept the step).
// Steady (Fluid/Transient = false), solve_current_step() runs pseudo time steps to convergence
// from the current state.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/base/time_control.h>
#include <fvfsi/base/time_levels.h>
#include <fvfsi/fluid/fluid_parameters.h>
#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/fv/face_matrix.h>
#include <fvfsi/fv/fv_operators.h>
#include <fvfsi/fv/gradients.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/linear_solver.h>
#include <fvfsi/fv/point_probes.h>
#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/io/checkpoint.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_parameters.h>

#include <array>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace fvfsi
{
  template <int dim>
  class FluidSolver : public TimeSteppingSolver
  {
  public:
    /// `clock` is the scene's, read at every time step (steady runs ignore it).
    FluidSolver(const FVGeometry<dim>& geometry, const MeshParameters& mesh_parameters,
                const FluidParameters& parameters, const TimeControl& clock);

    /// Move to the clock's time level: boundary and body-force expressions at t, the state to
    /// start from (transient: extrapolated from the last two steps).
    void begin_time_step() override;
    /// Transient: one PISO step from the step's start state (a repeated call, after another
    /// move_mesh(), starts from the same state). Steady: pseudo time steps until the relative
    /// change is below the steady tolerance, from the current state. Throws std::runtime_error
    /// naming the time step and the field if a value becomes non-finite.
    void solve_current_step() override;
    /// Accept the step (relative_change() tells by how much it changed u).
    void end_time_step() override;
    /// max|u^(n+1) - u^n| / max|u^(n+1)| of the last accepted step.
    double relative_change() const { return last_change; }
    /// The last accepted step's error estimate max |u - u_p| / U, u_p the extrapolation of the
    /// two steps before to its time, U the velocity scale (Time/Adaptive = error); 0 on the first.
    double step_error() const { return last_error; }
    /// The PISO pressure correctors of the last solve, summed over its outer loops.
    unsigned int pressure_correctors_used() const { return correctors_used; }
    /// The outer (PIMPLE) loops of the last solve.
    unsigned int outer_iterations_used() const { return outer_used; }

    /// Start from the velocity u(x) [m/s] and, if given, the kinematic pressure p(x) / rho
    /// [m^2/s^2] at the cell centres (every time level alike; the fluxes interpolated from u):
    /// the initial state of a run that continues an earlier one on another mesh.
    void set_state(const std::function<dealii::Tensor<1, dim>(const dealii::Point<dim>&)>& velocity,
                   const std::function<double(const dealii::Point<dim>&)>& kinematic_pressure);

    /// The driver has moved the mesh for the coming time step (FVGeometry::reinit) and passes
    /// the volumes the faces swept, FVGeometry::swept_volumes() of that motion [m^dim]. The next
    /// solve builds the mesh fluxes from them; a step without a call is a step without motion.
    /// Steady: the mesh is at rest in its new position (no mesh flux).
    void move_mesh(const std::vector<double>& swept_volume);

    /// Steady: pseudo time steps until the relative change is below the steady tolerance.
    /// Returns the number of pseudo steps. Where the change makes no progress (the geometric
    /// mean over 50 pseudo steps not 5% below that of the 50 before), alpha is lowered, 1 - alpha
    /// doubled: the pseudo-transient iteration with alpha near 1 and no pressure relaxation is
    /// unstable where viscosity dominates with SIMPLE's coefficients (CFD2 at Re = 1 needs alpha
    /// <= 0.8, the cavity at h = 0.0125 too), not with SIMPLEC's (Consistent pressure
    /// coupling). Below 0.3 it stops with an error saying whether the change oscillates or
    /// stagnates (a flow without a steady state, e.g. vortex shedding).
    unsigned int solve_steady();
    /// Steady: alpha in use now (Momentum relaxation, or lower after solve_steady()).
    double momentum_relaxation() const { return relaxation; }
    /// Steady: pseudo time steps of all solves so far.
    unsigned int pseudo_steps() const { return pseudo_step; }

    const FluidParameters& parameters() const { return prm; }

    /// u at the cell centres [m/s] (ghosts up to date).
    const CellVectorField<dim>& velocity() const { return u; }
    /// Kinematic pressure p / rho at the cell centres [m^2/s^2] (ghosts up to date).
    const CellVector& kinematic_pressure() const { return p; }
    /// grad (p / rho) at the cell centres [m/s^2].
    const CellGradient<dim>& kinematic_pressure_gradient() const { return grad_p; }
    /// grad u_j at the cell centres (vertex Gauss-Green, Eq. 37).
    const CellGradient<dim>& velocity_gradient(unsigned int j) const { return grad_u[j]; }
    /// The velocity [m/s] and pressure [Pa] at probe i: the linear reconstructions
    /// u_P + (x - r_P) . grad u and p_P + (x - r_P) . grad p in the cell holding the point
    /// (collective).
    std::pair<dealii::Tensor<1, dim>, double> probe_values(const PointProbes<dim>& probes,
                                                           unsigned int i) const;
    /// Volumetric face fluxes F_f = S_f . u_f [m^3/s] (per unit depth in 2D), indexed like
    /// FVGeometry::faces.
    const FaceVector& face_flux() const { return F; }
    /// Mesh fluxes F_f^mesh of the last time step [m^3/s] (zero on a fixed mesh).
    const FaceVector& mesh_flux() const { return F_mesh; }
    /// Force of the fluid on the body behind a wall patch, sum over its faces of
    /// S_f (p_f n_f - mu (n.grad u)_f) [N] (per unit depth in 2D), n_f out of the fluid.
    dealii::Tensor<1, dim> patch_force(unsigned int patch) const;
    /// The sum of patch_force over the patches `ids` [N].
    dealii::Tensor<1, dim> patches_force(const std::vector<unsigned int>& ids) const;
    /// The force per unit area the fluid exerts on the wall at boundary face f,
    /// rho (p_f n_f - nu (n.grad u)_f) [Pa], n_f out of the fluid.
    dealii::Tensor<1, dim> wall_traction(unsigned int f) const;
    /// True if an outlet fixes the pressure level; otherwise p = 0 in global cell 0.
    bool pressure_level_is_fixed() const { return pressure_level_fixed; }
    /// max over owned cells of |div u| V_P / (sum_f |F_f|): the continuity error.
    double continuity_error() const;
    /// max over cells of the Courant number dt sum_f |phi_f| / (2 V_P).
    double courant_number() const;
    /// The largest max |u| / U after any solve so far, U the velocity scale of the divergence
    /// guard (data_velocity_scale(); summary.json: max_velocity_over_scale).
    double largest_velocity_ratio() const { return largest_velocity_ratio_seen; }
    /// Velocity u [m/s], pressure p [Pa] and vorticity [1/s] (2D: dv/dx - du/dy; 3D: its
    /// magnitude) as output fields.
    void add_output_fields(OutputFields<dim>& fields) const;
    /// Save or load the state a transient run continues from between two time steps (the time
    /// levels of u, p, the fluxes and the moving mesh's old geometry; the lagged gradients and
    /// boundary values); see io/checkpoint.h.
    void checkpoint(MeshArchive<dim>& archive);
    /// The pressure's linear solver (for its solve and iteration counts).
    const LinearSolver& pressure_linear_solver() const { return pressure_solver; }
    const LinearSolver& momentum_linear_solver() const { return momentum_solver; }
    /// Wall time per part of the algorithm, for the run's log.
    dealii::TimerOutput& timer() { return timer_output; }

  private:
    using Type = FluidBoundaryCondition::Type;

    void setup_boundary_conditions(const MeshParameters& mesh_parameters);
    void set_initial_conditions();
    /// Transient: the clock's du/dt ~ c0 u - c1 u^o + c2 u^oo, the same in every cell; steady:
    /// zero (the local pseudo time steps are set in assemble_momentum()).
    BdfCoefficients time_coefficients() const;
    /// One PISO time step (transient) or pseudo time step (steady).
    void solve_piso_step();
    /// The clock's step (transient) or the pseudo time step (steady).
    unsigned int step_index() const { return prm.transient ? clock.step() : pseudo_step; }

    // Boundary values, vertex values and gradients of u and p.
    void update_velocity_boundary_values();
    void update_velocity_gradients();
    void update_pressure_boundary_values();
    void update_pressure_gradient();

    // The steps of one PISO time step.
    /// One PISO sequence, outer loop `outer` (from 0); `last`: the last outer loop of the step.
    void solve_outer_iteration(unsigned int outer, bool last);
    /// The least and most pressure correctors of outer loop `outer` of this solve.
    std::pair<unsigned int, unsigned int> corrector_range(unsigned int outer) const;
    /// max_f |F_f - before_f| / S_f over max_f |F_f| / S_f: what the last corrector (or outer
    /// loop) changed.
    double face_velocity_change(const FaceVector& before) const;
    FaceVector F_before_corrector;
    /// Transient: the fluxes at the start of the outer loop (its relaxation's old values).
    FaceVector F_outer_start;
    /// Transient: alpha of the current outer loop (Outer relaxation; 1 in the final loop).
    double outer_alpha = 1;
    unsigned int outer_used = 0; ///< outer_iterations_used()
    /// The pressure correctors of each outer loop of the step's first solve.
    std::vector<unsigned int> step_correctors;
    unsigned int correctors_used = 0; ///< pressure_correctors_used()
    void assemble_momentum();
    void add_convection_correction(unsigned int f, double phi);
    /// The viscous and convective terms of boundary face f (relative flux phi).
    void add_boundary_face_momentum(unsigned int f, double phi);
    /// The time derivative (BDF2 or the local pseudo time step) and the body force.
    void add_time_and_body_force_terms();
    void solve_momentum();
    void assemble_pressure_matrix();
    /// Gamma_f of face f (c1, c2 the BDF coefficients) and its share of the pressure equation.
    void add_pressure_face(unsigned int f, const FaceGeometry<dim>& face, double c1, double c2);
    /// Steady with Consistent pressure coupling: SIMPLEC's coefficients.
    bool simplec() const { return !prm.transient && prm.consistent_coupling; }
    /// a~_P = a_P - H1_P (SIMPLEC) or a_P, into a_tilde.
    void compute_consistent_coefficients();
    /// F*_f of a pressure corrector (Rhie-Chow); `new_outer_loop`: first compute the parts
    /// every corrector of the outer loop shares (compute_flux_parts()).
    void compute_predicted_fluxes(bool new_outer_loop);
    void compute_flux_parts();
    /// `last`: the last pressure corrector of the time step, whose last solve gets the full
    /// Residual reduction (the others: Corrector residual reduction).
    void solve_pressure(bool last);
    void correct_fluxes();
    void correct_velocity();
    void shift_time_levels();
    /// S_f and r_f of the current geometry into S^o, r_f^o.
    void record_face_geometry();
    /// F_f^mesh of the current time step from the swept volumes.
    void compute_mesh_fluxes();
    /// r1_f = (V^o / V)_f and r2_f = (V^oo / V)_f, interpolated linearly (1 on a fixed mesh).
    const std::array<double, 2>& volume_ratios(unsigned int f) const
    {
      return face_volume_ratio[f];
    }
    /// Recompute face_volume_ratio (after the geometry or the time levels change).
    void update_volume_ratios();
    std::vector<std::array<double, 2>> face_volume_ratio;
    /// True when the preconditioners are to be rebuilt (every `Preconditioner update interval`
    /// time steps; in between, the matrices change a little and the old ones still work).
    bool refresh_preconditioners() const
    {
      return (step_index() - 1) % prm.preconditioner_update_interval == 0;
    }
    void check_finite(const char* field) const;
    /// The divergence guard (fv/divergence_guard.h): raises U by this step's data, then throws a
    /// DivergenceError if max |u| > Velocity bound x U.
    void check_bounded_velocity();
    /// This step's data's speed [m/s]: given boundary velocities (inlets, moving walls),
    /// sqrt(dp) of the outlets' pressure differences (Bernoulli, p kinematic), sqrt(|g| L) of the
    /// body force over the domain's diameter L. The guard's U is its running maximum, started
    /// from the initial velocity's; it bounds max |u| by Velocity bound times U.
    double data_velocity_scale() const;
    /// "time step N (t = ... s)" or "pseudo time step N", for messages.
    std::string step_name() const;

    const FVGeometry<dim>& geometry;
    FluidParameters prm;
    const TimeControl& clock;
    dealii::ConditionalOStream pcout;
    dealii::TimerOutput timer_output;
    FVOperators<dim> operators; ///< vertex values, Gauss-Green gradient, Laplacian

    FaceConditions<dim, Type> conditions; ///< per boundary face
    dealii::FunctionParser<dim> body_force;
    /// g at the owned cell centres at the current time (evaluate_body_force()).
    std::array<std::vector<double>, dim> body_force_value;
    /// The body force once per time step (a FunctionParser evaluation per cell and PISO
    /// assembly was about 2% of a step).
    void evaluate_body_force();
    bool pressure_level_fixed = false; ///< true if some outlet fixes p; else a reference cell
    ScalarBoundaryConditions<dim> velocity_bc, pressure_bc;
    FaceVector nu_f; ///< nu per face (Gamma of the viscous Laplacian)

    // Matrices and linear solvers.
    FaceMatrix<dim> momentum, pressure_equation;
    dealii::TrilinosWrappers::SparseMatrix momentum_matrix, pressure_matrix;
    LinearSolver momentum_solver, pressure_solver;

    // State.
    // State: the present level and the old ones (u^o = u_levels.o, u^oo = u_levels.oo).
    CellVectorField<dim> u;
    TimeLevels<CellVectorField<dim>> u_levels;
    CellVector p;
    FaceVector F, F_mesh;
    TimeLevels<FaceVector> F_levels;
    // Mesh motion: the old levels of the cell volumes, face area vectors and face centres, and
    // the swept volumes of this step and the last.
    TimeLevels<std::vector<double>> V_levels;
    TimeLevels<std::vector<dealii::Tensor<1, dim>>> S_levels;
    TimeLevels<std::vector<dealii::Point<dim>>> r_f_levels;
    FaceVector swept, swept_old;
    unsigned int pseudo_step = 0; ///< steady: pseudo time steps so far
    /// Steady: alpha in use (Momentum relaxation, lowered by solve_steady() where the pseudo
    /// steps stop making progress; the steady solution does not depend on it).
    double relaxation = 1;
    double last_change = 0;                 ///< relative_change()
    double scale_U = 0;                     ///< U, the running maximum [m/s]
    double last_error = 0;                  ///< step_error()
    double domain_length = 0;               ///< the domain's diameter L [m]
    double largest_velocity_ratio_seen = 0; ///< largest_velocity_ratio()
    // The state a time step starts from (after extrapolation), for repeated solves of the step:
    // the fields and the gradients the boundary values are extrapolated with (u_b at outlets,
    // p_b at walls), so that every solve of the step starts from the same boundary values too.
    CellVectorField<dim> u_start;
    CellVector p_start;
    // Fluid/Pressure extrapolation: the start value of the step's first pressure solve, and
    // whether p_start still holds the level before the last step (p^(n-1)), i.e. a step ended
    // since the solver started or was restored.
    CellVector p_extrapolated;
    bool p_start_is_previous_level = false;
    bool use_p_extrapolated = false;
    FaceVector F_start;
    std::array<CellGradient<dim>, dim> grad_u_start;
    CellGradient<dim> grad_p_start;
    unsigned int solves_this_step = 0;

    // Derived from u and p.
    std::array<CellGradient<dim>, dim> grad_u;
    CellGradient<dim> grad_p;
    std::array<std::vector<double>, dim> vertex_u;
    std::vector<double> vertex_p;
    std::vector<dealii::Tensor<1, dim>> boundary_u; ///< u_b per boundary face
    FaceVector boundary_p;                          ///< p_b per boundary face

    // Momentum equation of the current time step (owned cells).
    std::array<std::vector<double>, dim> B_time; ///< V (c1 u^o - c2 u^oo)
    std::array<CellVector, dim> B_rest;          ///< every other explicit source
    CellVector a;                                ///< a_P = A_P / V_P [1/s], ghosted
    CellVector a_star;           ///< a*_P = a_P - c0, the spatial part [1/s], ghosted
    CellVectorField<dim> h;      ///< h_P [m/s^2], ghosted
    FaceVector a_star_f;         ///< a*_f = 1 / (1 / a*)_f
    std::vector<double> c0_cell; ///< c0 of each owned cell (steady: local pseudo time step)
    FaceVector c0_face;          ///< c0_f (= c1_f: backward Euler or steady)
    FaceVector F_old_part;       ///< c1 r1_f F^o - c2 r2_f F^oo of F*_f (compute_flux_parts())
    std::vector<dealii::Tensor<1, dim>> h_skewness; ///< m . (grad u_j)_f for each j
    FaceVector F_star, gamma_p; ///< F_f without its pressure part; Gamma_f = 1 / (c0 + a*_f)
    /// The coefficient of the pressure equation and of the flux correction: Gamma_f, or with
    /// Consistent pressure coupling (steady) SIMPLEC's 1 / (a - H1)_f.
    FaceVector gamma_c;
    CellVector a_tilde;              ///< SIMPLEC: a_P - H1_P [1/s] (else a_P), ghosted
    CellGradient<dim> grad_p_before; ///< SIMPLEC: grad p before the corrector's pressure solve
    CellVector pressure_rhs;         ///< -div F* and the outlet sources (without the correction)
  };
} // namespace fvfsi
