#pragma once
// Expressions from a .prm file (`Fluid/Body force = 0; -9.81`) as deal.II FunctionParser objects.

#include <deal.II/base/function_parser.h>

#include <string>

namespace fvfsi
{
  /**
   * Parse `expression`, n_components expressions of x, y[, z] and t separated by `;` (constant
   * pi), into `f`. A single `0` stands for the zero vector of any number of components. Throws a
   * std::runtime_error naming `parameter_name` if the expression does not parse or has the wrong
   * number of components.
   */
  template <int dim>
  void initialize_function(dealii::FunctionParser<dim>& f, const std::string& expression,
                           const std::string& parameter_name);

  /// The largest magnitude a value given in a .prm file may have (SI units): beyond it the
  /// solvers' products and squares would overflow to inf and NaN.
  constexpr double max_input_value = 1e100;

  /**
   * Component `component` of `f` at `point`. A value that is not finite or beyond
   * max_input_value is an input error: the std::runtime_error names `parameter_name`, the value,
   * the point and the time.
   */
  template <int dim>
  double checked_value(const dealii::FunctionParser<dim>& f, const dealii::Point<dim>& point,
                       unsigned int component, const std::string& parameter_name);
} // namespace fvfsi
