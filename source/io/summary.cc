#include <fvfsi/io/summary.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace fvfsi
{
  namespace
  {
    std::string number(const double x)
    {
      if (!std::isfinite(x))
        return "null";
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.10g", x);
      return buffer;
    }

    std::string quoted(const std::string& s)
    {
      // A JSON string: quotes and backslashes escaped, control characters (a newline in an
      // error message) as \n, \t or \u00XX, which JSON does not allow raw.
      std::string out = "\"";
      for (const char c : s)
      {
        if (c == '"' || c == '\\')
          (out += '\\') += c;
        else if (c == '\n')
          out += "\\n";
        else if (c == '\t')
          out += "\\t";
        else if (static_cast<unsigned char>(c) < 0x20)
        {
          char buffer[8];
          std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned int>(c));
          out += buffer;
        }
        else
          out += c;
      }
      return out + "\"";
    }
  } // namespace

  void Summary::put(Entries& entries, const std::string& key, const std::string& json)
  {
    for (auto& [k, v] : entries)
      if (k == key)
      {
        v = json;
        return;
      }
    entries.emplace_back(key, json);
  }

  void Summary::set(const std::string& key, const double value)
  {
    put(top, key, number(value));
  }
  void Summary::set(const std::string& key, const std::string& value)
  {
    put(top, key, quoted(value));
  }
  void Summary::set_result(const std::string& key, const double value)
  {
    put(results, key, number(value));
  }
  void Summary::set_text_result(const std::string& key, const std::string& value)
  {
    put(results, key, quoted(value));
  }
  void Summary::set_result(const std::string& key, const std::vector<double>& values)
  {
    std::string json = "[";
    for (unsigned int i = 0; i < values.size(); ++i)
      json += (i ? ", " : "") + number(values[i]);
    put(results, key, json + "]");
  }

  void Summary::set_timing(const std::string& section, const double seconds)
  {
    put(timing, section, number(seconds));
  }

  void Summary::write(const std::string& file_name) const
  {
    std::ofstream out(file_name);
    if (!out)
      throw std::runtime_error("cannot write `" + file_name + "`");
    const auto object = [&out](const std::string& name, const Entries& entries)
    {
      out << "  " << quoted(name) << ": {";
      for (unsigned int i = 0; i < entries.size(); ++i)
        out << (i ? "," : "") << "\n    " << quoted(entries[i].first) << ": " << entries[i].second;
      out << "\n  }";
    };
    out << "{\n";
    for (const auto& [key, json] : top)
      out << "  " << quoted(key) << ": " << json << ",\n";
    if (!timing.empty())
    {
      object("timing", timing);
      out << ",\n";
    }
    object("results", results);
    out << "\n}\n";
  }
} // namespace fvfsi
