#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <fvfsi/fv/gathered_direct_solver.h>

#include <cmath>

#include <Epetra_CrsMatrix.h>

#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  void GatheredDirectSolver::factorize(const TrilinosWrappers::SparseMatrix& A, const Where where_)
  {
    // UMFPACK takes deal.II's serial SparseMatrix: a copy of the Trilinos matrix on the ranks
    // that solve (which UMFPACK copies again into its own arrays; the copy lives only here), read
    // through Epetra's row views (deal.II's matrix iterators copy every row they visit). With
    // more ranks, each sends its rows as (row, column) pairs and values.
    comm = A.get_mpi_communicator();
    where = where_;
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const IndexSet owned = A.locally_owned_range_indices();
    if (!owned.is_contiguous())
      throw std::logic_error("GatheredDirectSolver: the rows a rank owns are not one range");
    const int n_owned = owned.n_elements();
    counts = Utilities::MPI::all_gather(comm, n_owned);
    offsets.assign(counts.size(), 0);
    for (unsigned int r = 1; r < counts.size(); ++r)
      offsets[r] = offsets[r - 1] + counts[r - 1];
    if (n_owned > 0 && int(owned.nth_index_in_set(0)) != offsets[rank])
      throw std::logic_error("GatheredDirectSolver: the ranks' rows are not in rank order");

    const Epetra_CrsMatrix& epetra = A.trilinos_matrix();
    std::vector<types::global_dof_index> my_indices; // row, column, row, column, ...
    std::vector<double> my_entries;
    for (int row = 0; row < epetra.NumMyRows(); ++row)
    {
      int n;
      double* values;
      int* columns;
      AssertThrow(epetra.ExtractMyRowView(row, n, values, columns) == 0, ExcInternalError());
      for (int k = 0; k < n; ++k)
      {
        my_indices.push_back(epetra.GRID64(row));
        my_indices.push_back(epetra.GCID64(columns[k]));
        my_entries.push_back(values[k]);
      }
    }
    const bool one_rank = counts.size() == 1, solves = where == Where::every_rank || rank == 0;
    std::vector<std::vector<types::global_dof_index>> indices; // per rank
    std::vector<std::vector<double>> entries;                  // per rank
    if (one_rank)
    {
      indices.push_back(std::move(my_indices));
      entries.push_back(std::move(my_entries));
    }
    else if (where == Where::every_rank)
    {
      indices = Utilities::MPI::all_gather(comm, my_indices);
      entries = Utilities::MPI::all_gather(comm, my_entries);
    }
    else
    {
      indices = Utilities::MPI::gather(comm, my_indices, 0);
      entries = Utilities::MPI::gather(comm, my_entries, 0);
    }
    umfpack.reset();
    if (!solves)
      return;
    DynamicSparsityPattern dsp(A.m(), A.n());
    for (unsigned int r = 0; r < indices.size(); ++r)
      for (std::size_t k = 0; k < entries[r].size(); ++k)
        dsp.add(indices[r][2 * k], indices[r][2 * k + 1]);
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> serial(pattern);
    for (unsigned int r = 0; r < indices.size(); ++r)
      for (std::size_t k = 0; k < entries[r].size(); ++k)
        serial.set(indices[r][2 * k], indices[r][2 * k + 1], entries[r][k]);
    umfpack = std::make_unique<SparseDirectUMFPACK>();
    umfpack->factorize(serial);
    whole.reinit(A.m());
  }

  void GatheredDirectSolver::solve(Vector& x, const Vector& b, const bool with_ghosts) const
  {
    if (counts.empty())
      throw std::logic_error("GatheredDirectSolver::solve() before factorize()");
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const int n_owned = counts[rank];
    // The owned entries of b are one range of the whole b: gather them in rank order.
    if (counts.size() == 1)
      std::copy(b.begin(), b.begin() + n_owned, whole.begin());
    else if (where == Where::every_rank)
      MPI_Allgatherv(b.begin(), n_owned, MPI_DOUBLE, whole.begin(), counts.data(), offsets.data(),
                     MPI_DOUBLE, comm);
    else
      MPI_Gatherv(b.begin(), n_owned, MPI_DOUBLE, rank == 0 ? whole.begin() : nullptr,
                  counts.data(), offsets.data(), MPI_DOUBLE, 0, comm);
    if (umfpack)
      umfpack->solve(whole);
    if (where == Where::rank_0 && counts.size() > 1)
      MPI_Scatterv(whole.begin(), counts.data(), offsets.data(), MPI_DOUBLE, x.begin(), n_owned,
                   MPI_DOUBLE, 0, comm);
    else
      std::copy(whole.begin() + offsets[rank], whole.begin() + offsets[rank] + n_owned, x.begin());
    if (where == Where::rank_0) // only rank 0 holds the whole solution: nothing to check here
    {
      if (with_ghosts)
        x.update_ghost_values();
      return;
    }
    for (const double value : whole)
      if (!std::isfinite(value))
        throw std::runtime_error("the direct solve gave a solution that is not finite (NaN or "
                                 "inf): the right-hand side or the matrix is not finite");
    if (with_ghosts)
    {
      // The ghost entries follow the owned ones in x's local storage, in the order of the
      // partitioner's ghost indices; every rank holds the whole solution.
      const IndexSet& ghosts = x.get_partitioner()->ghost_indices();
      unsigned int k = n_owned;
      for (const auto i : ghosts)
        x.local_element(k++) = whole[i];
      x.set_ghost_state(true);
    }
  }
} // namespace fvfsi
