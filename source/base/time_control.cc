#include <fvfsi/base/patterns.h>
#include <fvfsi/base/time_control.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fvfsi
{
  void TimeParameters::declare(dealii::ParameterHandler& prm)
  {
    prm.enter_subsection("Time");
    prm.add_parameter(
      "Time step", time_step,
      "dt [s] of a transient run: the fluid, the solid, the mesh motion and the "
      "coupling share it (a steady solver ignores it; a steady solid takes one step).",
      PositiveDouble(1e10));
    prm.add_parameter("End time", end_time,
                      "[s] of a transient run: it takes steps until t reaches the end time, so "
                      "the last step ends past it when the end time is not a whole number of "
                      "steps (0.1 s with dt = 0.03 s: 4 steps, to 0.12 s).",
                      dealii::Patterns::Double(0, 1e10));
    prm.add_parameter("Time step control", halvings,
                      "FSI: how many times a failed time step (a linear solve that fails, a "
                      "field that is not finite, coupling or solid iterations that do not "
                      "converge) is tried again from its start with half the time step; the "
                      "run continues with the smaller one (column dt of fsi_history.txt). "
                      "0: off, a failed step stops the run (after writing the last converged "
                      "state).",
                      dealii::Patterns::Integer(0, 20));
    prm.add_parameter(
      "Scheme", scheme,
      "The time derivative (fluid, solid, mesh flux; the first step is always backward "
      "Euler): BDF2, second order (paper Eqs 17-18), or backward Euler, first order and "
      "strongly damping.",
      dealii::Patterns::Selection("BDF2|backward Euler"));
    prm.add_parameter(
      "Adaptive", adaptive,
      "Fluid and FSI scenes: none (Time step throughout), Courant (each step from the last one's "
      "largest Courant number: dt <- dt x Max Courant number / Co, as OpenFOAM's adjustTimeStep "
      "with maxCo) or error (each step from the last one's error estimate e = max |u - u_p| / U, "
      "u_p the extrapolation of the last two steps to the new time, U the fluid's velocity scale: "
      "dt <- 0.9 dt sqrt(Error tolerance / e), e being of order dt^2). Time step is then the first "
      "step; a step grows by at most Max step growth, shrinks by at most a factor 5, and the "
      "BDF2 coefficients follow the step ratio exactly (variable-step BDF2, stable for ratios "
      "below 1 + sqrt 2). The column dt of the history holds the steps taken.",
      dealii::Patterns::Selection("none|Courant|error"));
    prm.add_parameter("Max Courant number", max_courant,
                      "Adaptive = Courant: the largest Courant number dt sum_f |phi_f| / (2 V_P) "
                      "to hold.",
                      PositiveDouble(1e6));
    prm.add_parameter("Error tolerance", error_tolerance,
                      "Adaptive = error: the error estimate e to hold (relative to the fluid's "
                      "velocity scale).",
                      PositiveDouble(1));
    prm.add_parameter("Max time step", max_time_step, "Adaptive: the largest time step [s].",
                      PositiveDouble(1e10));
    prm.add_parameter("Max step growth", max_step_growth,
                      "Adaptive: the largest ratio of a time step to the one before.",
                      dealii::Patterns::Double(1, 2.4));
    prm.leave_subsection();
  }

  TimeControl::TimeControl(const TimeParameters& parameters)
      : TimeControl(parameters.time_step, parameters.end_time, parameters.step_limit)
  {
    euler_only = parameters.scheme == "backward Euler";
    mode = parameters.adaptive == "Courant" ? Adaptive::courant
           : parameters.adaptive == "error" ? Adaptive::error
                                            : Adaptive::none;
    max_courant = parameters.max_courant;
    error_tolerance = parameters.error_tolerance;
    max_dt = parameters.max_time_step;
    growth = parameters.max_step_growth;
  }

  void TimeControl::adapt_time_step(const double courant, const double error)
  {
    if (mode == Adaptive::none)
      return;
    // The factor that would bring the measure to its target: the Courant number is linear in
    // dt, the error estimate quadratic (with a safety factor 0.9: its constant is not known).
    const double factor = mode == Adaptive::courant
                            ? max_courant / std::max(courant, 1e-12)
                            : 0.9 * std::sqrt(error_tolerance / std::max(error, 1e-300));
    double next = std::min(dt * std::clamp(factor, 0.2, growth), max_dt);
    // The end time: one step to it rather than a step and a sliver.
    const double left = end - t;
    if (left > 0 && left < 1.5 * next)
      next = left < next ? left : left / std::ceil(left / next - 1e-9);
    next_dt = std::max(next, 1e-6 * dt);
  }

  std::pair<double, double> TimeControl::extrapolation_weights() const
  {
    if (step_number <= 1 || dt_old == 0)
      return {1, 0};
    const double omega = dt / dt_old;
    return {1 + omega, -omega};
  }

  TimeControl::TimeControl(const double time_step, const double end_time,
                           const unsigned int step_limit)
      : dt(time_step), next_dt(time_step), end(end_time), limit(step_limit)
  {
    if (!(time_step > 0))
      throw std::runtime_error("Time/Time step must be positive (it is " +
                               std::to_string(time_step) + ")");
    // The step counter is an unsigned int: a run of more than a billion steps is a typo.
    if (!(end_time / time_step < 1e9))
    {
      std::ostringstream message;
      message << "Time/End time / Time/Time step = " << end_time << " s / " << time_step
              << " s: more than 1e9 time steps";
      throw std::runtime_error(message.str());
    }
  }

  void TimeControl::advance()
  {
    if (step_number > 0)
      dt_old = dt;
    dt = next_dt;
    t += dt;
    ++step_number;
  }

  unsigned int TimeControl::last_step() const
  {
    // k more steps of next_dt reach the end time when t + k next_dt >= end - 1e-6 next_dt.
    const double steps_left = std::max(0.0, std::ceil((end - t) / next_dt - 1e-6));
    const auto n = step_number + static_cast<unsigned int>(steps_left);
    return limit > 0 ? std::min(n, limit) : n;
  }

  std::string TimeControl::step_name() const
  {
    std::ostringstream name;
    name << "time step " << step_number << " (t = " << t << " s)";
    return name.str();
  }

  BdfCoefficients TimeControl::bdf() const
  {
    if (step_number <= 1 || euler_only)
      return {1 / dt, 1 / dt, 0};
    const double omega = dt / dt_old;
    return {(1 + 2 * omega) / ((1 + omega) * dt), (1 + omega) / dt,
            omega * omega / ((1 + omega) * dt)};
  }
} // namespace fvfsi
