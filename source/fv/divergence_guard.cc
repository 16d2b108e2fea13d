#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <fvfsi/fv/divergence_guard.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  CellMaximum<dim> cell_maximum(const FVGeometry<dim>& geometry,
                                const std::function<double(unsigned int)>& value)
  {
    CellMaximum<dim> local;
    local.value = -std::numeric_limits<double>::max();
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      const double v = value(c);
      if (v > local.value || !std::isfinite(v))
      {
        local.value = std::isfinite(v) ? v : std::numeric_limits<double>::max();
        local.position = geometry.centroid[c];
      }
    }
    // The rank with the largest value (the lowest rank of a tie) tells its position.
    const auto stats = Utilities::MPI::min_max_avg(local.value, geometry.comm());
    CellMaximum<dim> global;
    global.value = stats.max;
    global.position = Utilities::MPI::broadcast(geometry.comm(), local.position, stats.max_index);
    return global;
  }

  template <int dim>
  double domain_diameter(const FVGeometry<dim>& geometry)
  {
    Point<dim> lo, hi;
    for (unsigned int d = 0; d < dim; ++d)
    {
      lo[d] = std::numeric_limits<double>::max();
      hi[d] = -std::numeric_limits<double>::max();
    }
    // Of the cell centroids (the vertex array also holds unused vertices of other ranks' cells):
    // half a cell short of the domain's box, close enough for a scale.
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
      for (unsigned int d = 0; d < dim; ++d)
      {
        lo[d] = std::min(lo[d], geometry.centroid[c][d]);
        hi[d] = std::max(hi[d], geometry.centroid[c][d]);
      }
    double squared = 0;
    for (unsigned int d = 0; d < dim; ++d)
    {
      const double extent =
        Utilities::MPI::max(hi[d], geometry.comm()) + Utilities::MPI::max(-lo[d], geometry.comm());
      squared += extent * extent;
    }
    return std::sqrt(squared);
  }

  template <int dim>
  void check_bounded(const CellMaximum<dim>& largest, const double bound, const std::string& who,
                     const std::string& when, const std::string& quantity, const std::string& unit,
                     const std::string& bound_reason, const std::string& advice)
  {
    if (!(largest.value > bound) || largest.value == std::numeric_limits<double>::max())
      return;
    std::ostringstream message;
    message << who << ": the solution diverges at " << when << ": " << quantity << " = "
            << largest.value << " " << unit << " in the cell at (";
    for (unsigned int d = 0; d < dim; ++d)
      message << (d > 0 ? ", " : "") << largest.position[d];
    message << "), above the bound " << bound << " " << unit << " (" << bound_reason << "); "
            << advice;
    throw DivergenceError(message.str());
  }

  template struct CellMaximum<2>;
  template struct CellMaximum<3>;
  template CellMaximum<2> cell_maximum(const FVGeometry<2>&,
                                       const std::function<double(unsigned int)>&);
  template CellMaximum<3> cell_maximum(const FVGeometry<3>&,
                                       const std::function<double(unsigned int)>&);
  template double domain_diameter(const FVGeometry<2>&);
  template double domain_diameter(const FVGeometry<3>&);
  template void check_bounded(const CellMaximum<2>&, double, const std::string&, const std::string&,
                              const std::string&, const std::string&, const std::string&,
                              const std::string&);
  template void check_bounded(const CellMaximum<3>&, double, const std::string&, const std::string&,
                              const std::string&, const std::string&, const std::string&,
                              const std::string&);
} // namespace fvfsi
