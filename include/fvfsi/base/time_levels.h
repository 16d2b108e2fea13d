#pragma once
// The old time levels of one field, u^o = u^n and u^oo = u^(n-1), and what a solver does with
// them: shift them at the end of a step, extrapolate to the step being solved, take the BDF time
// derivative. The step sizes and so the weights come from the one clock (TimeControl), so that
// every solver (the fluid's u, F and moving geometry, the solid's u and v, the FSI predictor's
// interface displacement d, the tutorials' fields) uses the same history after a change of dt:
//
//   extrapolated:  u^(n+1) ~ w1 u^o + w2 u^oo,            (w1, w2) = clock.extrapolation_weights()
//   derivative:    du/dt(t^(n+1)) ~ c0 u - c1 u^o + c2 u^oo,   (c0, c1, c2) = clock.bdf()  (Eqs 17-18)
//
// T is any field indexed by a cell, face or entry number (CellVectorField, FaceVector, a
// std::vector of tensors, dealii::Vector); the present level u stays the solver's own member.

#include <fvfsi/base/time_control.h>

#include <utility>

namespace fvfsi
{
  template <class T>
  class TimeLevels
  {
  public:
    T o;  ///< u^o = u^n, the last accepted level
    T oo; ///< u^oo = u^(n-1)

    /// Every old level equal to `now` (the first step, or a steady state taken as the start).
    void start(const T& now)
    {
      o = now;
      oo = now;
    }
    /// The end of a step: u^oo <- u^o, u^o <- now.
    void shift(const T& now)
    {
      oo = o;
      o = now;
    }
    /// The same where the new level is written in place (e.g. from the geometry): u^oo <- u^o;
    /// returns u^o for the caller to fill.
    T& shift()
    {
      oo = o;
      return o;
    }
    /// Apply f to each old level (e.g. to update ghost values, or to save them).
    template <class Function>
    void for_each(Function f)
    {
      f(o);
      f(oo);
    }

    /// w1 u^o_i + w2 u^oo_i: entry i extrapolated to the step being solved.
    template <class Index>
    auto extrapolated(const std::pair<double, double>& w, const Index i) const
    {
      return w.first * o[i] + w.second * oo[i];
    }
    /// c0 u_i - c1 u^o_i + c2 u^oo_i: the BDF time derivative of entry i (Eqs 17-18).
    template <class Index, class Value>
    auto derivative(const BdfCoefficients& c, const Value& u_i, const Index i) const
    {
      return c.c0 * u_i - c.c1 * o[i] + c.c2 * oo[i];
    }
  };
} // namespace fvfsi
