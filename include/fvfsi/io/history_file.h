#pragma once
// A time-history table written as the run goes: `# name name ...` once, then one line of numbers
// per call, appended and flushed on rank 0, so that a run stopped early leaves every line it
// reached (fluid_history.txt, solid_history.txt, fsi_history.txt).

#include <deal.II/base/mpi.h>

#include <fstream>
#include <string>
#include <vector>

namespace fvfsi
{
  class HistoryFile
  {
  public:
    /// Create (truncate) `file_name` and write the header of `columns` (rank 0 of `comm`).
    HistoryFile(const std::string& file_name, const std::vector<std::string>& columns, MPI_Comm comm);

    /// Append one line (as many values as columns; rank 0 writes, the others ignore it).
    void write_line(const std::vector<double>& values);

    const std::vector<std::string>& columns() const { return names; }

  private:
    std::vector<std::string> names;
    std::ofstream out;
  };
} // namespace fvfsi
