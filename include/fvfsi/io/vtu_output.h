#pragma once
// Cell fields to VTU/PVTU files (one piece per rank), with a .pvd record for time series.

#include <fvfsi/mesh/fv_geometry.h>

#include <string>
#include <utility>
#include <vector>

namespace fvfsi
{
  template <int dim>
  class VtuOutput
  {
  public:
    VtuOutput(const FVGeometry<dim>& geometry, const std::string& directory, const std::string& base_name);

    /// Write `fields` (name, cell vector with ghosts) as step `step` at time `time`; keeps
    /// `<base_name>.pvd` up to date so that a run stopped early still leaves a readable series.
    void write(const std::vector<std::pair<std::string, const CellVector*>>& fields, unsigned int step,
               double time);

  private:
    const FVGeometry<dim>& geometry;
    std::string directory, base_name;
    std::vector<std::pair<double, std::string>> records;
  };
} // namespace fvfsi
