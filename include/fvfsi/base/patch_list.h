#pragma once
// The list syntax of .prm entries that name patches or points with a value each,
//   `name: value | name: value`        (e.g. `inlet: 1; 0 | outlet: 0`, `A: 0.6, 0.2`),
// and of plain name lists, `a, b, c`. One parser for every such entry.

#include <string>
#include <vector>

namespace fvfsi
{
  /// One `name: value` item of a list.
  struct NamedValue
  {
    std::string name;  ///< trimmed, never empty
    std::string value; ///< trimmed text after the first `:`
  };

  /// The items of `entry` (`name: value | ...`; empty: none). Throws a std::runtime_error naming
  /// `parameter` (e.g. `Fluid/Velocity inlet`) for an item without `:` or without a name.
  std::vector<NamedValue> parse_named_values(const std::string& entry, const std::string& parameter);

  /// The names of a comma-separated list (trimmed, empty items dropped).
  std::vector<std::string> parse_names(const std::string& entry);
} // namespace fvfsi
