#pragma once
// The solver settings of a steady run (issue 56, item 5). fvfsi's defaults are those of a
// time-accurate run: linear solves to 1e-6, SIMPLE's pressure coupling, a steady fluid converged
// to 1e-8 in every coupling iteration. A file that only switches `Fluid/Transient` (and
// `Solid/Transient`) to false would run a steady problem as a transient solver would, many times
// slower than a steady solver. So every parameter of the table in steady_settings.cc that the
// file and `--set` leave unset takes its steady value, and the run says so in its log; a value
// the file gives is kept.
//
// How "unset" is known: these parameters are declared with deal.II's `has_to_be_set` flag, and
// ParameterHandler::get_entries_wrongly_not_set() lists those that no file or set() reached.

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace fvfsi
{
  struct AllParameters;

  /// Apply the steady settings to `parameters` (after the file and the overrides are read) and
  /// return one line per setting taken, e.g. "Fluid/Consistent pressure coupling = true (SIMPLEC:
  /// ...)"; empty for a transient run.
  std::vector<std::string> apply_steady_settings(AllParameters& parameters);

  /// Whether `path` ("Section/Sub/Key") was given by the file or an override; true for a
  /// parameter not declared with `has_to_be_set` (its origin is unknown).
  bool given(const dealii::ParameterHandler& prm, const std::string& path);
} // namespace fvfsi
