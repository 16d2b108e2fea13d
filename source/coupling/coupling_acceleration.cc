#include <fvfsi/coupling/coupling_acceleration.h>

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  const SelectionNames<CouplingParameters::Method> CouplingParameters::method_names = {
    {"fixed", Method::fixed}, {"Aitken", Method::aitken}, {"IQN-ILS", Method::iqn_ils}};

  void CouplingParameters::declare(ParameterHandler& prm)
  {
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
                  "relaxation) or IQN-ILS (interface quasi-Newton, least-squares Jacobian).");
    prm.add_parameter("Relaxation", relaxation,
                      "omega of fixed relaxation (Eq. 31), also of the fixed iterations that start "
                      "every time step of Aitken and IQN-ILS.",
                      Patterns::Double(0, 1));
    prm.add_parameter("Fixed iterations", fixed_iterations,
                      "Aitken and IQN-ILS: fixed-relaxation iterations at the start of every time "
                      "step (the paper uses 2; IQN-ILS needs at least 1).",
                      Patterns::Integer(1));
    prm.add_parameter("Tolerance", tolerance,
                      "A time step has converged when |d~ - d|_2 <= this x |d~|_2 over the "
                      "interface vertices (Eq. 30).",
                      Patterns::Double(0));
    prm.add_parameter("Max iterations", max_iterations,
                      "Coupling iterations per time step before the run stops with an error.",
                      Patterns::Integer(1));
    prm.add_parameter("Reuse time steps", reuse_time_steps,
                      "IQN-ILS: also use the columns of this many earlier time steps (0: none).",
                      Patterns::Integer(0, 20));
    prm.add_parameter(
      "Start time", start_time,
      "Time [s] from which fluid and solid are coupled. Before it the solid is held "
      "in its initial state (at rest) and the fluid runs alone on the fixed mesh, "
      "as the paper does for Turek-Hron FSI2/FSI3 (full inflow from the first "
      "step, coupling from 2 s): the flow develops without an impulsive load on "
      "the solid. 0: coupled from the first time step.",
      Patterns::Double(0));
    prm.leave_subsection();
  }

  CouplingAcceleration::CouplingAcceleration(const CouplingParameters& parameters)
      : prm(parameters), omega(parameters.relaxation), model(/*filter=*/1e-2)
  {
  }

  void CouplingAcceleration::new_time_step()
  {
    ++time_step;
    iteration = 0;
    omega = prm.relaxation;
    previous_r.reinit(0);
    previous_d_tilde.reinit(0);
    // Drop IQN-ILS columns older than the reuse window.
    if (time_step > prm.reuse_time_steps)
      model.drop_tagged_before(time_step - prm.reuse_time_steps);
  }

  InterfaceVector CouplingAcceleration::next(const InterfaceVector& d,
                                             const InterfaceVector& d_tilde)
  {
    ++iteration;
    InterfaceVector r = d_tilde;
    r -= d;
    last_relative_residual = r.l2_norm() / std::max(d_tilde.l2_norm(), 1e-300);

    InterfaceVector result;
    bool accelerated = false;
    if (prm.method == CouplingParameters::Method::iqn_ils)
    {
      if (previous_r.size() > 0)
      {
        InterfaceVector V = r, W = d_tilde;
        V -= previous_r;
        W -= previous_d_tilde;
        model.add_column(V, W, time_step);
      }
      // Columns kept from earlier time steps already model the Jacobian: no fixed start then.
      const bool reused = model.size() > 0 && model.oldest_tag() < time_step;
      if (iteration > prm.fixed_iterations || reused)
      {
        // d <- d~ + W c, c = argmin |r + V c|.
        result = d_tilde;
        InterfaceVector correction(r.size());
        accelerated = model.correction(r, correction);
        if (accelerated)
          result += correction;
      }
    }
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
} // namespace fvfsi
