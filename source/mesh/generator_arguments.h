#pragma once
// The `:`-separated arguments of fvfsi's own mesh generators (benchmark_meshes.cc,
// tube_meshes.cc), read with checks that name the generator.

#include <deal.II/base/utilities.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace fvfsi::internal
{
  /// The numbers of `arguments`, at least min_count and at most max_count of them.
  inline std::vector<double> numbers_of(const std::string& name, const std::string& arguments,
                                        const unsigned int min_count, const unsigned int max_count)
  {
    std::vector<double> x;
    for (const auto& s : dealii::Utilities::split_string_list(arguments, ':'))
      x.push_back(dealii::Utilities::string_to_double(s));
    if (x.size() < min_count || x.size() > max_count)
      throw std::runtime_error(name + " needs " + std::to_string(min_count) + " to " +
                               std::to_string(max_count) + " arguments separated by `:`, got `" +
                               arguments + "`");
    return x;
  }

  /// Argument i of x as a count of cells: a whole number from 1 to 100 000 (a negative or
  /// non-finite one would wrap around to billions of cells).
  inline unsigned int count_of(const std::string& name, const std::vector<double>& x,
                               const unsigned int i)
  {
    if (!(x[i] >= 1 && x[i] <= 100000 && x[i] == std::floor(x[i])))
      throw std::runtime_error(name + ": argument " + std::to_string(i + 1) +
                               " is a number of cells, a whole number from 1 to 100000, not " +
                               dealii::Utilities::to_string(x[i]));
    return static_cast<unsigned int>(x[i]);
  }

  /// Argument i of x as a length [m]: finite and > 0.
  inline double length_of(const std::string& name, const std::vector<double>& x,
                          const unsigned int i)
  {
    if (!(x[i] > 0 && x[i] < 1e100))
      throw std::runtime_error(name + ": argument " + std::to_string(i + 1) +
                               " is a length [m], a number > 0, not " +
                               dealii::Utilities::to_string(x[i]));
    return x[i];
  }
} // namespace fvfsi::internal
