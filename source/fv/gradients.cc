#include <fvfsi/fv/face_loop.h>
#include <fvfsi/fv/gradients.h>

#include <algorithm>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  GaussGreenGradient<dim>::GaussGreenGradient(const FVGeometry<dim>& geometry) : geometry(geometry)
  {
    // The topology, which mesh motion does not change: per owned cell its vertices (the entries
    // start[c]..start[c+1] of vertex and coefficient) and, in the order of Eq. 37's sum, which
    // entry each of its faces' vertices adds to.
    start = {0};
    term_start = {0};
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      const auto& cell_vertices = geometry.cell_vertices(c);
      for (const unsigned int f : geometry.cell_faces(c))
      {
        const auto& face = geometry.faces[f];
        for (unsigned int i = 0; i < face.vertices.size(); ++i)
        {
          const auto it = std::find(cell_vertices.begin(), cell_vertices.end(), face.vertices[i]);
          if (it == cell_vertices.end())
            throw std::logic_error("GaussGreenGradient: a face vertex that is not a cell vertex "
                                   "(fvfsi needs conforming meshes)");
          terms.push_back(
            {f, i, static_cast<unsigned int>(start[c] + (it - cell_vertices.begin()))});
        }
      }
      vertex.insert(vertex.end(), cell_vertices.begin(), cell_vertices.end());
      start.push_back(vertex.size());
      term_start.push_back(terms.size());
    }
    coefficient.resize(vertex.size());
    reinit();
  }

  template <int dim>
  void GaussGreenGradient<dim>::reinit()
  {
    // Eq. 37 as weights of the vertex values: sum over the cell's faces of +-(face weight) / V_P.
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      for (unsigned int k = start[c]; k < start[c + 1]; ++k)
        coefficient[k] = Tensor<1, dim>();
      for (unsigned int t = term_start[c]; t < term_start[c + 1]; ++t)
      {
        const auto& face = geometry.faces[terms[t].face];
        coefficient[terms[t].entry] += (face.P == c ? 1.0 : -1.0) *
                                       face.gauss_green_weight[terms[t].face_vertex] /
                                       geometry.cell_volume[c];
      }
    }
  }

  template <int dim>
  void GaussGreenGradient<dim>::compute(const std::vector<double>& vertex_values,
                                        CellGradient<dim>& gradient, const bool with_ghosts) const
  {
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      Tensor<1, dim> g;
      for (unsigned int i = start[c]; i < start[c + 1]; ++i)
        g += coefficient[i] * vertex_values[vertex[i]];
      gradient.set(c, g);
    }
    if (with_ghosts)
      gradient.update_ghost_values();
  }

  namespace
  {
    // (grad phi)_P = 1/V_P sum_f S_f phi_f with phi_f = w phi_P + (1 - w) phi_N + correction_f.
    template <int dim, typename Correction>
    void gauss_gradient(const FVGeometry<dim>& geometry, const CellVector& phi,
                        const FaceVector& boundary_values, const Correction& correction,
                        CellGradient<dim>& gradient)
    {
      std::vector<Tensor<1, dim>> sum(geometry.n_owned_cells());
      for_each_face(geometry,
                    [&](const unsigned int f, const FaceGeometry<dim>& face)
                    {
                      const double phi_f =
                        face.N == invalid_cell
                          ? boundary_values[f]
                          : face.interpolate(phi.local_element(face.P), phi.local_element(face.N)) +
                              correction(f);
                      add_outflow(face, Tensor<1, dim>(phi_f * face.S), sum);
                    });
      for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
        gradient.set(c, sum[c] / geometry.cell_volume[c]);
      gradient.update_ghost_values();
    }
  } // namespace

  template <int dim>
  void gauss_linear_gradient(const FVGeometry<dim>& geometry, const CellVector& phi,
                             const FaceVector& boundary_values, CellGradient<dim>& gradient,
                             const bool skew_corrected)
  {
    gauss_gradient(
      geometry, phi, boundary_values, [](unsigned int) { return 0.0; }, gradient);
    if (!skew_corrected)
      return;
    // Skew correction: the linear interpolation is a value at r_f' = w r_P + (1 - w) r_N on the
    // line P-N; move it to the face centre r_f with the plain gradient, interpolated the same way.
    const CellGradient<dim> plain = gradient;
    gauss_gradient(
      geometry, phi, boundary_values,
      [&](const unsigned int f)
      {
        const auto& face = geometry.faces[f];
        const Point<dim> r_f_prime =
          face.interpolate(geometry.centroid[face.P], geometry.centroid[face.N]);
        return (face.centre - r_f_prime) * face.interpolate(plain[face.P], plain[face.N]);
      },
      gradient);
  }

  template <int dim>
  LeastSquaresGradient<dim>::LeastSquaresGradient(const FVGeometry<dim>& geometry)
      : geometry(geometry)
  {
    reinit();
  }

  template <int dim>
  void LeastSquaresGradient<dim>::reinit()
  {
    inverse_normal_matrix.assign(geometry.n_owned_cells(), Tensor<2, dim>());
    for_each_face(geometry,
                  [this](const unsigned int, const FaceGeometry<dim>& face)
                  {
                    const Tensor<2, dim> dd = outer_product(face.d, face.d) / face.d.norm_square();
                    add_to_cells(face, dd, dd, inverse_normal_matrix);
                  });
    for (auto& M : inverse_normal_matrix)
      M = invert(M);
  }

  template <int dim>
  void LeastSquaresGradient<dim>::compute(const CellVector& phi, const FaceVector& boundary_values,
                                          CellGradient<dim>& gradient) const
  {
    std::vector<Tensor<1, dim>> rhs(geometry.n_owned_cells());
    for_each_face(geometry,
                  [&](const unsigned int f, const FaceGeometry<dim>& face)
                  {
                    const double phi_P = phi.local_element(face.P);
                    const double phi_other =
                      face.N == invalid_cell ? boundary_values[f] : phi.local_element(face.N);
                    // Both sides see the same d d^T / |d|^2 and the same d (phi_N - phi_P) / |d|^2.
                    const Tensor<1, dim> term = face.d * (phi_other - phi_P) / face.d.norm_square();
                    add_to_cells(face, term, term, rhs);
                  });
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
      gradient.set(c, inverse_normal_matrix[c] * rhs[c]);
    gradient.update_ghost_values();
  }

  template void gauss_linear_gradient(const FVGeometry<2>&, const CellVector&, const FaceVector&,
                                      CellGradient<2>&, bool);
  template void gauss_linear_gradient(const FVGeometry<3>&, const CellVector&, const FaceVector&,
                                      CellGradient<3>&, bool);
  template class GaussGreenGradient<2>;
  template class GaussGreenGradient<3>;
  template class LeastSquaresGradient<2>;
  template class LeastSquaresGradient<3>;
} // namespace fvfsi
