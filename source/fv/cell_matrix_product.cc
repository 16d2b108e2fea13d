#include <fvfsi/fv/cell_matrix_product.h>

namespace fvfsi
{
  using namespace dealii;

  void CellMatrixProduct::reinit(const TrilinosWrappers::SparseMatrix& A, const CellVector& layout)
  {
    matrix = &A;
    const Epetra_CrsMatrix& epetra = A.trilinos_matrix();
    int *offsets = nullptr, *indices = nullptr;
    double* entries = nullptr;
    if (!epetra.StorageOptimized() || epetra.ExtractCrsDataPointers(offsets, indices, entries) != 0)
    {
      own = false;
      made_for_indices = nullptr;
      return;
    }
    row_offsets = offsets;
    values = entries;
    const Utilities::MPI::Partitioner& partitioner = *layout.get_partitioner();
    const int n_entries = epetra.NumMyNonzeros();
    if (&epetra == made_for_matrix && indices == made_for_indices &&
        n_entries == made_for_entries && &partitioner == made_for_layout)
      return; // the same pattern and layout: only the values may have changed

    // Translate each entry's column (Epetra's column-map position) into its cell's position in
    // a cell vector: owned cells first, then the ghost cells in the Partitioner's order.
    const unsigned int n_rows = epetra.NumMyRows();
    own = n_rows == partitioner.locally_owned_size();
    columns.resize(n_entries);
    interior_rows.clear();
    boundary_rows.clear();
    for (unsigned int r = 0; r < n_rows && own; ++r)
    {
      bool needs_ghost = false;
      for (int k = row_offsets[r]; k < row_offsets[r + 1] && own; ++k)
      {
        const types::global_dof_index column = epetra.ColMap().GID(indices[k]);
        own = partitioner.in_local_range(column) || partitioner.is_ghost_entry(column);
        if (own)
        {
          columns[k] = partitioner.global_to_local(column);
          needs_ghost = needs_ghost || columns[k] >= n_rows;
        }
      }
      auto& runs = needs_ghost ? boundary_rows : interior_rows;
      if (!runs.empty() && runs.back().second == r)
        ++runs.back().second;
      else
        runs.emplace_back(r, r + 1);
    }
    made_for_matrix = &epetra; // also when the product is Trilinos': the verdict is kept
    made_for_indices = indices;
    made_for_entries = n_entries;
    made_for_layout = &partitioner;
  }

  void CellMatrixProduct::vmult(CellVector& y, const CellVector& x) const
  {
    Assert(matrix != nullptr, ExcMessage("CellMatrixProduct::vmult before reinit"));
    if (!own)
    {
      matrix->vmult(y, x);
      return;
    }
    const bool x_had_ghosts = x.has_ghost_elements();
    if (!x_had_ghosts)
      x.update_ghost_values_start();
    if (y.has_ghost_elements())
      y.zero_out_ghost_values();
    // The rows that read owned cells only, while the ghost values travel.
    multiply_rows(interior_rows, x.begin(), y.begin());
    if (!x_had_ghosts)
      x.update_ghost_values_finish();
    multiply_rows(boundary_rows, x.begin(), y.begin());
    if (!x_had_ghosts)
      x.zero_out_ghost_values();
  }

  void
  CellMatrixProduct::multiply_rows(const std::vector<std::pair<unsigned int, unsigned int>>& runs,
                                   const double* x_local, double* y_local) const
  {
    const int* __restrict offsets = row_offsets;
    const double* __restrict a = values;
    const unsigned int* __restrict column = columns.data();
    const double* __restrict x = x_local;
    double* __restrict y = y_local;
    for (const auto& [first, last] : runs)
    {
      int k = offsets[first];
      for (unsigned int r = first; r < last; ++r)
      {
        double sum = 0; // one sum per row, in Epetra's order: the same result to the bit
        const int end = offsets[r + 1];
        // A row holds a handful of entries (a cell and its face neighbours): the unrolled loop
        // that deal.II's -funroll-loops makes of this spends more in its jump table than it saves.
#pragma GCC unroll 1
        for (; k < end; ++k)
          sum += a[k] * x[column[k]];
        y[r] = sum;
      }
    }
  }
} // namespace fvfsi
