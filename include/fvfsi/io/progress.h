#pragma once
// Progress of a long run for its log: the wall time since the run started and an estimate of the
// time left, from the mean time per step of the current phase (an FSI run's coupled steps cost
// several fluid-alone steps each).

#include <deal.II/base/timer.h>

#include <sstream>
#include <string>

namespace fvfsi
{
  class Progress
  {
  public:
    /// `step` of `n_steps` done: "elapsed 12.3 s, about 4.5 min left", from the mean time per
    /// step since the current phase began.
    std::string elapsed_and_left(const unsigned int step, const unsigned int n_steps) const
    {
      return "elapsed " + duration(timer.wall_time()) + ", " +
             (step > phase_step
                ? "about " + duration(seconds_per_step(step) * (n_steps - step)) + " left"
                : std::string("time left: estimated from the next steps"));
    }

    /// `step` done, a costlier phase begins after step `until` (an FSI run's coupling): "elapsed
    /// 12.3 s, about 20 s to step 2667", at the rate of the steps so far.
    std::string elapsed_and_until(const unsigned int step, const unsigned int until) const
    {
      return "elapsed " + duration(timer.wall_time()) + ", about " +
             duration(seconds_per_step(step) * (until - step)) + " to step " +
             std::to_string(until);
    }

    /// From after `step` on the steps cost differently: the estimates use those steps only.
    void new_phase(const unsigned int step)
    {
      phase_step = step;
      phase_start = timer.wall_time();
    }

  private:
    static std::string duration(const double seconds)
    {
      std::ostringstream text;
      text.precision(3);
      if (seconds < 120)
        text << seconds << " s";
      else if (seconds < 7200)
        text << seconds / 60 << " min";
      else
        text << seconds / 3600 << " h";
      return text.str();
    }

    double seconds_per_step(const unsigned int step) const
    {
      return step > phase_step ? (timer.wall_time() - phase_start) / (step - phase_step) : 0;
    }

    dealii::Timer timer;
    unsigned int phase_step = 0; ///< the last step before the current phase
    double phase_start = 0;      ///< wall time at its end [s]
  };
} // namespace fvfsi
