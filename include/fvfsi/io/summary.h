#pragma once
// summary.json: what a run was (dim, cells, ranks, wall time), where its time went (`timing`,
// seconds per part) and what it found (`results`).

#include <string>
#include <utility>
#include <vector>

namespace fvfsi
{
  class Summary
  {
  public:
    void set(const std::string& key, double value);
    void set(const std::string& key, const std::string& value);
    void set_result(const std::string& key, double value);
    void set_result(const std::string& key, const std::vector<double>& values);
    void set_text_result(const std::string& key, const std::string& value);
    /// Wall seconds of a part of the run (the `timing` object).
    void set_timing(const std::string& section, double seconds);
    /// Write the JSON file (call on one rank). NaN and infinity are written as null.
    void write(const std::string& file_name) const;

  private:
    using Entries = std::vector<std::pair<std::string, std::string>>; // key, JSON text
    static void put(Entries& entries, const std::string& key, const std::string& json);
    Entries top, timing, results;
  };
} // namespace fvfsi
