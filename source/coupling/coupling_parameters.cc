#include <fvfsi/base/patterns.h>
#include <fvfsi/coupling/coupling_method.h>
#include <fvfsi/coupling/coupling_parameters.h>

namespace fvfsi
{
  using namespace dealii;

  void CouplingParameters::declare(ParameterHandler& prm)
  {
    // One declaration after the other: longer than a screen, but a flat list of the entries.
    prm.enter_subsection("Coupling");
    prm.add_parameter(
      "Fluid interface", fluid_interface,
      "Fluid patches (of `Mesh`) that touch the solid, comma separated: walls that "
      "are also `Mesh motion/Moving patches` (the coupling sets their displacement).");
    prm.add_parameter("Solid interface", solid_interface,
                      "Solid patches (of `Solid mesh`) that touch the fluid, comma separated: "
                      "`Solid/External traction` patches (the coupling sets their traction).");
    std::string names;
    for (const std::string& name : CouplingMethod::names())
      names += (names.empty() ? "" : "|") + name;
    prm.add_parameter("Method", method,
                      "How the interface displacement is updated between the fluid and solid "
                      "solves of a time step (Algorithm 1): fixed (relaxation), Aitken (dynamic "
                      "relaxation), IQN-ILS (interface quasi-Newton, least-squares inverse "
                      "Jacobian of the step's iterations) or IQN-IMVJ (interface quasi-Newton, "
                      "multi-vector inverse Jacobian carried from time step to time step); "
                      "each is a class in source/coupling/methods/.",
                      Patterns::Selection(names));
    prm.add_parameter("Relaxation", relaxation,
                      "omega of fixed relaxation (Eq. 31), also of the fixed iterations that start "
                      "every time step of Aitken and IQN-ILS (and of IQN-IMVJ's first time step).",
                      Patterns::Double(0, 1));
    prm.add_parameter("Fixed iterations", fixed_iterations,
                      "Aitken and IQN-ILS: fixed-relaxation iterations at the start of every time "
                      "step (the paper uses 2; IQN-ILS needs at least 1); IQN-IMVJ: only on time "
                      "steps without an inverse Jacobian of earlier steps (the first).",
                      Patterns::Integer(1));
    prm.add_parameter("Tolerance", tolerance,
                      "A time step has converged when |d~ - d|_2 <= this x |d~|_2 over the "
                      "interface vertices (Eq. 30), or when Residual reduction says so.",
                      PositiveDouble(1));
    prm.add_parameter("Residual reduction", residual_reduction,
                      "Also converged when |d~ - d|_2 <= this x the largest |d~ - d|_2 of the "
                      "time step's iterations (Lindner et al. 2015: 1e-6); with Tolerance, "
                      "whichever is met first ends the step. 0: off.",
                      Patterns::Double(0, 1));
    prm.add_parameter("Max iterations", max_iterations,
                      "Coupling iterations per time step before the run stops with an error.",
                      Patterns::Integer(1));
    prm.add_parameter("Reuse time steps", reuse_time_steps,
                      "IQN-ILS: also use the columns of this many earlier time steps (0: none). "
                      "(IQN-IMVJ carries its inverse Jacobian instead and ignores this.)",
                      Patterns::Integer(0, 20));
    prm.add_parameter(
      "Start time", start_time,
      "Time [s] from which fluid and solid are coupled. Before it the solid is held "
      "in its initial state (at rest) and the fluid runs alone on the fixed mesh, "
      "as the paper does for Turek-Hron FSI2/FSI3 (full inflow from the first "
      "step, coupling from 2 s): the flow develops without an impulsive load on "
      "the solid. 0: coupled from the first time step.",
      Patterns::Double(0));
    prm.add_parameter(
      "QR filter", qr_filter,
      "IQN-ILS and IQN-IMVJ: a column (newest first) whose part orthogonal to the newer ones "
      "is at most this x its norm is left out of the least-squares problem (preCICE's QR2 "
      "filter). 0: keep all but exactly dependent columns (nearly dependent ones amplify "
      "round-off); larger: fewer columns, more robust, possibly more iterations.",
      Patterns::Double(0, 1));
    prm.add_parameter("IMVJ dense limit", imvj_dense_limit,
                      "IQN-IMVJ: interfaces of up to this many values (vertices x dim) keep J "
                      "as a dense matrix with every time step (N^2 doubles); larger ones keep "
                      "it implicitly over the last `IMVJ time steps` time steps.",
                      Patterns::Integer(0));
    prm.add_parameter("IMVJ time steps", imvj_time_steps,
                      "IQN-IMVJ with an implicit J: the sliding window of time steps whose "
                      "columns make J (memory 4 x columns x N doubles).",
                      Patterns::Integer(1));
    prm.add_parameter("Iteration log", iteration_log,
                      "Print the relative interface residual of every coupling iteration (to see "
                      "how a time step converges, or why it does not).");
    prm.add_parameter(
      "Face average displacement", face_average_displacement,
      "false: the solid's interface vertex displacements are its vertex values, the "
      "least-squares reconstruction from cell centres and boundary faces (App. B, the "
      "paper's). true: each interface vertex takes the inverse-distance average of the "
      "displacements of the interface faces round it (on the interface's rim, the vertex "
      "values), the displacement the fluid traction acts on in the solid: it keeps the thin "
      "tube wall with its heavy fluid stable at small time steps, where the vertex values "
      "oscillate from step to step (doc/results/fsi_3d.md).");
    prm.leave_subsection();
  }
} // namespace fvfsi
