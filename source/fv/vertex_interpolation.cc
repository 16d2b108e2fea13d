#include <fvfsi/fv/vertex_interpolation.h>

#include <algorithm>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  VertexInterpolation<dim>::VertexInterpolation(const FVGeometry<dim>& geometry)
      : geometry(geometry)
  {
    const unsigned int n_tria_vertices = geometry.vertices().size();
    std::vector<std::vector<unsigned int>> cells_of(n_tria_vertices), faces_of(n_tria_vertices);
    std::vector<bool> of_owned_cell(n_tria_vertices, false);
    for (unsigned int c = 0; c < geometry.n_relevant_cells(); ++c)
      for (const unsigned int v : geometry.cell_vertices(c))
      {
        cells_of[v].push_back(c);
        if (c < geometry.n_owned_cells())
          of_owned_cell[v] = true;
      }
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
      if (geometry.faces[f].N == invalid_cell)
        for (const unsigned int v : geometry.faces[f].vertices)
          faces_of[v].push_back(f);

    // Sort every stencil by global cell number (faces: by their cell's number, then face number),
    // which is the same on every rank.
    const auto by_global_cell = [&](const unsigned int a, const unsigned int b)
    { return geometry.global_index(a) < geometry.global_index(b); };
    const auto by_global_face = [&](const unsigned int a, const unsigned int b)
    {
      const auto &fa = geometry.faces[a], &fb = geometry.faces[b];
      return std::make_pair(geometry.global_index(fa.P), fa.face_no) <
             std::make_pair(geometry.global_index(fb.P), fb.face_no);
    };
    cell_start = {0};
    face_start = {0};
    for (unsigned int v = 0; v < n_tria_vertices; ++v)
      if (of_owned_cell[v])
      {
        vertex_list.push_back(v);
        std::sort(cells_of[v].begin(), cells_of[v].end(), by_global_cell);
        std::sort(faces_of[v].begin(), faces_of[v].end(), by_global_face);
        stencil_cell.insert(stencil_cell.end(), cells_of[v].begin(), cells_of[v].end());
        stencil_face.insert(stencil_face.end(), faces_of[v].begin(), faces_of[v].end());
        cell_start.push_back(stencil_cell.size());
        face_start.push_back(stencil_face.size());
      }
    reinit();
  }

  template <int dim>
  void VertexInterpolation<dim>::reinit()
  {
    cell_coefficient.resize(stencil_cell.size());
    face_coefficient.resize(stencil_face.size());
    quadratic_current = false; // computed by subtract_quadratic_terms() when it is first called
    std::vector<Point<dim>> r;
    std::vector<double> w;
    for (unsigned int i = 0; i < vertex_list.size(); ++i)
    {
      const Point<dim>& x_v = geometry.vertices()[vertex_list[i]];
      stencil_points(i, r);

      // Eq. 41: weighted reference point r_i0, with w_ij = 1 / |r_ij - x_v|^2.
      w.resize(r.size());
      double sum_w = 0;
      Point<dim> r0;
      for (unsigned int j = 0; j < r.size(); ++j)
      {
        w[j] = 1.0 / (r[j] - x_v).norm_square();
        sum_w += w[j];
        r0 += w[j] * r[j];
      }
      r0 /= sum_w;
      // Eq. 42: normal equations M C = sum_j w_j X_j (phi_j - phi_0), M = sum_j w_j X_j X_j^T.
      Tensor<2, dim> M;
      for (unsigned int j = 0; j < r.size(); ++j)
        M += w[j] * outer_product(r[j] - r0, r[j] - r0);
      // A stencil whose points do not span space (never on a valid mesh) keeps the weighted mean.
      const bool full_rank = determinant(M) > 1e-12 * std::pow(trace(M), dim);
      const Tensor<1, dim> a = full_rank ? invert(M) * (x_v - r0) : Tensor<1, dim>();
      // phi_v = phi_0 + C . (x_v - r0) = sum_j [w_j / sum_w + w_j a . (r_j - r0)] phi_j.
      const unsigned int n_cells = cell_start[i + 1] - cell_start[i];
      for (unsigned int j = 0; j < r.size(); ++j)
      {
        const double coefficient = w[j] / sum_w + w[j] * (a * (r[j] - r0));
        if (j < n_cells)
          cell_coefficient[cell_start[i] + j] = coefficient;
        else
          face_coefficient[face_start[i] + j - n_cells] = coefficient;
      }
    }
  }

  template <int dim>
  void VertexInterpolation<dim>::stencil_points(const unsigned int i,
                                                std::vector<Point<dim>>& r) const
  {
    r.clear();
    for (unsigned int j = cell_start[i]; j < cell_start[i + 1]; ++j)
      r.push_back(geometry.centroid[stencil_cell[j]]);
    for (unsigned int j = face_start[i]; j < face_start[i + 1]; ++j)
      r.push_back(geometry.faces[stencil_face[j]].centre);
  }

  template <int dim>
  void VertexInterpolation<dim>::compute_quadratic_terms() const
  {
    // a_j 1/2 s_k s_l per stencil entry, s = r_j - x_v (a moving mesh's fluid never asks for
    // them: computed here, once per reinit(), only for a caller of subtract_quadratic_terms()).
    cell_quadratic.resize(stencil_cell.size());
    face_quadratic.resize(stencil_face.size());
    std::vector<Point<dim>> r;
    for (unsigned int i = 0; i < vertex_list.size(); ++i)
    {
      const Point<dim>& x_v = geometry.vertices()[vertex_list[i]];
      stencil_points(i, r);
      const unsigned int n_cells = cell_start[i + 1] - cell_start[i];
      for (unsigned int j = 0; j < r.size(); ++j)
      {
        const bool cell = j < n_cells;
        const double coefficient = cell ? cell_coefficient[cell_start[i] + j]
                                        : face_coefficient[face_start[i] + j - n_cells];
        auto& quadratic =
          cell ? cell_quadratic[cell_start[i] + j] : face_quadratic[face_start[i] + j - n_cells];
        const Tensor<1, dim> s = r[j] - x_v;
        for (unsigned int k = 0; k < quadratic.size(); ++k)
        {
          const auto ab = SymmetricTensor<2, dim>::unrolled_to_component_indices(k);
          quadratic[k] = coefficient * (ab[0] == ab[1] ? 0.5 : 1.0) * s[ab[0]] * s[ab[1]];
        }
      }
    }
    quadratic_current = true;
  }

  template <int dim>
  void VertexInterpolation<dim>::interpolate(const CellVector& phi,
                                             const FaceVector& boundary_values,
                                             std::vector<double>& vertex_values) const
  {
    vertex_values.resize(geometry.vertices().size());
    for (unsigned int i = 0; i < vertex_list.size(); ++i)
    {
      double value = 0;
      for (unsigned int j = cell_start[i]; j < cell_start[i + 1]; ++j)
        value += cell_coefficient[j] * phi.local_element(stencil_cell[j]);
      for (unsigned int j = face_start[i]; j < face_start[i + 1]; ++j)
        value += face_coefficient[j] * boundary_values[stencil_face[j]];
      vertex_values[vertex_list[i]] = value;
    }
  }

  template <int dim>
  void VertexInterpolation<dim>::subtract_quadratic_terms(const CellHessian<dim>& hessian,
                                                          std::vector<double>& vertex_values) const
  {
    if (!quadratic_current)
      compute_quadratic_terms();
    constexpr unsigned int n_h = CellHessian<dim>::n_components;
    for (unsigned int i = 0; i < vertex_list.size(); ++i)
    {
      double sum = 0;
      for (unsigned int j = cell_start[i]; j < cell_start[i + 1]; ++j)
        for (unsigned int k = 0; k < n_h; ++k)
          sum += cell_quadratic[j][k] * hessian.components[k].local_element(stencil_cell[j]);
      for (unsigned int j = face_start[i]; j < face_start[i + 1]; ++j)
        for (unsigned int k = 0; k < n_h; ++k)
          sum += face_quadratic[j][k] *
                 hessian.components[k].local_element(geometry.faces[stencil_face[j]].P);
      vertex_values[vertex_list[i]] -= sum;
    }
  }

  template class VertexInterpolation<2>;
  template class VertexInterpolation<3>;
} // namespace fvfsi
