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
    prm.leave_subsection();
  }

  TimeControl::TimeControl(const TimeParameters& parameters)
      : TimeControl(parameters.time_step, parameters.end_time, parameters.step_limit)
  {
    euler_only = parameters.scheme == "backward Euler";
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
