#include <deal.II/base/utilities.h>

#include <fvfsi/coupling/partitioned_coupling.h>

#include <cmath>
#include <optional>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  PartitionedCoupling::PartitionedCoupling(const CouplingParameters& parameters,
                                           const unsigned int n_values,
                                           const ConditionalOStream& pcout, TimerOutput* timer)
      : prm(parameters), pcout(pcout), timer(timer), method(CouplingMethod::create(parameters)),
        d(n_values)
  {
    d_levels.start(d);
  }

  void PartitionedCoupling::begin_time_step(const TimeControl& clock)
  {
    d = d_levels.o;
    if (clock.step() > 2)
    {
      // d^n + omega (d^n - d^(n-1)), omega = dt / dt_old: 2 d^n - d^(n-1) for equal steps; the
      // clock's weights, which the fluid's extrapolated state and the error estimate use too.
      const auto w = clock.extrapolation_weights();
      for (unsigned int i = 0; i < d.size(); ++i)
        d[i] = d_levels.extrapolated(w, i);
    }
  }

  void PartitionedCoupling::end_time_step()
  {
    d_levels.shift(d);
  }

  unsigned int PartitionedCoupling::converge(const InterfaceOperator& fluid_then_solid,
                                             const std::string& step_name, const std::string& hint,
                                             const IterationObserver& observer)
  {
    method->new_time_step();
    double residual = 0;
    for (unsigned int k = 1; k <= prm.max_iterations; ++k)
    {
      InterfaceVector next;
      double d_tilde_norm = 0;
      try
      {
        const InterfaceVector d_tilde = fluid_then_solid(d); // 2a-2e
        d_tilde_norm = d_tilde.l2_norm();
        std::optional<TimerOutput::Scope> scope;
        if (timer)
          scope.emplace(*timer, "acceleration");
        next = method->next(d, d_tilde); // 2f: Eqs 30-31
      }
      catch (const std::exception& e)
      {
        throw std::runtime_error(
          "FSI: at " + step_name + ", coupling iteration " + std::to_string(k) +
          (k > 1
             ? " (relative interface residual before it: " + Utilities::to_string(residual) + ")"
             : std::string()) +
          ": " + e.what() +
          (k > 2 ? "\n(a coupling iteration that diverges ends like this: " + advice() + ")"
                 : std::string()) +
          hint);
      }
      residual = method->relative_residual();
      if (!std::isfinite(residual))
        throw std::runtime_error("FSI: the interface residual is not finite at " + step_name +
                                 ", coupling iteration " + std::to_string(k) + hint);
      const bool stop = observer && observer(k, residual);
      if (!observer && prm.iteration_log)
        pcout << "fvfsi: " << step_name << ", coupling iteration " << k
              << ": relative interface residual " << residual << ", |d| = " << d.l2_norm()
              << " m, |d~| = " << d_tilde_norm << " m\n";
      if (method->converged() || stop)
        return k; // d is the accepted displacement: both solvers' states belong to it
      d = next;
    }
    throw std::runtime_error("FSI: the coupling iterations did not converge at " + step_name +
                             ": relative interface residual " + Utilities::to_string(residual) +
                             " after " + std::to_string(prm.max_iterations) + " iterations (" +
                             advice() + "; or raise Coupling/Max iterations)");
  }

  void PartitionedCoupling::checkpoint(GlobalArchive& archive)
  {
    archive& d& d_levels.o& d_levels.oo;
    method->checkpoint(archive);
  }
} // namespace fvfsi
