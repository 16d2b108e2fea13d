// The steady mode's driver (Fluid/Transient = false): pseudo time steps until the solution stops
// changing, with the relaxation lowered where the iteration stalls.

#include <deal.II/base/mpi.h>

#include <fvfsi/base/exceptions.h>
#include <fvfsi/fluid/fluid_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    // The steady iteration's progress check: the pseudo steps are taken in windows of this
    // many; a window whose geometric mean of the relative change is not 5% below the best window
    // since alpha was set has made no progress. A converging iteration may be slow and uneven
    // (the cavity at h = 0.0125 falls by 3% in one window and 25% in the next), so alpha is
    // lowered only after stall_windows windows in a row without progress; it is not lowered
    // below minimum_relaxation.
    constexpr unsigned int steady_window = 50;
    constexpr unsigned int stall_windows = 2;
    constexpr double minimum_relaxation = 0.3;

    double geometric_mean(const std::vector<double>& changes)
    {
      double log_sum = 0;
      for (const double c : changes)
        log_sum += std::log(std::max(c, 1e-300));
      return std::exp(log_sum / changes.size());
    }

    /// "oscillates between a and b" or "stagnates at c": the relative changes of a window.
    std::string describe_changes(const std::vector<double>& changes)
    {
      const auto [low, high] = std::minmax_element(changes.begin(), changes.end());
      return *high > 2 * *low
               ? "oscillates between " + three_digits(*low) + " and " + three_digits(*high)
               : "stagnates at " + three_digits(geometric_mean(changes));
    }
  } // namespace

  template <int dim>
  unsigned int FluidSolver<dim>::solve_steady()
  {
    double change = 0;
    double best_mean = -1;      // the smallest window mean since alpha was set (-1: none yet)
    unsigned int stalls = 0;    // windows in a row without progress
    std::vector<double> window; // the changes of the current window
    for (unsigned int k = 1; k <= prm.max_steady_iterations; ++k)
    {
      ++pseudo_step;
      solve_piso_step();
      end_time_step();
      change = last_change;
      if (k % 100 == 0)
        pcout << "fvfsi: fluid pseudo time step " << k << ": relative change " << change
              << " (tolerance " << prm.steady_tolerance << "), continuity error "
              << continuity_error() << "\n";
      if (change < prm.steady_tolerance || clock.step_limit_reached(k))
        return k;
      window.push_back(change);
      if (window.size() < steady_window)
        continue;
      const double mean = geometric_mean(window);
      const bool progress = best_mean < 0 || mean < 0.95 * best_mean;
      if (progress)
        best_mean = mean;
      stalls = progress ? 0 : stalls + 1;
      if (stalls < stall_windows)
      {
        window.clear(); // progress, or not yet long enough without: go on
        continue;
      }
      // No progress over stall_windows windows: a smaller pseudo time step, or give up.
      const double lowered = 1 - std::max(2 * (1 - relaxation), 0.05); // 1, 0.95, 0.9, 0.8, 0.6
      if (lowered < minimum_relaxation)
        throw std::runtime_error(
          "Fluid: the steady solution does not converge: no progress in " +
          std::to_string(stall_windows * steady_window) + " pseudo time steps; over the last " +
          std::to_string(steady_window) + " pseudo time steps (to " + std::to_string(k) +
          ") the relative change " + describe_changes(window) + " at Momentum relaxation " +
          three_digits(relaxation) + " (lowered from " + three_digits(prm.momentum_relaxation) +
          "); the flow may have no steady state (e.g. vortex shedding): run it with "
          "Fluid/Transient = true");
      pcout << "fvfsi: fluid steady: the relative change " << describe_changes(window)
            << " over pseudo steps " << k - steady_window + 1 << "-" << k << " (no progress in "
            << stall_windows * steady_window << " pseudo steps)"
            << ": Momentum relaxation lowered from " << relaxation << " to " << lowered << "\n";
      relaxation = lowered;
      best_mean = -1;
      stalls = 0;
      window.clear();
    }
    throw std::runtime_error("Fluid: the steady solution did not converge in " +
                             std::to_string(prm.max_steady_iterations) +
                             " pseudo time steps (relative change " + Utilities::to_string(change) +
                             ", still falling); raise Fluid/Max steady iterations");
  }

  template unsigned int FluidSolver<2>::solve_steady();
  template unsigned int FluidSolver<3>::solve_steady();
} // namespace fvfsi
