// The one time-level history (base/time_levels.h) with the clock's coefficients, on steps of
// changing size (dt = 0.1, 0.1, 0.05, 0.15, 0.2, 0.02 s: step ratios 1, 0.5, 3, 1.33, 0.1):
//   - extrapolated(): w1 u^o + w2 u^oo is exact for a field linear in time, u = 2 - 3 t, on every
//     step after the first (the FSI predictor and the fluid's linearisation rely on it after a
//     change of dt);
//   - derivative(): c0 u - c1 u^o + c2 u^oo is exact for a quadratic, u = 1 + 2 t - 5 t^2, from
//     the second step on (variable-step BDF2, Eq. 17), first order on the first (backward Euler);
//   - shift() and start() keep the levels in order, for a cell vector field of tensors too.
// Asserted: those errors below 1e-12 (round-off of a few operations on O(1) values), printed as
// passed / failed (the output holds no numbers that round-off could change).
#include <deal.II/base/tensor.h>

#include <fvfsi/base/time_control.h>
#include <fvfsi/base/time_levels.h>

#include "../test_utilities.h"

#include <cmath>
#include <vector>

using namespace fvfsi_test;

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const auto linear = [](const double t) { return 2 - 3 * t; };
  const auto quadratic = [](const double t) { return 1 + 2 * t - 5 * t * t; };
  const auto quadratic_rate = [](const double t) { return 2 - 10 * t; };

  fvfsi::TimeControl clock(0.1, 10);
  // One entry per field: a std::vector<double> and a vector of tensors (component 1 = 2 u).
  std::vector<double> u_linear{linear(0)}, u_quadratic{quadratic(0)};
  std::vector<dealii::Tensor<1, 2>> u_tensor(1);
  u_tensor[0][0] = quadratic(0);
  u_tensor[0][1] = 2 * quadratic(0);
  fvfsi::TimeLevels<std::vector<double>> linear_levels, quadratic_levels;
  fvfsi::TimeLevels<std::vector<dealii::Tensor<1, 2>>> tensor_levels;
  linear_levels.start(u_linear);
  quadratic_levels.start(u_quadratic);
  tensor_levels.start(u_tensor);

  double extrapolation_error = 0, derivative_error = 0, tensor_error = 0, first_step_error = 0;
  for (const double dt : {0.1, 0.1, 0.05, 0.15, 0.2, 0.02})
  {
    clock.set_time_step(dt);
    clock.advance();
    const double t = clock.time();
    const auto w = clock.extrapolation_weights();
    if (clock.step() > 1)
      extrapolation_error =
        std::max(extrapolation_error, std::abs(linear_levels.extrapolated(w, 0) - linear(t)));
    u_linear[0] = linear(t);
    u_quadratic[0] = quadratic(t);
    u_tensor[0][0] = quadratic(t);
    u_tensor[0][1] = 2 * quadratic(t);
    const double rate = quadratic_levels.derivative(clock.bdf(), u_quadratic[0], 0);
    const dealii::Tensor<1, 2> tensor_rate = tensor_levels.derivative(clock.bdf(), u_tensor[0], 0);
    if (clock.step() == 1)
      first_step_error = std::abs(rate - quadratic_rate(t));
    else
      derivative_error = std::max(derivative_error, std::abs(rate - quadratic_rate(t)));
    tensor_error = std::max(
      {tensor_error, std::abs(tensor_rate[0] - rate), std::abs(tensor_rate[1] - 2 * rate)});
    linear_levels.shift(u_linear);
    quadratic_levels.shift(u_quadratic);
    tensor_levels.shift(u_tensor);
  }
  const auto verdict = [](const bool ok) { return ok ? "passed" : "FAILED"; };
  out << "extrapolation exact for a linear field on changing steps: "
      << verdict(extrapolation_error < 1e-12) << "\n"
      << "BDF2 derivative exact for a quadratic on changing steps: "
      << verdict(derivative_error < 1e-12) << "\n"
      << "first step (backward Euler) not exact for the quadratic (error 5 dt = 0.5): "
      << verdict(std::abs(first_step_error - 0.5) < 1e-12) << "\n"
      << "tensor levels give the scalar's derivative per component: "
      << verdict(tensor_error < 1e-12) << "\n"
      << "levels after the last shift are u(t^n), u(t^(n-1)): "
      << verdict(quadratic_levels.o[0] == quadratic(clock.time()) &&
                 std::abs(quadratic_levels.oo[0] - quadratic(clock.time() - 0.02)) < 1e-12)
      << "\n";
}
