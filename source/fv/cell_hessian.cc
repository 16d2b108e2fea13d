#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fvfsi/fv/cell_hessian.h>

#include <algorithm>
#include <cmath>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  Tensor<2, dim> CellHessianField<dim>::operator[](const unsigned int cell) const
  {
    Tensor<2, dim> H;
    unsigned int k = 0;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = a; b < dim; ++b, ++k)
        H[a][b] = H[b][a] = entries[k].local_element(cell);
    return H;
  }

  namespace
  {
    // Cholesky test of a symmetric positive semi-definite matrix: false if a pivot falls below
    // `tolerance` times the largest diagonal entry (the data do not determine a quadratic).
    bool well_posed(const FullMatrix<double>& M, const double tolerance)
    {
      const unsigned int m = M.m();
      double max_diagonal = 0;
      for (unsigned int r = 0; r < m; ++r)
        max_diagonal = std::max(max_diagonal, M(r, r));
      FullMatrix<double> C(m, m);
      for (unsigned int r = 0; r < m; ++r)
        for (unsigned int c = 0; c <= r; ++c)
        {
          double sum = M(r, c);
          for (unsigned int k = 0; k < c; ++k)
            sum -= C(r, k) * C(c, k);
          if (r == c)
          {
            if (!(sum > tolerance * max_diagonal))
              return false;
            C(r, r) = std::sqrt(sum);
          }
          else
            C(r, c) = sum / C(c, c);
        }
      return true;
    }
  } // namespace

  template <int dim>
  DisplacementHessian<dim>::DisplacementHessian(const FVGeometry<dim>& geometry, const std::vector<bool>& mirror,
                                const std::vector<bool>& known_value,
                                const std::vector<bool>& known_normal_derivative)
    : geometry(geometry)
  {
    std::vector<std::vector<unsigned int>> cells_of(geometry.vertices().size());
    for (unsigned int c = 0; c < geometry.n_relevant_cells(); ++c)
      for (const unsigned int v : geometry.cell_vertices(c))
        cells_of[v].push_back(c);
    start = {0};
    std::vector<unsigned int> cells;
    for (unsigned int P = 0; P < geometry.n_owned_cells(); ++P)
    {
      cells.clear();
      for (const unsigned int v : geometry.cell_vertices(P))
        cells.insert(cells.end(), cells_of[v].begin(), cells_of[v].end());
      // Sorted by global number: the same sums on every rank.
      std::sort(cells.begin(), cells.end(), [&](const unsigned int a, const unsigned int b) {
        return geometry.global_index(a) < geometry.global_index(b);
      });
      cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
      for (const unsigned int c : cells)
        if (c != P)
          entries.push_back({Kind::cell, c, Tensor<1, dim>(), Point<dim>()});
      for (const unsigned int g : geometry.cell_faces(P))
        if (geometry.faces[g].N == invalid_cell && mirror[g])
          for (const unsigned int c : cells)
            entries.push_back({Kind::cell, c, geometry.faces[g].n, geometry.faces[g].centre});
      for (const unsigned int c : cells)
        for (const unsigned int g : geometry.cell_faces(c))
          if (geometry.faces[g].N == invalid_cell && known_value[g])
            entries.push_back({Kind::face_value, g, Tensor<1, dim>(), Point<dim>()});
      for (const unsigned int g : geometry.cell_faces(P))
        if (geometry.faces[g].N == invalid_cell && known_normal_derivative[g])
          entries.push_back({Kind::normal_derivative, g, Tensor<1, dim>(), Point<dim>()});
      start.push_back(entries.size());
    }
    reinit();
  }

  template <int dim>
  void DisplacementHessian<dim>::reinit()
  {
    constexpr unsigned int n_h = n_hessian_entries<dim>;
    constexpr unsigned int m = dim + n_h; // unknowns g, H
    self_coefficient.assign(geometry.n_owned_cells(), {});
    n_without_fit = 0;
    std::vector<Tensor<1, dim>> s;
    for (unsigned int P = 0; P < geometry.n_owned_cells(); ++P)
    {
      const unsigned int n_data = start[P + 1] - start[P];
      for (unsigned int j = start[P]; j < start[P + 1]; ++j)
        entries[j].coefficient = {};
      // Positions relative to r_P, in units of the rms distance L of the value data.
      s.resize(n_data);
      double L2 = 0;
      unsigned int n_values = 0;
      for (unsigned int j = 0; j < n_data; ++j)
      {
        const Entry& e = entries[start[P] + j];
        Point<dim> r = e.kind == Kind::cell ? geometry.centroid[e.index] : geometry.faces[e.index].centre;
        r -= 2 * ((r - e.plane) * e.m) * e.m; // mirror image (no-op for m = 0)
        s[j] = r - geometry.centroid[P];
        if (e.kind != Kind::normal_derivative)
        {
          L2 += s[j].norm_square();
          ++n_values;
        }
      }
      if (n_data < m || n_values == 0)
      {
        ++n_without_fit;
        continue;
      }
      const double L = std::sqrt(L2 / n_values);
      // Rows in the unknowns (g L, H L^2): a value datum u(r) - u_P = g.s + 1/2 s.H.s, a normal
      // derivative datum L n . grad u(r_f) = n . (g L) + n . (H L^2) . s / L.
      FullMatrix<double> A(n_data, m);
      std::vector<double> w(n_data);
      for (unsigned int j = 0; j < n_data; ++j)
      {
        const Entry& e = entries[start[P] + j];
        const Tensor<1, dim> x = s[j] / L;
        w[j] = 1 / x.norm_square();
        unsigned int col = 0;
        if (e.kind == Kind::normal_derivative)
        {
          const Tensor<1, dim>& n = geometry.faces[e.index].n;
          for (unsigned int a = 0; a < dim; ++a)
            A(j, col++) = n[a];
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = a; b < dim; ++b)
              A(j, col++) = a == b ? n[a] * x[a] : n[a] * x[b] + n[b] * x[a];
        }
        else
        {
          for (unsigned int a = 0; a < dim; ++a)
            A(j, col++) = x[a];
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = a; b < dim; ++b)
              A(j, col++) = a == b ? 0.5 * x[a] * x[a] : x[a] * x[b];
        }
      }
      FullMatrix<double> M(m, m);
      for (unsigned int r = 0; r < m; ++r)
        for (unsigned int c = 0; c < m; ++c)
          for (unsigned int j = 0; j < n_data; ++j)
            M(r, c) += A(j, r) * w[j] * A(j, c);
      if (!well_posed(M, 1e-10))
      {
        ++n_without_fit;
        continue;
      }
      FullMatrix<double> M_inverse(m, m);
      M_inverse.invert(M);
      // Output k is H_k L^2 = (M^-1 A^T W rhs)_{dim + k}; rhs is (value - u_P) or L g_n.
      for (unsigned int k = 0; k < n_h; ++k)
        for (unsigned int j = 0; j < n_data; ++j)
        {
          Entry& e = entries[start[P] + j];
          double a = 0;
          for (unsigned int r = 0; r < m; ++r)
            a += M_inverse(dim + k, r) * A(j, r);
          a *= w[j] / (L * L);
          if (e.kind == Kind::normal_derivative)
            e.coefficient[k] = a * L;
          else
          {
            e.coefficient[k] = a;
            self_coefficient[P][k] -= a;
          }
        }
    }
  }

  template <int dim>
  void DisplacementHessian<dim>::compute(const CellVectorField<dim>& u,
                                 const std::vector<Tensor<1, dim>>& face_values,
                                 const std::vector<Tensor<1, dim>>& face_normal_derivatives,
                                 std::array<CellHessianField<dim>, dim>& hessian) const
  {
    constexpr unsigned int n_h = n_hessian_entries<dim>;
    for (auto& field : hessian)
      for (auto& v : field.entries)
        if (v.size() == 0)
          v = geometry.make_cell_vector();
    for (unsigned int P = 0; P < geometry.n_owned_cells(); ++P)
    {
      std::array<Tensor<1, dim>, n_h> H; // H[k][j]: entry k of the Hessian of u_j
      const Tensor<1, dim> u_P = u[P];
      for (unsigned int k = 0; k < n_h; ++k)
        H[k] = self_coefficient[P][k] * u_P;
      for (unsigned int j = start[P]; j < start[P + 1]; ++j)
      {
        const Entry& e = entries[j];
        Tensor<1, dim> datum;
        switch (e.kind)
        {
        case Kind::cell:
          datum = u[e.index];
          datum -= 2 * (datum * e.m) * e.m;
          break;
        case Kind::face_value:
          datum = face_values[e.index];
          break;
        case Kind::normal_derivative:
          datum = face_normal_derivatives[e.index];
          break;
        }
        for (unsigned int k = 0; k < n_h; ++k)
          H[k] += e.coefficient[k] * datum;
      }
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int k = 0; k < n_h; ++k)
          hessian[i].entries[k].local_element(P) = H[k][i];
    }
    for (auto& field : hessian)
      for (auto& v : field.entries)
        v.update_ghost_values();
  }

  template struct CellHessianField<2>;
  template struct CellHessianField<3>;
  template class DisplacementHessian<2>;
  template class DisplacementHessian<3>;
} // namespace fvfsi
