#pragma once
// The fvfsi command line:  fvfsi [CASE.prm] [--set "Section/Key=value"]... | --help | --print-parameters

#include <ostream>
#include <string>
#include <vector>

namespace fvfsi
{
  /// Run fvfsi as the executable does (MPI must be initialised). Messages go to `out`/`err` on
  /// rank 0. Returns the process exit code: 0 on success, 1 on any error.
  int run_application(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
} // namespace fvfsi
