#pragma once
// The strongly coupled linear interface model of tests/coupling/coupling_acceleration and
// coupling_imvj: the solid's answer d~ = A d + b with A symmetric, its n eigenvalues spread evenly
// over [-3, 0.5] (below -1: what strong added mass does to a Dirichlet-Neumann iteration), and the
// coupling iteration on it.
#include <fvfsi/coupling/coupling_method.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace fvfsi_test
{
  /// A = Q diag(lambda) Q^T with Q a Householder reflection I - 2 v v^T / v.v.
  struct LinearInterfaceModel
  {
    unsigned int n;
    std::vector<double> lambda, v;
    explicit LinearInterfaceModel(const unsigned int n) : n(n)
    {
      for (unsigned int i = 0; i < n; ++i)
      {
        lambda.push_back(-3 + 3.5 * i / (n - 1));
        v.push_back(std::sin(1.0 + i) + 0.3);
      }
    }
    std::vector<double> reflect(const std::vector<double>& x) const
    {
      double vx = 0, vv = 0;
      for (unsigned int i = 0; i < n; ++i)
      {
        vx += v[i] * x[i];
        vv += v[i] * v[i];
      }
      std::vector<double> y = x;
      for (unsigned int i = 0; i < n; ++i)
        y[i] -= 2 * vx / vv * v[i];
      return y;
    }
    std::vector<double> solid_answer(const std::vector<double>& d,
                                     const std::vector<double>& b) const
    {
      std::vector<double> y = reflect(d);
      for (unsigned int i = 0; i < n; ++i)
        y[i] *= lambda[i];
      y = reflect(y);
      for (unsigned int i = 0; i < n; ++i)
        y[i] += b[i];
      return y;
    }
    /// The fixed point d = A d + b: d = Q diag(1 / (1 - lambda)) Q^T b.
    std::vector<double> solution(const std::vector<double>& b) const
    {
      std::vector<double> y = reflect(b);
      for (unsigned int i = 0; i < n; ++i)
        y[i] /= 1 - lambda[i];
      return reflect(y);
    }
  };

  /// One time step: iterations of `model` (a LinearInterfaceModel or one like it) until
  /// CouplingMethod::converged(), or 0 if not within
  /// `max_iterations` (or diverged); d is the start and the result.
  template <typename Model>
  unsigned int solve(fvfsi::CouplingMethod& acceleration, const Model& model,
                     const std::vector<double>& b, std::vector<double>& d,
                     const unsigned int max_iterations = 400)
  {
    acceleration.new_time_step();
    for (unsigned int k = 1; k <= max_iterations; ++k)
    {
      const std::vector<double> d_tilde = model.solid_answer(d, b);
      const fvfsi::InterfaceVector next =
        acceleration.next(fvfsi::InterfaceVector(d.begin(), d.end()),
                          fvfsi::InterfaceVector(d_tilde.begin(), d_tilde.end()));
      d.assign(next.begin(), next.end());
      if (acceleration.converged())
        return k;
      if (!(acceleration.relative_residual() < 1e6))
        return 0;
    }
    return 0;
  }

} // namespace fvfsi_test
