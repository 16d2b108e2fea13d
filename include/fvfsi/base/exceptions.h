#pragma once
// Error messages for users: the text of an exception without deal.II's source-file banner and
// stack trace.

#include <exception>
#include <string>

namespace fvfsi
{
  /// For a dealii::ExceptionBase, only its "additional information"; otherwise what().
  std::string concise_message(const std::exception& e);
} // namespace fvfsi
