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
  std::vector<NamedValue> parse_named_values(const std::string& entry,
                                             const std::string& parameter);

  /// The syntax of an entry of `patch: expression` boundary conditions, for its documentation.
  inline const std::string boundary_expression_syntax =
    " Syntax: `patch: expression | patch: expression`, vector components separated by `;`.";

  /// The names of a comma-separated list (trimmed, empty items dropped).
  std::vector<std::string> parse_names(const std::string& entry);

  /// One .prm entry of boundary conditions: its text, its name (`Fluid/Wall`), the type of the
  /// conditions it lists, and whether it lists `patch: expression` items or plain patch names.
  template <typename Type>
  struct BoundaryEntry
  {
    const std::string& text;
    std::string name;
    Type type;
    bool with_expressions;
  };

  /// The (patch, type, expression, parameter) conditions that `entries` list; `Condition` is an
  /// aggregate of those four members.
  template <typename Condition, typename Type>
  std::vector<Condition> parse_boundary_entries(const std::vector<BoundaryEntry<Type>>& entries)
  {
    std::vector<Condition> conditions;
    for (const auto& e : entries)
      if (e.with_expressions)
        for (const auto& [patch, expression] : parse_named_values(e.text, e.name))
          conditions.push_back({patch, e.type, expression, e.name});
      else
        for (const auto& patch : parse_names(e.text))
          conditions.push_back({patch, e.type, "", e.name});
    return conditions;
  }
} // namespace fvfsi
