#pragma once
// Vertex values from cell-centre values by weighted least squares with a linear fit (paper
// Appendix B, Eqs 40-42). The stencil of a vertex is every cell that shares it and, at the domain
// boundary, every boundary face that shares it; weights are inverse squared distances.
//
// The fit is linear in the data, so reinit() stores, per vertex, the coefficient a_j of every
// stencil value: phi_v = sum_j a_j phi_j. interpolate() is then a sparse product.
//
// Parallel: the p4est ghost layer holds every cell that shares a vertex with an owned cell, so
// each rank has the whole stencil of each vertex of its owned cells. Stencils are sorted by global
// cell number, so every rank that sees a vertex sums in the same order and gets the same bits.

#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/mesh/fv_geometry.h>

#include <vector>

namespace fvfsi
{
  template <int dim>
  class VertexInterpolation
  {
  public:
    explicit VertexInterpolation(const FVGeometry<dim>& geometry);

    /// Recompute the least-squares coefficients; call after FVGeometry::reinit(). (The quadratic
    /// terms of subtract_quadratic_terms() follow at its first call.)
    void reinit();

    /// phi at the vertices of the locally owned cells, indexed by triangulation vertex index
    /// (other entries untouched). `phi` must have up-to-date ghost values; `boundary_values` holds
    /// phi_b on every boundary and ghost_boundary face.
    void interpolate(const CellVector& phi, const FaceVector& boundary_values,
                     std::vector<double>& vertex_values) const;

    /// The linear fit is exact for linear fields only: for a quadratic its error is
    /// sum_j a_j 1/2 (r_j - x_v) . H . (r_j - x_v). Subtract that, with H of datum j the Hessian
    /// of its cell (of a boundary face: of the face's cell; ghost values up to date): the vertex
    /// values of interpolate() become exact for quadratics if H is exact, with an O(h^3) error if
    /// H is first-order accurate.
    void subtract_quadratic_terms(const CellHessian<dim>& hessian,
                                  std::vector<double>& vertex_values) const;

    /// Triangulation indices of the vertices of locally owned cells.
    const std::vector<unsigned int>& vertices() const { return vertex_list; }
    /// Number of cells in the stencil of the i-th vertex of vertices().
    unsigned int n_stencil_cells(unsigned int i) const { return cell_start[i + 1] - cell_start[i]; }

  private:
    const FVGeometry<dim>& geometry;
    std::vector<unsigned int> vertex_list;
    // CSR stencils: cells [cell_start[i], cell_start[i+1]) and boundary faces likewise.
    std::vector<unsigned int> cell_start, stencil_cell;
    std::vector<unsigned int> face_start, stencil_face;
    std::vector<double> cell_coefficient, face_coefficient;
    /// The points r_j of the stencil of the i-th vertex: its cells' centroids, then its boundary
    /// faces' centres.
    void stencil_points(unsigned int i, std::vector<dealii::Point<dim>>& r) const;
    /// Per stencil entry: a_j 1/2 (r_j - x_v)_k (r_j - x_v)_l for H's independent components
    /// (k, l) in CellHessian's order, off-diagonal ones doubled (so that the sum over them with
    /// H_kl is a_j 1/2 s.H.s). A cache of the geometry: made by the first
    /// subtract_quadratic_terms() after reinit().
    void compute_quadratic_terms() const;
    mutable bool quadratic_current = false;
    mutable std::vector<std::array<double, CellHessian<dim>::n_components>> cell_quadratic,
      face_quadratic;
  };
} // namespace fvfsi
