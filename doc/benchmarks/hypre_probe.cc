// hypre's BoomerAMG on a dumped pressure system, through deal.II's PETSc wrappers (Debian's
// deal.II is built with PETSc and hypre), beside ML in amg_probe.cc (doc/results/
// pressure_options.py, performance.md section 15). Reads DIR/pressure_A.mtx, pressure_b.txt and
// pressure_x0.txt (doc/benchmarks/pressure_dump_probe.patch) on one rank and times PETSc's CG
// with one BoomerAMG V-cycle as preconditioner, from the dumped start value to a relative residual
// of 1e-2 and 1e-6, REPEATS solves each (median printed), for each strong threshold in
// $THRESHOLDS (default "0.25 0.5"; BoomerAMG's default 0.25, 0.5 the value hypre's manual gives
// for 3D). The output lines have amg_probe's format, so that the same script reads both.
//
//   usage: hypre_probe DIR [REPEATS]   (build: make hypre_probe)
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/petsc_precondition.h>
#include <deal.II/lac/petsc_solver.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/solver_control.h>

#include <petscsys.h>

#include "probe_input.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;
using probe::median;
using probe::read_values;

namespace
{
// The Matrix Market coordinate file EpetraExt writes (1-based "row column value" lines).
void read_matrix(const std::string& name, PETScWrappers::MPI::SparseMatrix& A, IndexSet& rows)
{
  std::ifstream in(name);
  if (!in)
    throw std::runtime_error("hypre_probe: cannot read " + name);
  std::string line;
  do
    std::getline(in, line);
  while (line[0] == '%');
  unsigned int m, n, nnz;
  std::istringstream(line) >> m >> n >> nnz;
  std::vector<unsigned int> i(nnz), j(nnz);
  std::vector<double> v(nnz);
  DynamicSparsityPattern pattern(m, n);
  for (unsigned int k = 0; k < nnz; ++k)
  {
    in >> i[k] >> j[k] >> v[k];
    pattern.add(--i[k], --j[k]);
  }
  rows = complete_index_set(m);
  A.reinit(rows, rows, pattern, MPI_COMM_WORLD);
  for (unsigned int k = 0; k < nnz; ++k)
    A.set(i[k], j[k], v[k]);
  A.compress(VectorOperation::insert);
}
} // namespace

int main(int argc, char** argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 2)
  {
    std::cerr << "usage: hypre_probe DIR [REPEATS]" << std::endl;
    return 1;
  }
  const std::string dir = argv[1];
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 20;
  PETScWrappers::MPI::SparseMatrix A;
  IndexSet rows;
  read_matrix(dir + "/pressure_A.mtx", A, rows);
  const auto b_all = read_values(dir + "/pressure_b.txt"),
             x0_all = read_values(dir + "/pressure_x0.txt");
  PETScWrappers::MPI::Vector b(rows, MPI_COMM_WORLD), x0(rows, MPI_COMM_WORLD), x(b);
  for (unsigned int k = 0; k < b_all.size(); ++k)
  {
    b(k) = b_all[k];
    x0(k) = x0_all[k];
  }
  b.compress(VectorOperation::insert);
  x0.compress(VectorOperation::insert);
  // The residual of the start value: the reductions are relative to it (as fvfsi's and
  // amg_probe's CG).
  PETScWrappers::MPI::Vector r(b);
  A.vmult(r, x0);
  r.sadd(-1, b);
  const double r0 = r.l2_norm();
  // CG's stopping test on the true residual |b - A x|, as Belos's in amg_probe (PETSc's CG
  // otherwise tests the preconditioned one); deal.II's solver reads PETSc's options database.
  PetscOptionsSetValue(nullptr, "-ksp_norm_type", "unpreconditioned");

  std::istringstream thresholds(std::getenv("THRESHOLDS") ? std::getenv("THRESHOLDS") : "0.25 0.5");
  double threshold;
  while (thresholds >> threshold)
  {
    PETScWrappers::PreconditionBoomerAMG::AdditionalData data;
    data.symmetric_operator = true;
    data.strong_threshold = threshold;
    std::vector<double> setup;
    PETScWrappers::PreconditionBoomerAMG amg;
    for (int round = 0; round < 5; ++round) // set-up timed five times, the median kept
    {
      const double start = MPI_Wtime();
      amg.initialize(A, data);
      setup.push_back(MPI_Wtime() - start);
    }
    for (const double tol : {1e-2, 1e-6})
    {
      std::vector<double> seconds;
      unsigned int iterations = 0;
      for (int round = 0; round < repeats; ++round)
      {
        x = x0;
        SolverControl control(1000, tol * r0);
        PETScWrappers::SolverCG cg(control, MPI_COMM_WORLD);
        const double start = MPI_Wtime();
        cg.solve(A, x, b, amg);
        seconds.push_back(MPI_Wtime() - start);
        iterations = control.last_step();
      }
      std::cout << "BoomerAMG, np 1, tol " << tol << ", strong threshold " << threshold << ": "
                << iterations << " CG iterations, " << 1e3 * median(seconds)
                << " ms per solve (x1 of the first), set-up " << 1e3 * median(setup) << " ms"
                << std::endl;
    }
  }
}
