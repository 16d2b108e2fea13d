#pragma once
// Named probe points (`A: 0.6, 0.2 | B: 0.3, 0.21` in a .prm): cell fields sampled at fixed
// points of space, for time-history tables and summary.json.
//
// A probe reads the linear reconstruction of a cell field inside the cell that holds the point,
//
//   phi(x) = phi_P + (x - r_P) . (grad phi)_P,
//
// which is second-order accurate like the cell values. The owning rank evaluates it and the
// others add zero, so every rank gets the value (a point on a face between two ranks' cells is
// found by both: their values are averaged).

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <fvfsi/mesh/fv_geometry.h>

#include <functional>
#include <string>
#include <vector>

namespace fvfsi
{
  template <int dim>
  class PointProbes
  {
  public:
    /// Parse `name: x, y[, z] | ...` (empty: no probes); `parameter` (e.g. `Fluid scene/Probes`)
    /// names the .prm entry in error messages.
    PointProbes(const std::string& list, const std::string& parameter);

    /// Find the locally owned cell that holds each point. Call once for a fixed mesh and again
    /// whenever the vertices move. Collective; throws if a point lies outside the mesh.
    void locate(const FVGeometry<dim>& geometry);

    unsigned int size() const { return names.size(); }
    const std::string& name(const unsigned int i) const { return names[i]; }
    const dealii::Point<dim>& point(const unsigned int i) const { return points[i]; }

    /// The value of probe i: on the owning rank `value(c, x - r_c)` with c the local index of the
    /// cell that holds the point, summed over the ranks. Collective.
    template <typename T>
    T evaluate(
      unsigned int i,
      const std::function<T(unsigned int c, const dealii::Tensor<1, dim>& dx)>& value) const
    {
      T local{};
      if (cell[i] != dealii::numbers::invalid_unsigned_int)
        local = value(cell[i], points[i] - geometry->centroid[cell[i]]);
      return dealii::Utilities::MPI::sum(local, geometry->comm()) / n_found[i];
    }

  private:
    std::string parameter;
    std::vector<std::string> names;
    std::vector<dealii::Point<dim>> points;
    const FVGeometry<dim>* geometry = nullptr;
    std::vector<unsigned int> cell; ///< local index of the owned cell holding the point, or invalid
    std::vector<double> n_found;    ///< how many ranks found the point
  };
} // namespace fvfsi
