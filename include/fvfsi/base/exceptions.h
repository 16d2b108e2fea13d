#pragma once
// Error messages for users: the text of an exception without deal.II's source-file banner and
// stack trace, and the numbers in them.

#include <exception>
#include <string>

namespace fvfsi
{
  /// For a dealii::ExceptionBase, only its "additional information"; otherwise what().
  std::string concise_message(const std::exception& e);

  /// x with three significant digits ("0.95", "1e-06"), for numbers in messages.
  std::string three_digits(double x);
} // namespace fvfsi
