#include <fvfsi/io/history_file.h>

#include <iomanip>
#include <stdexcept>

namespace fvfsi
{
  HistoryFile::HistoryFile(const std::string& file_name, const std::vector<std::string>& columns,
                           const MPI_Comm comm)
      : names(columns)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    out.open(file_name, std::ios::trunc);
    if (!out)
      throw std::runtime_error("cannot write `" + file_name + "`");
    out << "#";
    for (const auto& name : names)
      out << ' ' << name;
    out << '\n' << std::setprecision(10);
    out.flush();
  }

  HistoryFile::HistoryFile(const std::string& file_name, const std::vector<std::string>& columns,
                           const MPI_Comm comm, const std::string& earlier_file,
                           const std::uint64_t length)
      : names(columns)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    // Read the earlier lines first: the two files may be the same.
    std::ifstream in(earlier_file, std::ios::binary);
    std::string text(length, '\0');
    if (!in.read(text.data(), std::streamsize(length)))
      throw std::runtime_error("restart: `" + earlier_file + "` is shorter than the " +
                               std::to_string(length) +
                               " bytes its checkpoint recorded (was it changed after the run?)");
    in.close();
    out.open(file_name, std::ios::trunc | std::ios::binary);
    if (!out)
      throw std::runtime_error("cannot write `" + file_name + "`");
    out << text << std::setprecision(10);
    out.flush();
  }

  void HistoryFile::write_line(const std::vector<double>& values)
  {
    if (!out.is_open())
      return;
    if (values.size() != names.size())
      throw std::logic_error("HistoryFile: " + std::to_string(values.size()) + " values for " +
                             std::to_string(names.size()) + " columns");
    for (unsigned int i = 0; i < values.size(); ++i)
      out << (i == 0 ? "" : " ") << values[i];
    out << '\n';
    out.flush();
  }
} // namespace fvfsi
