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
} // namespace fvfsi
