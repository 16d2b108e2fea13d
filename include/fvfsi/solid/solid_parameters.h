#pragma once
// The `subsection Solid` of a .prm file: material, time integration, discretisation variant,
// outer iterations and boundary conditions of the solid solver.

#include <deal.II/base/parameter_handler.h>

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
  };

  struct SolidParameters
  {
    std::string model = "linear elastic"; ///< `linear elastic` or `St. Venant-Kirchhoff`
    std::string plane = "plane strain";   ///< 2D only: `plane strain` or `plane stress`
    double E = 1e7;                       ///< Young's modulus [Pa]
    double nu = 0.3;                      ///< Poisson's ratio [-]
    double rho = 1000;                    ///< density rho_0 [kg/m^3]
    std::string body_force = "0; 0";      ///< b [m/s^2], vector expression of x, y[, z], t
    std::string variant = "present";      ///< present | Demirdzic-Muzaferija | Jasak-Weller

    bool transient = false;               ///< false: steady (no inertia)
    double time_step = 0.01;              ///< dt [s]
    double end_time = 1;                  ///< [s]
    /// Outer (segregated) iterations per time step: stop when max |du| / max |u| < tolerance.
    double outer_tolerance = 1e-6;
    unsigned int max_outer_iterations = 1000;
    /// Anderson acceleration of the outer iterations: number of kept differences (0: none).
    unsigned int acceleration_depth = 10;
    /// Passes of boundary values + vertex values + gradients per outer iteration.
    unsigned int boundary_sweeps = 8;
    /// present variant: second-order (Hessian) terms in the vertex values and the extrapolated
    /// boundary values (an extension of the paper; see solid_solver.cc).
    bool hessian_correction = false;

    std::string fixed_displacement, traction, pressure, symmetry, external_traction;
    LinearSolverParameters solver;

    void declare(dealii::ParameterHandler& prm);
    /// The boundary conditions listed in the five BC entries; throws naming a malformed entry.
    std::vector<SolidBoundaryCondition> boundary_conditions() const;
  };
} // namespace fvfsi
