#pragma once
// No silent divergence. A time step whose solution is finite but unbounded (a velocity a thousand
// times the inflow, a displacement larger than the body) is as wrong as one with a NaN, and long
// before the NaN appears a run that blows up prints garbage as its result. Each solver checks
// after every solve that its largest value stays below a bound set by the scale of its data (the
// fluid: the velocities and pressure differences of its boundary conditions and body force; the
// solid: the size of the body), and throws a DivergenceError naming the time step, the quantity,
// its value, the bound and the position of the cell where it is largest. The scene then does what
// it does for any failed step: it writes the last good state, marks summary.json as failed and
// exits non-zero.

#include <deal.II/base/point.h>

#include <fvfsi/mesh/fv_geometry.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace fvfsi
{
  /// A solution that is finite but beyond the bound of its data: the run diverges.
  class DivergenceError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// The largest value over all cells of all ranks and the centroid of its cell (collective).
  template <int dim>
  struct CellMaximum
  {
    double value = 0;
    dealii::Point<dim> position;
  };

  template <int dim>
  CellMaximum<dim> cell_maximum(const FVGeometry<dim>& geometry,
                                const std::function<double(unsigned int)>& value);

  /// The diameter of the mesh's bounding box [m] (collective), a length scale of the domain.
  template <int dim>
  double domain_diameter(const FVGeometry<dim>& geometry);

  /// Throws a DivergenceError unless `largest.value` <= bound (or the value is not finite: the
  /// solvers' own finiteness checks name those). `who` starts the message ("Fluid"), `when` names
  /// the time step, `quantity` and `unit` what was measured ("max |u|", "m/s"), `bound_reason`
  /// where the bound comes from and `advice` what to change.
  template <int dim>
  void check_bounded(const CellMaximum<dim>& largest, double bound, const std::string& who,
                     const std::string& when, const std::string& quantity, const std::string& unit,
                     const std::string& bound_reason, const std::string& advice);
} // namespace fvfsi
