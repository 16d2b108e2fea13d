#pragma once
// The `subsection Fluid` of a .prm file: fluid properties, time integration, the PISO algorithm,
// the convection scheme and the boundary conditions of the incompressible flow solver.

#include <deal.II/base/parameter_handler.h>

#include <fvfsi/fv/convection_scheme.h>
#include <fvfsi/fv/linear_solver.h>

#include <string>
#include <vector>

namespace fvfsi
{
  /// One fluid boundary condition: a patch, its type and its value expression(s).
  struct FluidBoundaryCondition
  {
    enum class Type
    {
      velocity_inlet, ///< u given (vector expression of x, y[, z], t) [m/s]; zero-gradient p
      wall,           ///< no slip: u = mesh velocity (zero on a fixed mesh); zero-gradient p
      outlet,         ///< p given (scalar expression) [Pa]; zero-gradient u
      symmetry        ///< u . n = 0, no shear; zero-gradient p
    };
    std::string patch;
    Type type = Type::wall;
    std::string expression;
    std::string parameter; ///< the .prm entry that lists it, e.g. `Fluid/Wall`
  };

  struct FluidParameters
  {
    FluidParameters();

    double rho = 1000;            ///< density [kg/m^3]
    double nu = 1e-3;             ///< kinematic viscosity [m^2/s]
    std::string body_force = "0"; ///< g [m/s^2], vector expression of x, y[, z], t (`0`: zero)
    std::string initial_velocity = "0"; ///< u(x, t = 0) [m/s] (`0`: zero)

    bool transient = true;             ///< false: steady (relaxed pseudo time steps to convergence)
    double momentum_relaxation = 0.95; ///< steady: alpha, the local pseudo time step
    double steady_tolerance = 1e-8;    ///< steady: stop when the relative change is below
    unsigned int max_steady_iterations = 5000; ///< steady: pseudo time step limit
    /// steady: SIMPLEC's pressure coefficient 1 / (a_P - H1_P) in place of 1 / a_P
    bool consistent_coupling = false;

    unsigned int outer_correctors = 1; ///< PIMPLE outer loops per time step, at most (1 = PISO)
    /// Stop the outer loops once one changed the face velocities by less than this, relative
    /// (then one final loop); 0: always Outer correctors loops.
    double outer_tolerance = 0;
    /// Under-relaxation alpha of the momentum equation in every outer loop but the final one.
    double outer_relaxation = 1;
    bool flux_extrapolation = true; ///< BDF2: first outer loop convects with 2 F^n - F^(n-1)
    /// The first pressure solve of a step starts from p extrapolated from the last two steps
    /// (a start value only: the step's equations do not change).
    bool pressure_extrapolation = false;
    unsigned int pressure_correctors = 2;     ///< PISO pressure correctors per outer loop, at least
    unsigned int max_pressure_correctors = 6; ///< ... and at most (transient)
    /// More correctors while the last changed the face velocities by more than this, relative.
    double pressure_corrector_tolerance = 1e-3;
    unsigned int non_orthogonal_correctors = 2; ///< extra pressure solves for Eq. 19's correction
    bool momentum_predictor = true;
    /// The divergence guard: max |u| may not exceed this times the velocity scale of the data.
    double velocity_bound = 10;
    unsigned int preconditioner_update_interval = 10; ///< time steps between ILU/AMG rebuilds
    /// The face velocity of the convection term (deferred correction on implicit upwind).
    using Convection = ConvectionScheme; ///< fv/terms.h
    Convection convection = Convection::linear_upwind;

    std::string velocity_inlet, outlet, wall, symmetry;

    LinearSolverParameters momentum_solver, pressure_solver;
    /// Residual reduction of every pressure solve of a time step but its last (0: the pressure
    /// solver's Residual reduction for all).
    double pressure_corrector_reduction = 0;

    void declare(dealii::ParameterHandler& prm);
    /// The boundary conditions listed in the four entries; throws naming a malformed entry.
    std::vector<FluidBoundaryCondition> boundary_conditions() const;
  };
} // namespace fvfsi
