#pragma once
// A time-history table written as the run goes: `# name name ...` once, then one line of numbers
// per call, appended and flushed on rank 0, so that a run stopped early leaves every line it
// reached (fluid_history.txt, solid_history.txt, fsi_history.txt).

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace fvfsi
{
  /// `<base>x<suffix>`, `<base>y<suffix>`[, `<base>z<suffix>`]: the column names of a vector
  /// (e.g. ux_A, uy_A for the displacement at probe A).
  template <int dim>
  std::vector<std::string> vector_columns(const std::string& base, const std::string& suffix)
  {
    const char* axis[] = {"x", "y", "z"};
    std::vector<std::string> columns;
    for (unsigned int d = 0; d < dim; ++d)
      columns.push_back(base + axis[d] + suffix);
    return columns;
  }

  /// Append the components of a tensor to a history line.
  template <int dim>
  void append(std::vector<double>& line, const dealii::Tensor<1, dim>& x)
  {
    for (unsigned int d = 0; d < dim; ++d)
      line.push_back(x[d]);
  }

  class HistoryFile
  {
  public:
    /// Create (truncate) `file_name` and write the header of `columns` (rank 0 of `comm`).
    HistoryFile(const std::string& file_name, const std::vector<std::string>& columns,
                MPI_Comm comm);

    /// Restarting: `file_name` continues the first `length` bytes of `earlier_file` (the
    /// checkpoint's length of the history the restarted run wrote; the two may be one file).
    HistoryFile(const std::string& file_name, const std::vector<std::string>& columns,
                MPI_Comm comm, const std::string& earlier_file, std::uint64_t length);

    /// Bytes written so far (rank 0; 0 on the other ranks): the length a checkpoint records.
    std::uint64_t length() { return out.is_open() ? std::uint64_t(out.tellp()) : 0; }

    /// Append one line (as many values as columns; rank 0 writes, the others ignore it).
    void write_line(const std::vector<double>& values);

    const std::vector<std::string>& columns() const { return names; }

  private:
    std::vector<std::string> names;
    std::ofstream out;
  };
} // namespace fvfsi
