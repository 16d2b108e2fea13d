#pragma once
// Shared by the pressure-solve probes (amg_probe.cc, hypre_probe.cc): reading the dumped values
// (doc/benchmarks/pressure_dump_probe.patch) and the median of timed repeats.
#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace probe
{
/// The numbers of a text file, one per line (pressure_b.txt, pressure_x0.txt).
inline std::vector<double> read_values(const std::string& name)
{
  std::ifstream in(name);
  if (!in)
    throw std::runtime_error("probe: cannot read " + name);
  std::vector<double> v;
  double x;
  while (in >> x)
    v.push_back(x);
  return v;
}

inline double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
} // namespace probe
