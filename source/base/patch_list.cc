#include <deal.II/base/utilities.h>

#include <fvfsi/base/patch_list.h>

#include <stdexcept>

namespace fvfsi
{
  using dealii::Utilities::split_string_list;
  using dealii::Utilities::trim;

  std::vector<NamedValue> parse_named_values(const std::string& entry, const std::string& parameter)
  {
    std::vector<NamedValue> items;
    for (const auto& item : split_string_list(entry, '|'))
    {
      const auto colon = item.find(':');
      if (colon == std::string::npos || trim(item.substr(0, colon)).empty())
        throw std::runtime_error(parameter + ": `" + item + "` is not `name: value`");
      items.push_back({trim(item.substr(0, colon)), trim(item.substr(colon + 1))});
    }
    return items;
  }

  std::vector<std::string> parse_names(const std::string& entry)
  {
    std::vector<std::string> names;
    for (const auto& item : split_string_list(entry, ','))
      if (!trim(item).empty())
        names.push_back(trim(item));
    return names;
  }
} // namespace fvfsi
