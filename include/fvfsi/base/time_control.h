#pragma once
// The one clock of a scene: time t, time step dt, step number, end time, and the coefficients of
// the backward-difference time derivative (paper Eqs 17-18). The scene owns it and advances it;
// the fluid, the solid, the mesh motion and the coupling loop read it.
//
//   du/dt (t^(n+1)) ~ c0 u^(n+1) - c1 u^n + c2 u^(n-1)
//
// The first step is backward Euler (c0 = c1 = 1/dt, c2 = 0), every later one BDF2 (`Time/Scheme =
// BDF2`, the paper's) or backward Euler again (`Time/Scheme = backward Euler`); with steps of
// different size (dt = t^(n+1) - t^n, dt_o = t^n - t^(n-1), omega = dt / dt_o)
//   c0 = (1 + 2 omega) / ((1 + omega) dt),  c1 = (1 + omega) / dt,  c2 = omega^2 / ((1 + omega) dt),
// which for equal steps are 3/(2 dt), 2/dt, 1/(2 dt). Always c1 = c0 + c2 (a constant has zero
// derivative), which the discrete space conservation law of the moving fluid mesh relies on.

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>

namespace fvfsi
{
  /// The life cycle every solver of a scene has (the fluid, the solid): the scene advances the
  /// clock, then calls begin_time_step(), solve_current_step() (repeatable: a coupling solves the
  /// step again with new data from the other side), end_time_step(). A coupling loop calls the
  /// solvers through this interface alone.
  class TimeSteppingSolver
  {
  public:
    virtual ~TimeSteppingSolver() = default;
    /// Move to the clock's time level.
    virtual void begin_time_step() = 0;
    /// Solve the current time level (again).
    virtual void solve_current_step() = 0;
    /// Accept the solution of the time level.
    virtual void end_time_step() = 0;
    /// The three in a row, for a scene that solves each step once.
    void solve_time_step()
    {
      begin_time_step();
      solve_current_step();
      end_time_step();
    }
  };

  /// `subsection Time` of a .prm file.
  struct TimeParameters
  {
    double time_step = 1e-3; ///< dt [s]
    double end_time = 1;     ///< [s]
    /// Times a failed time step is tried again with half its dt (0: a failed step stops the run).
    unsigned int halvings = 0;
    /// Stop after this many time steps, and a steady solve after this many iterations (pseudo
    /// time steps, outer or coupling iterations), as if the run had converged (0: no limit).
    /// From the command line (`fvfsi CASE.prm --steps N`), not from the .prm file: for trying a
    /// case, and for tests that run every shipped case for a few steps.
    unsigned int step_limit = 0;
    /// The time derivative after the first step: "BDF2" (second order) or "backward Euler".
    std::string scheme = "BDF2";
    /// Adaptive time steps (fluid and FSI scenes): "none", "Courant" (the largest Courant
    /// number held at max_courant) or "error" (the step's error estimate held at
    /// error_tolerance). `Time step` is then the first step.
    std::string adaptive = "none";
    double max_courant = 1;        ///< Adaptive = Courant: the target (OpenFOAM's maxCo)
    double error_tolerance = 1e-3; ///< Adaptive = error: the target of the error estimate
    double max_time_step = 1e10;   ///< adaptive steps stay below this [s]
    double max_step_growth = 1.2;  ///< ... and grow by at most this factor per step
    void declare(dealii::ParameterHandler& prm);
  };

  /// du/dt ~ c0 u^(n+1) - c1 u^n + c2 u^(n-1) [1/s].
  struct BdfCoefficients
  {
    double c0 = 0, c1 = 0, c2 = 0;
  };

  class TimeControl
  {
  public:
    explicit TimeControl(const TimeParameters& parameters);
    TimeControl(double time_step, double end_time, unsigned int step_limit = 0);

    /// Move to the next time level: step + 1, t += dt. The solvers then solve for t.
    void advance();
    /// Take `dt` from the next advance() on [s].
    void set_time_step(double dt) { next_dt = dt; }
    /// Adaptive time steps: the next dt from the step just solved, its largest Courant number
    /// and its error estimate (the one the mode reads), within the growth limit, below Max time
    /// step, and ending on the end time rather than a sliver short of it. No-op if not adaptive.
    void adapt_time_step(double courant, double error);
    /// The weights (w1, w2) of the extrapolation u^(n+1) ~ w1 u^n + w2 u^(n-1) to the step being
    /// solved, exact for linear functions of time with the present step ratio omega = dt / dt_o:
    /// (1 + omega, -omega); (1, 0) on the first step.
    std::pair<double, double> extrapolation_weights() const;

    double time() const { return t; }                    ///< t^(n+1) of the step being solved [s]
    double previous_time() const { return t - dt; }      ///< t^n [s]
    double time_step() const { return dt; }              ///< dt of the step being solved [s]
    double previous_time_step() const { return dt_old; } ///< t^n - t^(n-1) [s] (0: none)
    unsigned int step() const { return step_number; }    ///< 0 before the first advance()
    double end_time() const { return end; }
    /// The number of the step that reaches the end time (to a millionth of a step, as at_end()
    /// counts) if dt stays what it is now, at most the step limit: before the first step the
    /// number of steps of the run (0.1 s with dt = 0.03 s: 4, the last one ending at 0.12 s),
    /// and the right total also after a restart or a halved time step.
    unsigned int last_step() const;
    /// True once t has reached the end time (to a millionth of a step), or the step limit.
    bool at_end() const { return t >= end - 1e-6 * dt || step_limit_reached(step_number); }
    /// True if iteration or step `k` is the last one the step limit (--steps) allows.
    bool step_limit_reached(const unsigned int k) const { return limit > 0 && k >= limit; }

    /// Backward Euler on the first step, BDF2 (variable-step) after, unless the scheme is
    /// backward Euler throughout.
    BdfCoefficients bdf() const;

    /// "time step N (t = T s)", for messages.
    std::string step_name() const;

    /// Save or load the clock's state for a checkpoint (Boost serialization): the time, the
    /// steps and the step number; the end time stays the one of the .prm file, so that a restart
    /// can run further than the run it continues.
    template <class Archive>
    void serialize(Archive& ar, const unsigned int /*version*/)
    {
      ar& t& dt& dt_old& next_dt& step_number;
    }

  private:
    enum class Adaptive
    {
      none,
      courant,
      error
    };
    Adaptive mode = Adaptive::none; // TimeParameters::adaptive and its limits, from the .prm file
    double max_courant = 1, error_tolerance = 1e-3, max_dt = 1e10, growth = 1.2;
    double t = 0, dt, dt_old = 0, next_dt, end;
    unsigned int step_number = 0;
    unsigned int limit;      // TimeParameters::step_limit; not saved in a checkpoint
    bool euler_only = false; // TimeParameters::scheme; from the .prm file, not saved
  };
} // namespace fvfsi
