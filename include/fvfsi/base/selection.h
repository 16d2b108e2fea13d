#pragma once
// A .prm entry with a fixed set of names that the code reads as an enum: the text is checked
// (Patterns::Selection) and decoded once, when the file is read, never compared inside loops.
//
//   enum class Convection { upwind, linear_upwind };
//   add_selection(prm, "Convection scheme", convection,
//                 {{"upwind", Convection::upwind}, {"linear upwind", Convection::linear_upwind}},
//                 "Face velocity of the convection term ...");

#include <deal.II/base/parameter_handler.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fvfsi
{
  template <typename Enum>
  using SelectionNames = std::vector<std::pair<std::string, Enum>>;

  /// The name of `value` in `names` (for messages and summaries).
  template <typename Enum>
  std::string selection_name(const SelectionNames<Enum>& names, const Enum value)
  {
    for (const auto& [name, v] : names)
      if (v == value)
        return name;
    throw std::logic_error("selection_name: a value without a name");
  }

  /// Declare `entry` in the current subsection with the name of `member` as its default, and
  /// set `member` whenever the entry is read or set. `names` must outlive nothing: it is copied.
  template <typename Enum>
  void add_selection(dealii::ParameterHandler& prm, const std::string& entry, Enum& member,
                     const SelectionNames<Enum>& names, const std::string& documentation)
  {
    std::string pattern;
    for (const auto& [name, value] : names)
      pattern += (pattern.empty() ? "" : "|") + name;
    prm.declare_entry(entry, selection_name(names, member), dealii::Patterns::Selection(pattern),
                      documentation);
    prm.add_action(entry,
                   [&member, names](const std::string& text)
                   {
                     for (const auto& [name, value] : names)
                       if (name == text)
                         member = value;
                   });
  }
} // namespace fvfsi
