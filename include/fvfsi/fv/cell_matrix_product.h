#pragma once
// y = A x for an assembled Trilinos matrix, computed on the cell vectors themselves.
//
// Trilinos' own product (`TrilinosWrappers::SparseMatrix::vmult`) first imports x into Epetra's
// column-map vector: it copies the owned entries and exchanges the ghost entries, and that import
// starts with a barrier of all ranks (Epetra_MpiDistributor). A cell vector already has room
// for the ghost cells' values and its own exchange (deal.II's Partitioner, no barrier). This
// product reads the matrix's compressed rows in place (Epetra's row offsets and values, never
// copied) with the column indices translated once per sparsity pattern into positions in the
// cell vector, and overlaps the ghost exchange with the rows that need no ghost value. Each row
// sums its entries in Epetra's order, as Epetra's kernel does.

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/mesh/fv_geometry.h>

#include <utility>
#include <vector>

namespace fvfsi
{
  class CellMatrixProduct
  {
  public:
    /// Use `matrix` for the products on vectors laid out as `layout`. Cheap when neither the
    /// matrix's sparsity pattern nor the layout changed since the last call (values may change).
    /// Falls back to Trilinos' product if the matrix's storage is not one compressed block or
    /// a column lies outside the layout's owned and ghost cells.
    void reinit(const dealii::TrilinosWrappers::SparseMatrix& matrix, const CellVector& layout);

    /// y = A x (x's ghost values need not be set; they are exchanged here and, if x had none
    /// before, cleared again, so that the solver's later vector operations do not exchange them).
    void vmult(CellVector& y, const CellVector& x) const;

    /// Whether the product is this class's own (false: Trilinos' product).
    bool own_product() const { return own; }

  private:
    const dealii::TrilinosWrappers::SparseMatrix* matrix = nullptr;
    bool own = false;
    // Epetra's compressed rows: row r's entries are [row_offsets[r], row_offsets[r + 1]).
    const int* row_offsets = nullptr;
    const double* values = nullptr;
    /// Per entry: the position of its column in a cell vector's local storage (owned, then ghost).
    std::vector<unsigned int> columns;
    /// Runs [first, last) of rows whose columns are all owned, and of the rest (at least one
    /// ghost column); most rows are interior and lie in long runs.
    std::vector<std::pair<unsigned int, unsigned int>> interior_rows, boundary_rows;
    /// y_r = sum_k A_rk x_k for the rows of `runs` (x_local: the cell vector's local storage).
    void multiply_rows(const std::vector<std::pair<unsigned int, unsigned int>>& runs,
                       const double* x_local, double* y_local) const;
    // What the translation was made for: it is redone when any of these changes.
    const Epetra_CrsMatrix* made_for_matrix = nullptr;
    const int* made_for_indices = nullptr;
    int made_for_entries = -1;
    const dealii::Utilities::MPI::Partitioner* made_for_layout = nullptr;
  };
} // namespace fvfsi
