// fvfsi: cell-centred finite-volume fluid-structure interaction on deal.II.
#include <deal.II/base/mpi.h>

#include <fvfsi/app/application.h>

#include <iostream>

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return fvfsi::run_application(std::vector<std::string>(argv + 1, argv + argc), std::cout,
                                std::cerr);
}
