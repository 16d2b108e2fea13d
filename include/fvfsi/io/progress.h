#pragma once
// Progress of a long run for its log: the wall time since the run started and an estimate of the
// time left, from the mean time per step so far.

#include <deal.II/base/timer.h>

#include <sstream>
#include <string>

namespace fvfsi
{
  class Progress
  {
  public:
    /// `step` of `n_steps` done: "elapsed 12.3 s, about 4.5 min left".
    std::string elapsed_and_left(const unsigned int step, const unsigned int n_steps) const
    {
      const double elapsed = timer.wall_time();
      const double left = step == 0 ? 0 : elapsed / step * (n_steps - step);
      std::ostringstream text;
      text.precision(3);
      text << "elapsed " << duration(elapsed) << ", about " << duration(left) << " left";
      return text.str();
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

    dealii::Timer timer;
  };
} // namespace fvfsi
