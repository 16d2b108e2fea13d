#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fvfsi/fv/quadratic_fit.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    /// The row of a value datum at the scaled offset x: g . x + 1/2 x . H . x in the unknowns
    /// (g, H's independent components): x_d, then x_k^2 / 2 on the diagonal (k, k) and x_k x_l
    /// off it (the off-diagonal entry appears twice in x . H . x).
    template <int dim, typename Row>
    void value_row(const Tensor<1, dim>& x, Row& row)
    {
      for (unsigned int d = 0; d < dim; ++d)
        row[d] = x[d];
      for (unsigned int i = 0; i < CellHessian<dim>::n_components; ++i)
      {
        const auto kl = SymmetricTensor<2, dim>::unrolled_to_component_indices(i);
        row[dim + i] = kl[0] == kl[1] ? 0.5 * x[kl[0]] * x[kl[0]] : x[kl[0]] * x[kl[1]];
      }
    }

    /// The row of a normal-derivative datum: n . (g + H x), x the scaled offset of the face.
    template <int dim, typename Row>
    void normal_derivative_row(const Tensor<1, dim>& n, const Tensor<1, dim>& x, Row& row)
    {
      for (unsigned int d = 0; d < dim; ++d)
        row[d] = n[d];
      for (unsigned int i = 0; i < CellHessian<dim>::n_components; ++i)
      {
        const auto kl = SymmetricTensor<2, dim>::unrolled_to_component_indices(i);
        row[dim + i] =
          kl[0] == kl[1] ? n[kl[0]] * x[kl[0]] : n[kl[0]] * x[kl[1]] + n[kl[1]] * x[kl[0]];
      }
    }

    template <int dim>
    SymmetricTensor<2, dim> hessian_from(const double* x)
    {
      SymmetricTensor<2, dim> H;
      for (unsigned int i = 0; i < CellHessian<dim>::n_components; ++i)
        H[SymmetricTensor<2, dim>::unrolled_to_component_indices(i)] = x[i];
      return H;
    }
  } // namespace

  template <int dim>
  QuadraticFit<dim>::QuadraticFit(const FVGeometry<dim>& geometry, const QuadraticFitData& data)
      : geometry(geometry), options(data)
  {
    // Cells and boundary faces around every vertex (the ghost layer completes them for the
    // vertices of owned cells).
    const unsigned int n_vertices = geometry.vertices().size();
    std::vector<std::vector<unsigned int>> cells_of(n_vertices), faces_of(n_vertices);
    for (unsigned int c = 0; c < geometry.n_relevant_cells(); ++c)
      for (const unsigned int v : geometry.cell_vertices(c))
        cells_of[v].push_back(c);
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
      if (geometry.faces[f].N == invalid_cell)
        for (const unsigned int v : geometry.faces[f].vertices)
          faces_of[v].push_back(f);
    start = {0};
    for (unsigned int P = 0; P < geometry.n_owned_cells(); ++P)
      build_stencil(P, cells_of, faces_of);
    reinit();
  }

  template <int dim>
  void QuadraticFit<dim>::build_stencil(const unsigned int P,
                                        const std::vector<std::vector<unsigned int>>& cells_of,
                                        const std::vector<std::vector<unsigned int>>& faces_of)
  {
    const auto masked = [](const std::vector<bool>& mask, const unsigned int f)
    { return !mask.empty() && mask[f]; };
    // P and its vertex neighbours, and the boundary faces that touch P, in global order (every
    // rank that holds P sums the same terms in the same order).
    std::vector<unsigned int> cells, faces;
    for (const unsigned int v : geometry.cell_vertices(P))
    {
      cells.insert(cells.end(), cells_of[v].begin(), cells_of[v].end());
      faces.insert(faces.end(), faces_of[v].begin(), faces_of[v].end());
    }
    std::sort(cells.begin(), cells.end(),
              [&](const unsigned int a, const unsigned int b)
              { return geometry.global_index(a) < geometry.global_index(b); });
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    if (!options.value_faces_touch_P)
    { // the faces of P and its vertex neighbours instead
      faces.clear();
      for (const unsigned int c : cells)
        for (const unsigned int f : geometry.cell_faces(c))
          if (geometry.faces[f].N == invalid_cell)
            faces.push_back(f);
    }
    const auto face_order = [&](const unsigned int a, const unsigned int b)
    {
      const auto &fa = geometry.faces[a], &fb = geometry.faces[b];
      return std::make_pair(geometry.global_index(fa.P), fa.face_no) <
             std::make_pair(geometry.global_index(fb.P), fb.face_no);
    };
    std::sort(faces.begin(), faces.end(), face_order);
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());

    for (const unsigned int c : cells)
      if (c != P)
        data.push_back({Kind::cell, c, Tensor<1, dim>(), Point<dim>()});
    for (const unsigned int g : geometry.cell_faces(P))
      if (geometry.faces[g].N == invalid_cell && masked(options.mirror_faces, g))
        for (const unsigned int c : cells)
          data.push_back({Kind::cell, c, geometry.faces[g].n, geometry.faces[g].centre});
    for (const unsigned int f : faces)
      if (masked(options.value_faces, f))
        data.push_back({Kind::face_value, f, Tensor<1, dim>(), Point<dim>()});
    for (const unsigned int g : geometry.cell_faces(P))
      if (geometry.faces[g].N == invalid_cell && masked(options.normal_derivative_faces, g))
        data.push_back({Kind::normal_derivative, g, Tensor<1, dim>(), Point<dim>()});
    start.push_back(data.size());
  }

  template <int dim>
  void QuadraticFit<dim>::reinit()
  {
    coefficient.assign(data.size(), Coefficients{});
    self.assign(geometry.n_owned_cells(), Coefficients{});
    n_without_fit = 0;
    for (unsigned int P = 0; P < geometry.n_owned_cells(); ++P)
      if (!fit(P))
      {
        if (options.undetermined_is_error)
          throw std::runtime_error(
            "QuadraticFit: the neighbourhood of cell " + std::to_string(geometry.global_index(P)) +
            " does not determine a quadratic (" + std::to_string(n_data(P)) + " data for " +
            std::to_string(n_unknowns) + " unknowns, or rank deficient)");
        ++n_without_fit;
      }
  }

  template <int dim>
  double QuadraticFit<dim>::offsets(const unsigned int P, std::vector<Tensor<1, dim>>& s) const
  {
    // Offsets from r_P (mirror images reflected), and L^2, their mean square over value data.
    const unsigned int n = n_data(P);
    s.resize(n);
    double L2 = 0;
    unsigned int n_values = 0;
    for (unsigned int j = 0; j < n; ++j)
    {
      const Datum& d = data[start[P] + j];
      Point<dim> r =
        d.kind == Kind::cell ? geometry.centroid[d.index] : geometry.faces[d.index].centre;
      r -= 2 * ((r - d.plane) * d.m) * d.m; // mirror image (no-op for m = 0)
      s[j] = r - geometry.centroid[P];
      if (d.kind != Kind::normal_derivative)
      {
        L2 += s[j].norm_square();
        ++n_values;
      }
    }
    return n_values == 0 ? 0 : L2 / n_values;
  }

  template <int dim>
  bool QuadraticFit<dim>::fit(const unsigned int P)
  {
    const unsigned int n = n_data(P), m = n_unknowns;
    std::vector<Tensor<1, dim>> s;
    const double L2 = offsets(P, s), L = std::sqrt(L2);
    if (n < m || L2 == 0)
      return false;
    // Rows in the scaled unknowns (L g, L^2 H); a normal-derivative datum is scaled by L too.
    // B = W^(1/2) A, whose pseudo-inverse times W^(1/2) maps the data to the unknowns.
    LAPACKFullMatrix<double> B(n, m);
    std::vector<double> sqrt_w(n), row(m);
    for (unsigned int j = 0; j < n; ++j)
    {
      const Datum& d = data[start[P] + j];
      const Tensor<1, dim> x = s[j] / L;
      const double q = 1 / x.norm_square(), p = options.weight_exponent;
      sqrt_w[j] = std::sqrt(p == 2 ? q : p == 6 ? q * q * q : std::pow(q, p / 2));
      if (d.kind == Kind::normal_derivative)
        normal_derivative_row(geometry.faces[d.index].n, x, row);
      else
        value_row(x, row);
      for (unsigned int a = 0; a < m; ++a)
        B(j, a) = sqrt_w[j] * row[a];
    }
    B.compute_svd();
    const double sigma_max = B.singular_value(0), sigma_min = B.singular_value(m - 1);
    if (!(sigma_min * sigma_min > options.rank_tolerance * sigma_max * sigma_max))
      return false;
    B.compute_inverse_svd();
    // Coefficient of datum j: column j of pinv(B) W^(1/2), unscaled (g = (L g) / L, H = (L^2 H) /
    // L^2, a normal derivative datum times L). Value data enter as phi_j - phi_P.
    Vector<double> e(n), x(m);
    for (unsigned int j = 0; j < n; ++j)
    {
      e = 0;
      e(j) = sqrt_w[j];
      B.vmult(x, e);
      const bool value = data[start[P] + j].kind != Kind::normal_derivative;
      Coefficients& c = coefficient[start[P] + j];
      for (unsigned int a = 0; a < m; ++a)
      {
        c[a] = x(a) / (a < dim ? L : L2) * (value ? 1 : L);
        if (value)
          self[P][a] -= c[a];
      }
    }
    return true;
  }

  template <int dim>
  void QuadraticFit<dim>::compute(const CellVector& phi, const FaceVector& face_values,
                                  const FaceVector& normal_derivatives, CellGradient<dim>& gradient,
                                  CellHessian<dim>& hessian) const
  {
    for (unsigned int P = 0; P < geometry.n_owned_cells(); ++P)
    {
      Coefficients x = self[P];
      for (auto& a : x)
        a *= phi.local_element(P);
      for (unsigned int j = start[P]; j < start[P + 1]; ++j)
      {
        const Datum& d = data[j];
        const double datum = d.kind == Kind::cell         ? phi.local_element(d.index)
                             : d.kind == Kind::face_value ? face_values[d.index]
                                                          : normal_derivatives[d.index];
        for (unsigned int a = 0; a < n_unknowns; ++a)
          x[a] += coefficient[j][a] * datum;
      }
      Tensor<1, dim> g;
      for (unsigned int a = 0; a < dim; ++a)
        g[a] = x[a];
      gradient.set(P, g);
      hessian.set(P, hessian_from<dim>(&x[dim]));
    }
    gradient.update_ghost_values();
    hessian.update_ghost_values();
  }

  template <int dim>
  void QuadraticFit<dim>::compute(const CellVectorField<dim>& u,
                                  const std::vector<Tensor<1, dim>>& face_values,
                                  const std::vector<Tensor<1, dim>>& normal_derivatives,
                                  std::array<CellHessian<dim>, dim>& hessian) const
  {
    for (unsigned int P = 0; P < geometry.n_owned_cells(); ++P)
    {
      std::array<Tensor<1, dim>, n_unknowns> X; // X[a][i]: unknown a of component u_i
      const Tensor<1, dim> u_P = u[P];
      for (unsigned int a = 0; a < n_unknowns; ++a)
        X[a] = self[P][a] * u_P;
      for (unsigned int j = start[P]; j < start[P + 1]; ++j)
      {
        const Datum& d = data[j];
        Tensor<1, dim> datum;
        if (d.kind == Kind::cell)
        {
          datum = u[d.index];
          datum -= 2 * (datum * d.m) * d.m; // mirrored vector value (no-op for m = 0)
        }
        else
          datum = d.kind == Kind::face_value ? face_values[d.index] : normal_derivatives[d.index];
        for (unsigned int a = 0; a < n_unknowns; ++a)
          X[a] += coefficient[j][a] * datum;
      }
      for (unsigned int i = 0; i < dim; ++i)
      {
        std::array<double, CellHessian<dim>::n_components> h;
        for (unsigned int k = 0; k < h.size(); ++k)
          h[k] = X[dim + k][i];
        hessian[i].set(P, hessian_from<dim>(h.data()));
      }
    }
    for (auto& H : hessian)
      H.update_ghost_values();
  }

  template class QuadraticFit<2>;
  template class QuadraticFit<3>;
} // namespace fvfsi
