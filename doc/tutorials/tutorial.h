#pragma once
// What the tutorial programs share: their main() and the table each writes for the test suite.

#include <deal.II/base/mpi.h>
#include <deal.II/base/table_handler.h>

#include <fstream>
#include <iostream>
#include <string>

namespace fvfsi_tutorial
{
/// Initialise MPI (and with it p4est and Trilinos), call `run()`; an error ends the program
/// with a message that names it and exit code 1.
template <typename Run>
int main_program(int argc, char** argv, const std::string& name, const Run& run)
{
  try
  {
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    run();
  }
  catch (const std::exception& e)
  {
    std::cerr << name << ": error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}

/// The table on rank 0: to the screen and to the file `output` that the test suite compares.
inline void write_table(const dealii::TableHandler& table, const MPI_Comm comm)
{
  if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
    return;
  std::ofstream output("output");
  table.write_text(std::cout);
  table.write_text(output);
}
} // namespace fvfsi_tutorial
