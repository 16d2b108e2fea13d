#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <fvfsi/base/selection.h>
#include <fvfsi/fv/jacobian_solver.h>

#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  void JacobianSolverParameters::declare(ParameterHandler& prm, const std::string& name)
  {
    prm.enter_subsection(name);
    add_selection(prm, "Method", method,
                  {{"KLU", Method::klu},
                   {"UMFPACK", Method::umfpack},
                   {"GMRES-AMG", Method::gmres_amg},
                   {"GMRES-ILU", Method::gmres_ilu}},
                  "Solver of the Newton systems: sparse direct (UMFPACK, multifrontal; or Trilinos "
                  "Amesos KLU, 1.7 times slower on the plate with a hole and the 3D plate, 5 times "
                  "with OpenBLAS, "
                  "doc/results/solid_coupled.md; both factorise the matrix gathered on one rank), "
                  "or GMRES with ML AMG for systems (block size dim) or "
                  "Ifpack ILU(0).");
    prm.add_parameter("Residual reduction", reduction,
                      "GMRES: relative residual reduction of a Newton system.",
                      Patterns::Double(0, 1));
    prm.add_parameter("Max iterations", max_iterations, "GMRES: iteration limit.",
                      Patterns::Integer(1));
    prm.add_parameter("Restart", restart, "GMRES: Krylov vectors kept before a restart.",
                      Patterns::Integer(2));
    prm.leave_subsection();
  }

  JacobianSolver::JacobianSolver(const JacobianSolverParameters& parameters)
      : parameters(parameters)
  {
  }

  void JacobianSolver::initialize(const TrilinosWrappers::SparseMatrix& A,
                                  const unsigned int block_size)
  {
    using Method = JacobianSolverParameters::Method;
    matrix = &A;
    direct.reset();
    umfpack.reset();
    preconditioner.reset();
    if (parameters.method == Method::umfpack)
      factorize_on_root(A);
    else if (parameters.method == Method::klu)
    {
      direct = std::make_unique<TrilinosWrappers::SolverDirect>(
        direct_control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Klu"));
      direct->initialize(A);
    }
    else if (parameters.method == Method::gmres_amg)
    {
      // One constant mode per component: ML aggregates the nodes, block_size unknowns at a time.
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic = true;
      data.higher_order_elements = false;
      data.smoother_sweeps = 2;
      data.aggregation_threshold = 0.02;
      const unsigned int n = A.local_size();
      data.constant_modes.assign(block_size, std::vector<bool>(n, false));
      for (unsigned int i = 0; i < n; ++i)
        data.constant_modes[i % block_size][i] = true;
      auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      amg->initialize(A, data);
      preconditioner = std::move(amg);
    }
    else
    {
      auto ilu = std::make_unique<TrilinosWrappers::PreconditionILU>();
      ilu->initialize(A);
      preconditioner = std::move(ilu);
    }
  }

  void JacobianSolver::factorize_on_root(const TrilinosWrappers::SparseMatrix& A)
  {
    // UMFPACK takes deal.II's serial SparseMatrix: a copy of the Trilinos matrix on rank 0 (which
    // UMFPACK copies again into its own arrays; the copy lives only here), read through Epetra's
    // row views (deal.II's matrix iterators copy every row they visit). With more ranks, each
    // sends its rows to rank 0 as (row, column) pairs and values.
    const MPI_Comm comm = A.get_mpi_communicator();
    const Epetra_CrsMatrix& epetra = A.trilinos_matrix();
    const auto for_each_local_entry = [&epetra](const auto& f)
    {
      int n;
      double* values;
      int* columns;
      for (int row = 0; row < epetra.NumMyRows(); ++row)
      {
        AssertThrow(epetra.ExtractMyRowView(row, n, values, columns) == 0, ExcInternalError());
        for (int k = 0; k < n; ++k)
          f(epetra.GRID64(row), epetra.GCID64(columns[k]), values[k]);
      }
    };
    std::vector<std::vector<types::global_dof_index>> indices; // per rank: row, column, ...
    std::vector<std::vector<double>> entries;                  // per rank
    const bool one_rank = Utilities::MPI::n_mpi_processes(comm) == 1;
    if (!one_rank)
    {
      std::vector<types::global_dof_index> my_indices;
      std::vector<double> my_entries;
      for_each_local_entry(
        [&](const auto row, const auto column, const double value)
        {
          my_indices.push_back(row);
          my_indices.push_back(column);
          my_entries.push_back(value);
        });
      indices = Utilities::MPI::gather(comm, my_indices, 0);
      entries = Utilities::MPI::gather(comm, my_entries, 0);
    }
    umfpack = std::make_unique<SparseDirectUMFPACK>();
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    const auto for_each_entry = [&](const auto& f)
    {
      if (one_rank)
        for_each_local_entry(f);
      for (unsigned int r = 0; r < entries.size(); ++r)
        for (std::size_t k = 0; k < entries[r].size(); ++k)
          f(indices[r][2 * k], indices[r][2 * k + 1], entries[r][k]);
    };
    DynamicSparsityPattern dsp(A.m(), A.n());
    for_each_entry([&dsp](const auto row, const auto column, double) { dsp.add(row, column); });
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> serial(pattern);
    for_each_entry([&serial](const auto row, const auto column, const double value)
                   { serial.set(row, column, value); });
    umfpack->factorize(serial);
  }

  void JacobianSolver::solve_on_root(Vector& x, const Vector& b) const
  {
    // b gathered on rank 0 (by global index), solved there, the solution sent to every rank.
    const MPI_Comm comm = b.get_mpi_communicator();
    std::vector<types::global_dof_index> owned;
    b.locally_owned_elements().fill_index_vector(owned);
    std::vector<double> my_values(owned.size());
    for (unsigned int i = 0; i < owned.size(); ++i)
      my_values[i] = b.local_element(i);
    const auto all_owned = Utilities::MPI::gather(comm, owned, 0);
    const auto all_values = Utilities::MPI::gather(comm, my_values, 0);
    dealii::Vector<double> solution(b.size());
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      for (unsigned int r = 0; r < all_owned.size(); ++r)
        for (unsigned int i = 0; i < all_owned[r].size(); ++i)
          solution[all_owned[r][i]] = all_values[r][i];
      umfpack->solve(solution);
    }
    Utilities::MPI::broadcast(solution.data(), solution.size(), 0, comm);
    for (unsigned int i = 0; i < owned.size(); ++i)
      x.local_element(i) = solution[owned[i]];
  }

  unsigned int JacobianSolver::solve(Vector& x, const Vector& b, const std::string& what,
                                     const double reduction)
  {
    if (direct)
    {
      direct->solve(x, b);
      return 0;
    }
    if (umfpack)
    {
      solve_on_root(x, b);
      return 0;
    }
    SolverControl control(parameters.max_iterations,
                          (reduction >= 0 ? reduction : parameters.reduction) * b.l2_norm(), false,
                          false);
    // Right preconditioning: the control sees the true residual.
    SolverGMRES<Vector> gmres(control,
                              SolverGMRES<Vector>::AdditionalData(parameters.restart, true));
    try
    {
      gmres.solve(*matrix, x, b, *preconditioner);
    }
    catch (const std::exception&)
    {
      throw std::runtime_error("GMRES on " + what + " did not converge: residual " +
                               Utilities::to_string(control.last_value()) + " after " +
                               std::to_string(control.last_step()) + " iterations (target " +
                               Utilities::to_string(control.tolerance()) + ")");
    }
    return control.last_step();
  }
} // namespace fvfsi
