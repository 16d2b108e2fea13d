#pragma once
// Point-value files: fields sampled at points (cell centres, interface vertices) as a text table,
// `# x y [z] name ...` and one row per point, and read back as functions of position on another
// mesh. A steady FSI run writes its state in this form at the end; a run on a finer mesh starts
// from it (`Initial state from`): mesh sequencing, the nested iteration that lets the finest
// mesh start near its answer instead of from rest.

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/numerics/rtree.h>

#include <string>
#include <utility>
#include <vector>

namespace fvfsi
{
  /// Write `rows` (one per point, the values of `columns`) at `points` into `file`: every rank
  /// passes its own points, rank 0 writes them all (collective). Full precision, so that a run
  /// continued from the file on the same mesh starts from the same state.
  template <int dim>
  void write_point_values(const std::string& file, const std::vector<std::string>& columns,
                          const std::vector<dealii::Point<dim>>& points,
                          const std::vector<std::vector<double>>& rows, MPI_Comm comm);

  /// A table written by write_point_values(), read on every rank, as functions of position.
  template <int dim>
  class PointValues
  {
  public:
    /// Read `file`; throws naming it and `parameter` (the setting that named it) if it cannot be
    /// read, lacks one of `columns`, or has a row that is not numbers.
    PointValues(const std::string& file, const std::vector<std::string>& columns,
                const std::string& parameter);

    /// The values of the columns (in the constructor's order) at x: the average of the
    /// 2^dim nearest samples weighted by the inverse square of their distance, the sample's
    /// own values where x is a sample point. First-order accurate: a start, not a transfer
    /// that keeps the discretisation's order.
    std::vector<double> value(const dealii::Point<dim>& x) const;
    unsigned int size() const { return points.size(); }

  private:
    std::vector<dealii::Point<dim>> points;
    std::vector<std::vector<double>> values; ///< per point, the constructor's columns
    dealii::RTree<std::pair<dealii::Point<dim>, unsigned int>> tree; ///< (point, index)
  };
} // namespace fvfsi
