#include <fvfsi/base/patterns.h>
#include <fvfsi/coupling/coupling_acceleration.h>

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  const SelectionNames<CouplingParameters::Method> CouplingParameters::method_names = {
    {"fixed", Method::fixed},
    {"Aitken", Method::aitken},
    {"IQN-ILS", Method::iqn_ils},
    {"IQN-IMVJ", Method::iqn_imvj}};

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
    add_selection(prm, "Method", method, method_names,
                  "How the interface displacement is updated between the fluid and solid "
                  "solves of a time step (Algorithm 1): fixed (relaxation), Aitken (dynamic "
                  "relaxation), IQN-ILS (interface quasi-Newton, least-squares inverse Jacobian of "
                  "the step's iterations) or IQN-IMVJ (interface quasi-Newton, multi-vector "
                  "inverse Jacobian carried from time step to time step).");
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

  CouplingAcceleration::CouplingAcceleration(const CouplingParameters& parameters)
      : prm(parameters), omega(parameters.relaxation), model(parameters.qr_filter),
        jacobian(parameters.imvj_dense_limit, parameters.imvj_time_steps)
  {
  }

  void CouplingAcceleration::new_time_step()
  {
    ++time_step;
    iteration = 0;
    omega = prm.relaxation;
    previous_r.reinit(0);
    previous_d_tilde.reinit(0);
    largest_residual = 0;
    if (prm.method == CouplingParameters::Method::iqn_imvj)
    {
      // J_prev <- J_prev + (W - J_prev V) V^+ with the last step's columns.
      if (model.size() > 0)
      {
        const auto secants = model.kept_secants();
        jacobian.update(secants.dR, secants.dX, secants.Z);
      }
      model.clear();
    }
    // Drop IQN-ILS columns older than the reuse window.
    else if (time_step > prm.reuse_time_steps)
      model.drop_tagged_before(time_step - prm.reuse_time_steps);
  }

  bool CouplingAcceleration::converged() const
  {
    return last_relative_residual <= prm.tolerance ||
           (prm.residual_reduction > 0 &&
            last_residual <= prm.residual_reduction * largest_residual);
  }

  InterfaceVector CouplingAcceleration::next(const InterfaceVector& d,
                                             const InterfaceVector& d_tilde)
  {
    ++iteration;
    InterfaceVector r = d_tilde;
    r -= d;
    last_residual = r.l2_norm();
    largest_residual = std::max(largest_residual, last_residual);
    last_relative_residual = last_residual / std::max(d_tilde.l2_norm(), 1e-300);

    InterfaceVector result;
    bool accelerated = false;
    const bool iqn = prm.method == CouplingParameters::Method::iqn_ils ||
                     prm.method == CouplingParameters::Method::iqn_imvj;
    if (iqn && previous_r.size() > 0)
    {
      InterfaceVector V = r, W = d_tilde;
      V -= previous_r;
      W -= previous_d_tilde;
      model.add_column(V, W, time_step);
    }
    if (prm.method == CouplingParameters::Method::iqn_ils)
      accelerated = iqn_ils_update(r, d_tilde, result);
    else if (prm.method == CouplingParameters::Method::iqn_imvj)
      accelerated = iqn_imvj_update(r, d_tilde, result);
    else if (prm.method == CouplingParameters::Method::aitken && iteration > prm.fixed_iterations &&
             previous_r.size() > 0)
    {
      InterfaceVector dr = r;
      dr -= previous_r;
      const double dr2 = dr * dr;
      if (dr2 > 0)
        omega = -omega * (previous_r * dr) / dr2;
    }
    if (!accelerated)
    {
      const double w = prm.method == CouplingParameters::Method::aitken ? omega : prm.relaxation;
      result = d;
      result.add(w, r);
    }
    previous_r = r;
    previous_d_tilde = d_tilde;
    return result;
  }

  bool CouplingAcceleration::iqn_ils_update(const InterfaceVector& r,
                                            const InterfaceVector& d_tilde,
                                            InterfaceVector& result) const
  {
    // Columns kept from earlier time steps already model the Jacobian: no fixed start then.
    const bool reused = model.size() > 0 && model.oldest_tag() < time_step;
    if (iteration <= prm.fixed_iterations && !reused)
      return false;
    // d <- d~ + W c, c = argmin |r + V c|.
    InterfaceVector correction(r.size());
    if (!model.correction(r, correction))
      return false;
    result = d_tilde;
    result += correction;
    return true;
  }

  bool CouplingAcceleration::iqn_imvj_update(const InterfaceVector& r,
                                             const InterfaceVector& d_tilde,
                                             InterfaceVector& result) const
  {
    // J_prev models the Jacobian already: no fixed start once there is one.
    if (iteration <= prm.fixed_iterations && jacobian.empty())
      return false;
    // d <- d~ - J r = d~ + W c - J_prev (r + V c), c = argmin |r + V c| (W c = correction,
    // V c = fitted).
    InterfaceVector correction(r.size()), fitted(r.size()), rest = r;
    const bool columns = model.correction(r, correction, &fitted);
    if (!columns && jacobian.empty())
      return false;
    result = d_tilde;
    if (columns)
    {
      result += correction;
      rest += fitted;
    }
    InterfaceVector J_rest;
    jacobian.vmult(J_rest, rest);
    result -= J_rest;
    return true;
  }
} // namespace fvfsi
