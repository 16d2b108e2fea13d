#include <fvfsi/base/patch_list.h>
#include <fvfsi/base/patterns.h>
#include <fvfsi/solid/solid_parameters.h>

namespace fvfsi
{
  using namespace dealii;

  const SelectionNames<SolidParameters::Model> SolidParameters::model_names = {
    {"linear elastic", Model::linear_elastic},
    {"St. Venant-Kirchhoff", Model::st_venant_kirchhoff}};
  const SelectionNames<SolidParameters::Variant> SolidParameters::variant_names = {
    {"present", Variant::present},
    {"Demirdzic-Muzaferija", Variant::demirdzic_muzaferija},
    {"Jasak-Weller", Variant::jasak_weller}};

  // One entry after the other, each with the documentation that --print-parameters shows: a list
  // longer than a screen, read as one.
  void SolidParameters::declare(ParameterHandler& prm)
  {
    prm.enter_subsection("Solid");
    add_selection(prm, "Model", model, model_names,
                  "St. Venant-Kirchhoff (finite strain, total Lagrangian, Eqs 4-9) or linear "
                  "elastic (small strain: q without its nonlinear terms).");
    add_selection(prm, "Plane", plane,
                  {{"plane strain", Plane::strain}, {"plane stress", Plane::stress}},
                  "2D only: plane strain or plane stress.");
    prm.add_parameter("Young's modulus", E, "E [Pa].", PositiveDouble(1e15));
    prm.add_parameter("Poisson's ratio", nu, "nu [-].", Patterns::Double(-0.999, 0.4999));
    prm.add_parameter("Density", rho, "rho_0 [kg/m^3] (reference configuration).",
                      PositiveDouble(1e10));
    prm.add_parameter(
      "Body force", body_force,
      "b [m/s^2] per unit mass, dim expressions of x, y[, z], t separated by `;` (`0`: "
      "the zero vector in 2D and 3D).");
    add_selection(prm, "Variant", variant, variant_names,
                  "Face gradient: present (paper: central normal part + vertex Gauss-Green "
                  "tangential part, also on boundary faces), Demirdzic-Muzaferija (least-squares "
                  "cell gradients interpolated to faces), Jasak-Weller (cell-centred Gauss "
                  "gradients with skew-corrected linear face values, the model of OpenFOAM's "
                  "solidDisplacementFoam).");
    prm.add_parameter(
      "Transient", transient,
      "true: inertia with the BDF2 (backward) scheme, Eqs 17-18, first step backward "
      "Euler, time step and end time from `Time`; false: steady (one solve).");
    prm.add_parameter("Outer tolerance", outer_tolerance,
                      "Stop the outer (segregated) iterations of a time step when "
                      "max |du| / max |u| is below this.",
                      PositiveDouble(1));
    prm.add_parameter(
      "Displacement bound", displacement_bound,
      "No silent divergence: after every solve max |u| over the cells must stay below this "
      "times (the diameter of the body's bounding box + the largest given boundary "
      "displacement); otherwise the run stops naming the time step, the value and the cell. "
      "A clamped body bends, it does not travel its own size.",
      Patterns::Double(1e-6, 1e10));
    prm.add_parameter("Max outer iterations", max_outer_iterations,
                      "Limit of outer iterations per time step (exceeding it stops the run).",
                      Patterns::Integer(1));
    prm.add_parameter("Outer acceleration depth", acceleration_depth,
                      "Anderson acceleration of the outer iterations (the least-squares model of "
                      "IQN-ILS): number of kept iterate differences; 0 = plain segregated "
                      "iterations as in the paper.",
                      Patterns::Integer(0, 50));
    prm.add_parameter(
      "Boundary sweeps", boundary_sweeps,
      "Passes of the boundary-value (Eqs 23-24), vertex-value and gradient update per "
      "outer iteration: they depend on each other, and converging them makes the "
      "outer iteration a fixed-point map of u alone (needed by the acceleration).",
      Patterns::Integer(1, 100));
    prm.add_parameter(
      "Hessian correction", hessian_correction,
      "present variant only (an extension of the paper): add the second-order Taylor "
      "terms, with per-cell Hessians from a least-squares quadratic fit, to the vertex "
      "values (App. B) and to the boundary values extrapolated at traction (Eqs 23-24) "
      "and symmetry faces. The paper's first-order forms leave an O(h^2) vertex error "
      "whose structure changes at a traction boundary; where two traction boundaries "
      "meet, the max displacement error then converges like h^2 log(1/h). With the "
      "correction it is O(h^2) (prm/plate_hole.prm sets it). Costs one sparse product "
      "per cell and outer iteration, and about 15 % more outer iterations (plate with "
      "a hole, nu = 0.3); the other variants ignore it. Not for nearly incompressible "
      "plane strain: it slows the outer iterations there (plate with a hole, 968 "
      "cells: nu = 0.45 131 -> 274, nu = 0.49 274 -> 4866 iterations; nu = 0.499 not "
      "converged after 5000).");
    add_selection(prm, "Algorithm", algorithm,
                  {{"segregated", Algorithm::segregated}, {"coupled", Algorithm::coupled}},
                  "segregated: the paper's outer iterations, one displacement component at a "
                  "time (section 3.3); coupled: Newton's method on the same discrete equations, "
                  "all components and the boundary values (Eqs 23-24) at once, with the Jacobian "
                  "assembled by probing (see source/solid/solid_coupled.templates.h): for slender, "
                  "bending-dominated structures, where the segregated iteration converges slowly.");
    prm.add_parameter("Newton tolerance", newton_tolerance,
                      "coupled: stop when the residual has fallen by this factor (or when a "
                      "Newton step changes u by less than Outer tolerance).",
                      Patterns::Double(0));
    prm.add_parameter("Max Newton iterations", max_newton_iterations,
                      "coupled: limit of Newton iterations per solve (then a steady solve steps "
                      "the load; a transient one stops).",
                      Patterns::Integer(1));
    prm.add_parameter("Newton update every iteration", newton_update_every_iteration,
                      "coupled, St. Venant-Kirchhoff: true: a new Jacobian every Newton "
                      "iteration; false: keep it (also from one time step to the next) while "
                      "the Newton corrections shrink by 10 per iteration.");
    prm.add_parameter("Jacobian-free Newton", jacobian_free,
                      "coupled: false: the Jacobian assembled by probing and solved by `Solid "
                      "Newton linear solver`; true: Jacobian-free Newton-Krylov, GMRES (settings "
                      "of `Solid Newton linear solver`) on directional differences of the "
                      "residual, preconditioned by the segregated operator (one AMG V-cycle of "
                      "each component's A_j, diagonal scaling of the boundary rows).");
    prm.add_parameter("Newton log", newton_log,
                      "coupled: print a line per Newton iteration (step length, residual, "
                      "correction) and one per trial step of its damping (the simplified "
                      "correction over the step, and the bound it must meet).");
    const std::string& syntax = boundary_expression_syntax;
    prm.add_parameter("Fixed displacement", fixed_displacement,
                      "Patches with a given displacement u(x, t) [m]." + syntax);
    prm.add_parameter("Traction", traction,
                      "Patches with a given Cauchy traction t(x, t) [Pa] (Eq. 24; in finite strain "
                      "scaled by the deformed area ratio S'/S)." +
                        syntax);
    prm.add_parameter("Pressure", pressure,
                      "Patches with a given pressure p(x, t) [Pa]: traction -p n' on the deformed "
                      "face." +
                        syntax);
    prm.add_parameter("Symmetry", symmetry, "Symmetry-plane patches, comma separated.");
    prm.add_parameter(
      "External traction", external_traction,
      "Patches whose Cauchy traction is set per face by another solver (FSI), comma "
      "separated.");
    prm.leave_subsection();
    solver.reduction = 0.1;
    solver.declare(prm, "Solid linear solver");
    newton_solver.declare(prm, "Solid Newton linear solver");
  }

  std::vector<SolidBoundaryCondition> SolidParameters::boundary_conditions() const
  {
    using Type = SolidBoundaryCondition::Type;
    return parse_boundary_entries<SolidBoundaryCondition, Type>(
      {{fixed_displacement, "Solid/Fixed displacement", Type::fixed_displacement, true},
       {traction, "Solid/Traction", Type::traction, true},
       {pressure, "Solid/Pressure", Type::pressure, true},
       {symmetry, "Solid/Symmetry", Type::symmetry, false},
       {external_traction, "Solid/External traction", Type::external_traction, false}});
  }
} // namespace fvfsi
