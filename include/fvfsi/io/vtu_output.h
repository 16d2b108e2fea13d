#pragma once
// Cell fields to VTU/PVTU files (one piece per rank), with a .pvd record for time series.
//
// A scene owns one VtuOutput per mesh for the whole run, so that its .pvd lists every written
// step (ParaView then plays the series); the record is rewritten after each write, so a run that
// stops early still leaves a readable series. A solver adds its fields to an OutputFields (e.g.
// FluidSolver::add_output_fields), the scene writes them.

#include <fvfsi/mesh/fv_geometry.h>

#include <string>
#include <utility>
#include <vector>

namespace fvfsi
{
  /// Named cell fields for output, each a cell vector with ghost values.
  template <int dim>
  class OutputFields
  {
  public:
    explicit OutputFields(const FVGeometry<dim>& geometry) : geometry(geometry) {}

    /// The field `name` with the value `value(c)` in every owned cell c.
    template <typename Value>
    void add(const std::string& name, const Value& value)
    {
      CellVector v = geometry.make_cell_vector();
      for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
        v.local_element(c) = value(c);
      v.update_ghost_values();
      fields.emplace_back(name, std::move(v));
    }
    /// The components `name_x`, `name_y`[, `name_z`] of the vector `value(c)`.
    template <typename Vector>
    void add_vector(const std::string& name, const Vector& value)
    {
      const char* axis[] = {"x", "y", "z"};
      for (unsigned int d = 0; d < dim; ++d)
        add(name + "_" + axis[d], [&](const unsigned int c) { return value(c)[d]; });
    }

    const FVGeometry<dim>& geometry;
    std::vector<std::pair<std::string, CellVector>> fields;
  };

  template <int dim>
  class VtuOutput
  {
  public:
    /// Writes `<directory>/<base_name>_<step>.pvtu` (+ one .vtu per rank) and `<base_name>.pvd`.
    VtuOutput(const FVGeometry<dim>& geometry, const std::string& directory,
              const std::string& base_name);

    /// Write `fields` as step `step` at time `time` [s] and rewrite the .pvd record of all steps
    /// written so far (collective).
    void write(const OutputFields<dim>& fields, unsigned int step, double time);

    /// The steps written so far: (time, .pvtu file name).
    const std::vector<std::pair<double, std::string>>& written() const { return records; }
    /// Restarting: the steps an earlier run wrote into `earlier_directory` come first in the
    /// .pvd record (their file names made relative to this writer's directory).
    void continue_from(const std::vector<std::pair<double, std::string>>& earlier,
                       const std::string& earlier_directory);

  private:
    const FVGeometry<dim>& geometry;
    std::string directory, base_name;
    std::vector<std::pair<double, std::string>> records;
  };
} // namespace fvfsi
