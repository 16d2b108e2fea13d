#include <deal.II/base/utilities.h>

#include <fvfsi/fv/quadratic_reconstruction.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    /// The row of the fit's matrix for the offset r = x_j - r_P, in the order of the unknowns
    /// (g_0 .. g_dim-1, then H's independent components in SymmetricTensor's unrolled order):
    /// g . r + 1/2 r . H . r = sum_d g_d r_d + sum_i H_i a_i with a_i = r_k^2 / 2 on the diagonal
    /// (k, k) and r_k r_l off it (the off-diagonal entry appears twice in r . H . r).
    template <int dim>
    std::array<double, QuadraticReconstruction<dim>::n_unknowns>
    quadratic_row(const Tensor<1, dim>& r)
    {
      std::array<double, QuadraticReconstruction<dim>::n_unknowns> row;
      for (unsigned int d = 0; d < dim; ++d)
        row[d] = r[d];
      for (unsigned int i = 0; i < CellHessian<dim>::n_components; ++i)
      {
        const auto kl = SymmetricTensor<2, dim>::unrolled_to_component_indices(i);
        row[dim + i] = kl[0] == kl[1] ? 0.5 * r[kl[0]] * r[kl[0]] : r[kl[0]] * r[kl[1]];
      }
      return row;
    }

    template <std::size_t n>
    using SquareMatrix = std::array<std::array<double, n>, n>;

    /// In place, the Cholesky factor L (lower triangle) of the symmetric positive definite M
    /// (lower triangle given). False if a pivot falls below 1e-12 of M's largest diagonal entry,
    /// i.e. M is singular to working accuracy (its entries are O(1) here).
    template <std::size_t n>
    bool cholesky(SquareMatrix<n>& M)
    {
      double max_diagonal = 0;
      for (unsigned int a = 0; a < n; ++a)
        max_diagonal = std::max(max_diagonal, M[a][a]);
      for (unsigned int a = 0; a < n; ++a)
      {
        for (unsigned int b = 0; b < a; ++b)
          M[a][a] -= M[a][b] * M[a][b];
        if (!(M[a][a] > 1e-12 * max_diagonal))
          return false;
        M[a][a] = std::sqrt(M[a][a]);
        for (unsigned int i = a + 1; i < n; ++i)
        {
          for (unsigned int b = 0; b < a; ++b)
            M[i][a] -= M[i][b] * M[a][b];
          M[i][a] /= M[a][a];
        }
      }
      return true;
    }

    /// x <- (L L^T)^-1 x.
    template <std::size_t n>
    void cholesky_solve(const SquareMatrix<n>& L, std::array<double, n>& x)
    {
      for (unsigned int a = 0; a < n; ++a)
      {
        for (unsigned int b = 0; b < a; ++b)
          x[a] -= L[a][b] * x[b];
        x[a] /= L[a][a];
      }
      for (unsigned int a = n; a-- > 0;)
      {
        for (unsigned int b = a + 1; b < n; ++b)
          x[a] -= L[b][a] * x[b];
        x[a] /= L[a][a];
      }
    }
  } // namespace

  template <int dim>
  QuadraticReconstruction<dim>::QuadraticReconstruction(const FVGeometry<dim>& geometry)
    : geometry(geometry)
  {
    // Cells and boundary faces around every vertex (the ghost layer completes them for the
    // vertices of owned cells).
    const unsigned int n_tria_vertices = geometry.vertices().size();
    std::vector<std::vector<unsigned int>> cells_of(n_tria_vertices), faces_of(n_tria_vertices);
    for (unsigned int c = 0; c < geometry.n_relevant_cells(); ++c)
      for (const unsigned int v : geometry.cell_vertices(c))
        cells_of[v].push_back(c);
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
      if (geometry.faces[f].N == invalid_cell)
        for (const unsigned int v : geometry.faces[f].vertices)
          faces_of[v].push_back(f);

    // The stencil of P: the union over P's vertices, without P, each entry once.
    cell_start = {0};
    face_start = {0};
    std::vector<unsigned int> cells, faces;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      cells.clear();
      faces.clear();
      for (const unsigned int v : geometry.cell_vertices(c))
      {
        cells.insert(cells.end(), cells_of[v].begin(), cells_of[v].end());
        faces.insert(faces.end(), faces_of[v].begin(), faces_of[v].end());
      }
      std::sort(cells.begin(), cells.end());
      cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
      cells.erase(std::find(cells.begin(), cells.end(), c));
      std::sort(faces.begin(), faces.end());
      faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
      stencil_cell.insert(stencil_cell.end(), cells.begin(), cells.end());
      stencil_face.insert(stencil_face.end(), faces.begin(), faces.end());
      cell_start.push_back(stencil_cell.size());
      face_start.push_back(stencil_face.size());
    }
    reinit();
  }

  template <int dim>
  void QuadraticReconstruction<dim>::reinit()
  {
    cell_coefficient.resize(stencil_cell.size());
    face_coefficient.resize(stencil_face.size());
    std::vector<Point<dim>> points;
    std::vector<std::array<double, n_unknowns>> coefficients;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      points.clear();
      for (unsigned int j = cell_start[c]; j < cell_start[c + 1]; ++j)
        points.push_back(geometry.centroid[stencil_cell[j]]);
      for (unsigned int j = face_start[c]; j < face_start[c + 1]; ++j)
        points.push_back(geometry.faces[stencil_face[j]].centre);
      fit_coefficients(c, points, coefficients);
      const unsigned int n_cells = n_stencil_cells(c);
      std::copy(coefficients.begin(), coefficients.begin() + n_cells,
                cell_coefficient.begin() + cell_start[c]);
      std::copy(coefficients.begin() + n_cells, coefficients.end(),
                face_coefficient.begin() + face_start[c]);
    }
  }

  template <int dim>
  void QuadraticReconstruction<dim>::fit_coefficients(
    const unsigned int c, const std::vector<Point<dim>>& points,
    std::vector<std::array<double, n_unknowns>>& coefficients) const
  {
    const unsigned int m = points.size(), n = n_unknowns;
    if (m < n)
      throw std::runtime_error("QuadraticReconstruction: the stencil of cell " +
                               std::to_string(geometry.global_index(c)) + " has " +
                               std::to_string(m) + " points for " + std::to_string(n) +
                               " unknowns");
    // Offsets scaled by the stencil's rms distance h, so that the matrix entries are O(1): the
    // fit then solves for (h g, h^2 H), unscaled below.
    std::vector<Tensor<1, dim>> r(m);
    double h2 = 0;
    for (unsigned int j = 0; j < m; ++j)
    {
      r[j] = points[j] - geometry.centroid[c];
      h2 += r[j].norm_square() / m;
    }
    const double h = std::sqrt(h2);

    // Normal matrix M = A^T W A with rows a_j of the scaled offsets and w_j = (h / |r_j|)^6
    // (the header explains the exponent).
    std::vector<std::array<double, n_unknowns>> rows(m);
    std::vector<double> w(m);
    SquareMatrix<n_unknowns> M{};
    for (unsigned int j = 0; j < m; ++j)
    {
      rows[j] = quadratic_row<dim>(r[j] / h);
      w[j] = Utilities::fixed_power<3>(h2 / r[j].norm_square());
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b <= a; ++b)
          M[a][b] += w[j] * rows[j][a] * rows[j][b];
    }
    // A stencil whose points do not determine a quadratic (never on the meshes fvfsi accepts) is
    // an error rather than a silent garbage Hessian.
    if (!cholesky(M))
      throw std::runtime_error("QuadraticReconstruction: the stencil of cell " +
                               std::to_string(geometry.global_index(c)) +
                               " does not determine a quadratic (singular least-squares matrix)");

    // c_j = M^-1 a_j w_j, unscaled: g = (h g) / h, H = (h^2 H) / h^2.
    coefficients.resize(m);
    for (unsigned int j = 0; j < m; ++j)
    {
      std::array<double, n_unknowns> x = rows[j];
      cholesky_solve(M, x);
      for (unsigned int a = 0; a < n; ++a)
        coefficients[j][a] = x[a] * w[j] / (a < dim ? h : h2);
    }
  }

  template <int dim>
  void QuadraticReconstruction<dim>::compute(const CellVector& phi,
                                             const FaceVector& boundary_values,
                                             CellGradient<dim>& gradient,
                                             CellHessian<dim>& hessian) const
  {
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      const double phi_P = phi.local_element(c);
      std::array<double, n_unknowns> x{};
      for (unsigned int j = cell_start[c]; j < cell_start[c + 1]; ++j)
      {
        const double dphi = phi.local_element(stencil_cell[j]) - phi_P;
        for (unsigned int a = 0; a < n_unknowns; ++a)
          x[a] += cell_coefficient[j][a] * dphi;
      }
      for (unsigned int j = face_start[c]; j < face_start[c + 1]; ++j)
      {
        const double dphi = boundary_values[stencil_face[j]] - phi_P;
        for (unsigned int a = 0; a < n_unknowns; ++a)
          x[a] += face_coefficient[j][a] * dphi;
      }
      Tensor<1, dim> g;
      for (unsigned int d = 0; d < dim; ++d)
        g[d] = x[d];
      SymmetricTensor<2, dim> H;
      for (unsigned int i = 0; i < CellHessian<dim>::n_components; ++i)
        H[SymmetricTensor<2, dim>::unrolled_to_component_indices(i)] = x[dim + i];
      gradient.set(c, g);
      hessian.set(c, H);
    }
    gradient.update_ghost_values();
    hessian.update_ghost_values();
  }

  template class CellHessian<2>;
  template class CellHessian<3>;
  template class QuadraticReconstruction<2>;
  template class QuadraticReconstruction<3>;
} // namespace fvfsi
