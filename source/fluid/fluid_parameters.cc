#include <fvfsi/base/patch_list.h>
#include <fvfsi/base/patterns.h>
#include <fvfsi/base/selection.h>
#include <fvfsi/fluid/fluid_parameters.h>

#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  FluidParameters::FluidParameters()
  {
    // The momentum matrix is not symmetric (convection): GMRES + ILU. A predictor needs little
    // accuracy; the pressure equation decides continuity and is solved tighter.
    momentum_solver.method = LinearSolverParameters::Method::gmres;
    momentum_solver.preconditioner = LinearSolverParameters::Preconditioner::ilu;
    momentum_solver.reduction = 1e-3;
    momentum_solver.absolute_tolerance = 1e-15;
    pressure_solver.reduction = 1e-6;
    pressure_solver.absolute_tolerance = 1e-15;
  }

  // One entry after the other, each with the documentation that --print-parameters shows: a list
  // longer than a screen, read as one.
  void FluidParameters::declare(ParameterHandler& prm)
  {
    prm.enter_subsection("Fluid");
    prm.add_parameter("Density", rho, "rho [kg/m^3] (forces and pressure output are in N, Pa).",
                      PositiveDouble(1e10));
    prm.add_parameter("Kinematic viscosity", nu, "nu [m^2/s].", PositiveDouble(1e10));
    prm.add_parameter(
      "Body force", body_force,
      "g [m/s^2] per unit mass, dim expressions of x, y[, z], t separated by `;` (`0`: "
      "the zero vector in 2D and 3D).");
    prm.add_parameter(
      "Initial velocity", initial_velocity,
      "u at t = 0 [m/s], dim expressions of x, y[, z] separated by `;` (`0`: the zero "
      "vector).");
    prm.add_parameter("Transient", transient,
                      "true: time accurate, BDF2 (first step backward Euler), PISO; false: steady, "
                      "by local pseudo time steps (set by Momentum relaxation) until the solution "
                      "stops changing (the consistent Rhie-Chow flux makes the result independent "
                      "of the relaxation). The time step and end time are `Time/Time step` and "
                      "`Time/End time`.");
    prm.add_parameter("Momentum relaxation", momentum_relaxation,
                      "Steady: alpha in (0, 1]; each cell takes the pseudo time step with "
                      "1 / dt_P = a*_P (1 - alpha) / alpha (a*_P its momentum coefficient per unit "
                      "volume), i.e. SIMPLE-style under-relaxation of velocity and face fluxes.",
                      Patterns::Double(0.01, 1));
    prm.add_parameter(
      "Steady tolerance", steady_tolerance,
      "Steady: stop when max|u^k - u^(k-1)| / U over one pseudo step is below this (U: "
      "the larger of max|u| and sqrt(max p - min p), p kinematic). Steady FSI: unless given, "
      "0.1 x Coupling/Tolerance (see the log's steady settings).",
      PositiveDouble(1), /*has_to_be_set, i.e. tell a given value from the default:*/ true);
    prm.add_parameter(
      "Consistent pressure coupling", consistent_coupling,
      "Steady: true: SIMPLEC (Van Doormaal and Raithby) instead of SIMPLE: the pressure "
      "equation and the flux and velocity corrections take the coefficient 1 / (a_P - H1_P), "
      "H1_P = sum_N |a_PN| / V_P (for a smooth correction the neighbours move with the cell, "
      "which leaves the pseudo time term alone: 1 / (a_P - H1_P) ~ dt_P), and the predicted "
      "fluxes carry the difference of the two coefficients times the last pressure gradient, "
      "so that the converged state is SIMPLE's (the same Rhie-Chow flux). With alpha near 1 "
      "SIMPLE's pressure correction is 1 / (1 - alpha) times too strong where viscosity "
      "dominates, which makes fine meshes oscillate (doc/results/cavity.md). Unless given, a "
      "steady run takes true (see the log's steady settings).",
      Patterns::Bool(), /*has_to_be_set: tell a given value from the default*/ true);
    prm.add_parameter(
      "Max steady iterations", max_steady_iterations,
      "Steady: limit of pseudo time steps (exceeding it stops the run with an error).",
      Patterns::Integer(1));
    prm.add_parameter("Outer correctors", outer_correctors,
                      "Outer (PIMPLE) loops per time step, at most: momentum re-assembled with the "
                      "latest fluxes; 1 = plain PISO. The count of each step is the column "
                      "`outer` of the history.",
                      Patterns::Integer(1, 1000));
    prm.add_parameter(
      "Outer tolerance", outer_tolerance,
      "Transient, Outer correctors > 1: once an outer loop changed the face velocities F_f / S_f "
      "by less than this times their largest value, one final loop (unrelaxed) ends the step; "
      "0: always Outer correctors loops. The last loop is final in either case.",
      Patterns::Double(0, 1));
    prm.add_parameter(
      "Outer relaxation", outer_relaxation,
      "Transient: under-relaxation alpha of the momentum equation in every outer loop but the "
      "final one, as a pseudo time step within the time step: a*_P (1 - alpha) / alpha is added "
      "to the time derivative's c0_P and c0_f, with the previous outer loop's u and F as the old "
      "values (the consistent Rhie-Chow flux of the steady SIMPLE iteration). The final loop is "
      "unrelaxed, so the converged step is PISO's. Unrelaxed outer loops diverge at large "
      "Courant numbers on stretched cells (doc/results/hard_cases.md).",
      Patterns::Double(0.01, 1));
    prm.add_parameter("Flux extrapolation", flux_extrapolation,
                      "BDF2 steps: the first outer loop linearises the convection with the "
                      "extrapolated flux 2 F^n - F^(n-1) (second order in time with one outer "
                      "loop); false: with F^n, a first-order lag as in OpenFOAM's PISO.",
                      Patterns::Bool());
    prm.add_parameter("Pressure extrapolation", pressure_extrapolation,
                      "Transient: the first pressure solve of a time step starts from p "
                      "extrapolated from the last two steps (2 p^n - p^(n-1) for equal steps) "
                      "instead of p^n. A start value only: the equations are the same, and with "
                      "`Reduction relative to = initial residual` (the default) a better start "
                      "ends nearer the solution, not in fewer iterations "
                      "(doc/results/performance.md, section 15).",
                      Patterns::Bool());
    prm.add_parameter("Pressure correctors", pressure_correctors,
                      "PISO pressure corrections per outer loop, at least (steady: exactly).",
                      Patterns::Integer(1, 100));
    prm.add_parameter(
      "Max pressure correctors", max_pressure_correctors,
      "Transient: after Pressure correctors, more correctors while the last one changed the "
      "face velocities F_f / S_f by more than Pressure corrector tolerance times their largest "
      "value, up to this many (a number below Pressure correctors: exactly Pressure correctors). "
      "PISO's explicit correctors converge the step's pressure-velocity coupling only at small "
      "Courant numbers: on the plate of prm/wall_plate_channel.prm at Courant 4.3 two correctors "
      "per step leave an error that grows from step to step until the run diverges, with these "
      "defaults it runs to Courant 20 (doc/results/hard_cases.md). The count of each step is the "
      "column `correctors` of the history; a coupling iteration repeats the first solve's count.",
      Patterns::Integer(1, 100));
    prm.add_parameter("Pressure corrector tolerance", pressure_corrector_tolerance,
                      "See Max pressure correctors.", Patterns::Double(0, 1));
    prm.add_parameter("Non-orthogonal correctors", non_orthogonal_correctors,
                      "Extra pressure solves per corrector that update the explicit "
                      "non-orthogonal part of Eq. 19 (0 on orthogonal meshes; with 1 the steady "
                      "iteration on the distorted Kovasznay meshes of tests/fluid oscillates "
                      "instead of converging, with 2 it converges).",
                      Patterns::Integer(0, 100));
    prm.add_parameter("Momentum predictor", momentum_predictor,
                      "Solve the momentum equation before the pressure correctors.");
    prm.add_parameter(
      "Velocity bound", velocity_bound,
      "No silent divergence: after every (pseudo) time step max |u| over the cells must stay "
      "below this times the velocity scale U of the run's data (the largest given boundary "
      "velocity at inlets and moving walls, sqrt of the outlets' kinematic pressure differences, "
      "sqrt(|g| L) of the body force over the domain's diameter L, the initial velocity; the "
      "largest so far). Otherwise the run stops, naming the step, the value and the cell, and "
      "writes its last good state. The shipped cases measured in "
      "doc/results/hard_cases.md stay below 2.5 U; a flow that legitimately runs faster than 10 U "
      "(a jet "
      "through a narrow contraction) needs a larger bound.",
      Patterns::Double(1, 1e10));
    prm.add_parameter("Preconditioner update interval", preconditioner_update_interval,
                      "Rebuild the momentum ILU and pressure AMG preconditioners every this many "
                      "time steps (the matrices change slowly; an older preconditioner only costs "
                      "a few more Krylov iterations, never accuracy).",
                      Patterns::Integer(1));
    add_selection(prm, "Convection scheme", convection,
                  {{"upwind", Convection::upwind},
                   {"linear upwind", Convection::linear_upwind},
                   {"central", Convection::central}},
                  "Face velocity of the convection term, by deferred correction on an implicit "
                  "upwind part: upwind (first order), linear upwind (second order: upwind cell "
                  "value + its Gauss-Green gradient times (r_f - r_U)), central (second order, "
                  "unbounded at high cell Reynolds numbers).");
    const std::string& syntax = boundary_expression_syntax;
    prm.add_parameter("Velocity inlet", velocity_inlet,
                      "Patches with a given velocity u(x, t) [m/s]." + syntax);
    prm.add_parameter("Outlet", outlet,
                      "Patches with a given pressure p(x, t) [Pa] and zero-gradient velocity." +
                        syntax);
    prm.add_parameter("Wall", wall,
                      "No-slip wall patches (moving with the mesh), comma separated.");
    prm.add_parameter("Symmetry", symmetry, "Symmetry-plane (slip) patches, comma separated.");
    prm.leave_subsection();

    momentum_solver.declare(prm, "Fluid momentum solver");
    pressure_solver.declare(prm, "Fluid pressure solver");
    prm.enter_subsection("Fluid pressure solver");
    prm.add_parameter(
      "Corrector residual reduction", pressure_corrector_reduction,
      "Residual reduction of every pressure solve of a time step (or pseudo time step) but the "
      "last, i.e. of the PISO and non-orthogonal correctors before the final one, whose residual "
      "is the continuity error of the step and which keeps Residual reduction (OpenFOAM's relTol "
      "for p and pFinal); 0: Residual reduction for every solve. On the Turek-Hron CFD3 channel "
      "(400 steps, 20 960 cells, Residual reduction 1e-6) 1e-2 takes 4.9 instead of 10.2 CG "
      "iterations per solve and changes drag and lift by 2e-9 and 4e-5 relative, the continuity "
      "error not at all; 1e-1 changes the lift by 1.4e-4 (doc/results/performance.md). Unless "
      "given, a steady run takes 1e-1 (see the log's steady settings).",
      Patterns::Double(0, 1), /*has_to_be_set: tell a given value from the default*/ true);
    prm.leave_subsection();
  }

  std::vector<FluidBoundaryCondition> FluidParameters::boundary_conditions() const
  {
    using Type = FluidBoundaryCondition::Type;
    return parse_boundary_entries<FluidBoundaryCondition, Type>(
      {{velocity_inlet, "Fluid/Velocity inlet", Type::velocity_inlet, true},
       {outlet, "Fluid/Outlet", Type::outlet, true},
       {wall, "Fluid/Wall", Type::wall, false},
       {symmetry, "Fluid/Symmetry", Type::symmetry, false}});
  }
} // namespace fvfsi
