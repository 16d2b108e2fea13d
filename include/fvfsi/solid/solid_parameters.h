#pragma once
// The `subsection Solid` of a .prm file: material, time integration, discretisation variant,
// outer iterations and boundary conditions of the solid solver.

#include <deal.II/base/parameter_handler.h>

#include <fvfsi/base/selection.h>
#include <fvfsi/fv/jacobian_solver.h>
#include <fvfsi/fv/linear_solver.h>

#include <string>
#include <vector>

namespace fvfsi
{
  /// One boundary condition: a patch, its type and its value expression(s).
  struct SolidBoundaryCondition
  {
    enum class Type
    {
      fixed_displacement, ///< u given (vector expression of x, y[, z], t)   [m]
      traction,           ///< Cauchy traction given (vector expression)     [Pa]
      pressure,           ///< pressure given (scalar expression), traction = -p n'  [Pa]
      symmetry,           ///< u . n = 0, no tangential traction
      external_traction   ///< Cauchy traction per face, set from outside (the FSI interface)
    };
    std::string patch;
    Type type = Type::traction;
    std::string expression;
    std::string parameter; ///< the .prm entry that lists it, e.g. `Fluid/Wall`
  };

  /// True for the boundary conditions that give a traction (Eq. 24) rather than a displacement.
  inline bool takes_traction(const SolidBoundaryCondition::Type t)
  {
    using Type = SolidBoundaryCondition::Type;
    return t == Type::traction || t == Type::pressure || t == Type::external_traction;
  }

  struct SolidParameters
  {
    enum class Model
    {
      linear_elastic,     ///< small strain
      st_venant_kirchhoff ///< finite strain, total Lagrangian (Eqs 4-9)
    };
    enum class Plane
    {
      strain,
      stress
    };
    /// The face gradient of the discretisation (paper section 3.2 and its comparison models).
    enum class Variant
    {
      present,              ///< central normal part + vertex Gauss-Green tangential part
      demirdzic_muzaferija, ///< least-squares cell gradients interpolated to faces
      jasak_weller          ///< skew-corrected Gauss cell gradients (solidDisplacementFoam)
    };
    /// How a time step's nonlinear system is solved.
    enum class Algorithm
    {
      segregated, ///< the paper's: component by component, outer iterations (section 3.3)
      coupled     ///< Newton's method on all components and boundary values at once
    };
    static const SelectionNames<Model> model_names;
    static const SelectionNames<Variant> variant_names;

    Model model = Model::linear_elastic;
    Plane plane = Plane::strain;  ///< 2D only
    double E = 1e7;               ///< Young's modulus [Pa]
    double nu = 0.3;              ///< Poisson's ratio [-]
    double rho = 1000;            ///< density rho_0 [kg/m^3]
    std::string body_force = "0"; ///< b [m/s^2], vector expression of x, y[, z], t (`0`: zero)
    Variant variant = Variant::present;

    bool transient = false; ///< false: steady (no inertia)
    /// Outer (segregated) iterations per time step: stop when max |du| / max |u| < tolerance.
    double outer_tolerance = 1e-6;
    /// The divergence guard: max |u| may not exceed this times (the body's diameter + the
    /// largest given displacement).
    double displacement_bound = 1;
    unsigned int max_outer_iterations = 1000;
    /// Anderson acceleration of the outer iterations: number of kept differences (0: none).
    unsigned int acceleration_depth = 10;
    /// Passes of boundary values + vertex values + gradients per outer iteration.
    unsigned int boundary_sweeps = 8;
    /// present variant: second-order (Hessian) terms in the vertex values and the extrapolated
    /// boundary values (an extension of the paper; see solid_solver.cc).
    bool hessian_correction = false;

    Algorithm algorithm = Algorithm::segregated;
    /// coupled: stop when the residual has fallen by this factor, or when a Newton step changes u
    /// by less than the outer tolerance (max |du| / max |u|).
    double newton_tolerance = 1e-10;
    unsigned int max_newton_iterations = 25;
    /// coupled: reassemble the Jacobian of St. Venant-Kirchhoff every Newton iteration (true), or
    /// keep it while Newton's method converges fast (false).
    bool newton_update_every_iteration = false;
    bool newton_log = false; ///< coupled: a line per Newton iteration
    /// coupled: the Jacobian assembled by probing (solved by Solid Newton linear solver), or
    /// Jacobian-free Newton-Krylov (GMRES on directional differences of the residual,
    /// preconditioned by the segregated operator: AMG of each component's A_j).
    bool jacobian_free = false;
    JacobianSolverParameters newton_solver;

    std::string fixed_displacement, traction, pressure, symmetry, external_traction;
    LinearSolverParameters solver;

    void declare(dealii::ParameterHandler& prm);
    /// The boundary conditions listed in the five BC entries; throws naming a malformed entry.
    std::vector<SolidBoundaryCondition> boundary_conditions() const;
  };
} // namespace fvfsi
