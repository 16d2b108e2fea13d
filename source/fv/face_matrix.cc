#include <fvfsi/fv/face_matrix.h>

#include <algorithm>

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
  void FaceMatrix<dim>::add_face_diffusion(const unsigned int f, const double a)
  {
    const auto& face = geometry.faces[f];
    diagonal[face.P] += a;
    upper[f] -= a;
    if (face.kind == FaceKind::interior)
    {
      diagonal[face.N] += a;
      lower[f] -= a;
    }
  }

  template <int dim>
  void FaceMatrix<dim>::copy_to(TrilinosWrappers::SparseMatrix& matrix) const
  {
    std::vector<types::global_dof_index> columns;
    std::vector<double> values;
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

  template class FaceMatrix<2>;
  template class FaceMatrix<3>;
} // namespace fvfsi
