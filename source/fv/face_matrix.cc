#include <fvfsi/fv/face_matrix.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  FaceMatrix<dim>::FaceMatrix(const FVGeometry<dim>& geometry) : geometry(geometry)
  {
    reinit();
  }

  template <int dim>
  void FaceMatrix<dim>::reinit()
  {
    entry_source.clear();
    diagonal.assign(geometry.n_owned_cells(), 0.0);
    upper.assign(geometry.faces.size(), 0.0);
    lower.assign(geometry.faces.size(), 0.0);
  }

  template <int dim>
  void FaceMatrix<dim>::zero()
  {
    std::fill(diagonal.begin(), diagonal.end(), 0.0);
    std::fill(upper.begin(), upper.end(), 0.0);
    std::fill(lower.begin(), lower.end(), 0.0);
  }

  template <int dim>
  void FaceMatrix<dim>::copy_to(TrilinosWrappers::SparseMatrix& matrix) const
  {
    if (&matrix != layout_of || entry_source.empty())
    {
      set_rows(matrix);
      return;
    }
    // The layout is known: write the values straight into the Epetra rows (no search for the
    // column of each entry, which took most of the time of a matrix.set() per row).
    // (deal.II hands out the Epetra matrix const; its values are ours to write.)
    auto& epetra = const_cast<Epetra_CrsMatrix&>(matrix.trilinos_matrix());
    unsigned int k = 0;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      int n;
      double* values;
      int* indices;
      epetra.ExtractMyRowView(c, n, values, indices);
      for (int j = 0; j < n; ++j, ++k)
      {
        const int source = entry_source[k];
        values[j] = source < 0        ? diagonal[c]
                    : source % 2 == 0 ? upper[source / 2]
                                      : lower[source / 2];
      }
    }
  }

  template <int dim>
  void FaceMatrix<dim>::set_rows(TrilinosWrappers::SparseMatrix& matrix) const
  {
    std::vector<types::global_dof_index> columns;
    std::vector<double> values;
    std::vector<int> source;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      columns.assign(1, geometry.global_index(c));
      values.assign(1, diagonal[c]);
      for (const unsigned int f : geometry.cell_faces(c))
      {
        const auto& face = geometry.faces[f];
        if (face.N == invalid_cell)
          continue;
        const bool is_P = face.P == c;
        columns.push_back(geometry.global_index(is_P ? face.N : face.P));
        values.push_back(is_P ? upper[f] : lower[f]);
      }
      matrix.set(columns[0], columns.size(), columns.data(), values.data());
    }
    matrix.compress(VectorOperation::insert);
    // Where each stored entry of the owned rows comes from, in Epetra's order: the diagonal (-1),
    // upper[f] (2 f) or lower[f] (2 f + 1).
    entry_source.clear();
    const Epetra_CrsMatrix& epetra = matrix.trilinos_matrix();
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      int n;
      double* row_values;
      int* indices;
      epetra.ExtractMyRowView(c, n, row_values, indices);
      for (int j = 0; j < n; ++j)
      {
        const auto column = static_cast<types::global_dof_index>(epetra.ColMap().GID(indices[j]));
        int from = -2;
        if (column == geometry.global_index(c))
          from = -1;
        else
          for (const unsigned int f : geometry.cell_faces(c))
          {
            const auto& face = geometry.faces[f];
            if (face.N == invalid_cell)
              continue;
            const bool is_P = face.P == c;
            if (geometry.global_index(is_P ? face.N : face.P) == column)
              from = is_P ? 2 * f : 2 * f + 1;
          }
        if (from == -2)
          throw std::logic_error("FaceMatrix: a matrix entry that no face fills");
        entry_source.push_back(from);
      }
    }
    layout_of = &matrix;
  }

  template <int dim>
  void FaceMatrix<dim>::off_diagonal_product(const CellVector& x, std::vector<double>& y) const
  {
    y.assign(geometry.n_owned_cells(), 0.0);
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
    {
      const auto& face = geometry.faces[f];
      if (face.kind == FaceKind::interior)
      {
        y[face.P] += upper[f] * x.local_element(face.N);
        y[face.N] += lower[f] * x.local_element(face.P);
      }
      else if (face.kind == FaceKind::processor)
        y[face.P] += upper[f] * x.local_element(face.N);
    }
  }

  template <int dim>
  void FaceMatrix<dim>::off_diagonal_sum(std::vector<double>& y) const
  {
    y.assign(geometry.n_owned_cells(), 0.0);
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
    {
      const auto& face = geometry.faces[f];
      if (face.kind == FaceKind::interior)
      {
        y[face.P] += upper[f];
        y[face.N] += lower[f];
      }
      else if (face.kind == FaceKind::processor)
        y[face.P] += upper[f];
    }
  }

  template class FaceMatrix<2>;
  template class FaceMatrix<3>;
} // namespace fvfsi
