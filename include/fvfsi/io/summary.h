#pragma once
// summary.json: what a run was (dim, cells, ranks, wall time) and what it found (`results`).

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
    /// Write the JSON file (call on one rank). NaN and infinity are written as null.
    void write(const std::string& file_name) const;

  private:
    using Entries = std::vector<std::pair<std::string, std::string>>; // key, JSON text
    static void put(Entries& entries, const std::string& key, const std::string& json);
    Entries top, results;
  };
} // namespace fvfsi
