#pragma once
// Algorithm 1 of the paper (section 3.4): the strongly coupled Dirichlet-Neumann iteration of a
// time step, apart from the physics. It sees the fluid and the solid only as one operator on the
// interface displacement,
//
//   d -> d~ = S(F(d))   (the scene's part: move the fluid mesh to d, solve the fluid, hand its
//                        wall tractions to the solid, solve the solid, read its interface
//                        displacement; FsiScene::coupling_iteration),
//
// and keeps the interface displacements of the accepted time levels, d^n and d^(n-1):
//
//   1. begin_time_step(): the predictor, linear extrapolation to the new time level,
//      d = d^n + omega (d^n - d^(n-1)), omega = dt / dt_old (2 d^n - d^(n-1) for equal steps);
//   2. converge(): d <- method(d, S(F(d))) (Eqs 30-31; coupling/coupling_method.h: fixed,
//      Aitken, IQN-ILS, IQN-IMVJ) until the method's convergence test holds;
//   3. end_time_step(): d is accepted as d^(n+1).
//
// A steady coupled solve is step 2 alone (no predictor, no time levels).

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <fvfsi/base/time_control.h>
#include <fvfsi/base/time_levels.h>
#include <fvfsi/coupling/coupling_method.h>

#include <functional>
#include <memory>
#include <string>

namespace fvfsi
{
  class PartitionedCoupling
  {
  public:
    /// d -> d~ = S(F(d)) [m].
    using InterfaceOperator = std::function<InterfaceVector(const InterfaceVector&)>;
    /// Called after coupling iteration k with its relative residual; returns true to accept d
    /// there, converged or not (a steady run's iteration limit).
    using IterationObserver = std::function<bool(unsigned int k, double residual)>;

    /// An interface of n_values displacement values (points x dim), d = 0 at every level; the
    /// method's updates timed as "acceleration" in `timer` (if given).
    PartitionedCoupling(const CouplingParameters& parameters, unsigned int n_values,
                        const dealii::ConditionalOStream& pcout,
                        dealii::TimerOutput* timer = nullptr);

    /// 1: the predictor from the accepted time levels and the clock's step ratio.
    void begin_time_step(const TimeControl& clock);
    /// 2: coupling iterations from d until the method's convergence test holds; returns their
    /// number (d is then the accepted displacement, and the solvers' states belong to it).
    /// `step_name` and `hint` go into the error messages of a failed iteration.
    unsigned int converge(const InterfaceOperator& fluid_then_solid, const std::string& step_name,
                          const std::string& hint = "", const IterationObserver& observer = {});
    /// 3: d becomes d^(n+1).
    void end_time_step();

    /// The interface displacement of the present iteration (or the accepted one) [m].
    const InterfaceVector& displacement() const { return d; }
    /// Set it (a steady run starting from an earlier run's state).
    void set_displacement(const InterfaceVector& displacement) { d = displacement; }
    /// The relative interface residual of the last iteration.
    double relative_residual() const { return method->relative_residual(); }
    /// What to change when the iterations diverge or stall, for the method in use.
    std::string advice() const { return method->advice(); }
    /// Save or load the displacements of the time levels and the method's state.
    void checkpoint(GlobalArchive& archive);

  private:
    const CouplingParameters prm;
    dealii::ConditionalOStream pcout;
    dealii::TimerOutput* timer;
    std::unique_ptr<CouplingMethod> method;
    /// Interface displacement at the fluid interface vertices at t^(n+1) [m], and its old levels
    /// at t^n, t^(n-1) (d_levels.o, d_levels.oo).
    InterfaceVector d;
    TimeLevels<InterfaceVector> d_levels;
  };
} // namespace fvfsi
