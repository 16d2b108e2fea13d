#pragma once
// A quadratic reconstruction of a cell-centred scalar field: per cell P the gradient g_P and the
// Hessian H_P of the weighted least-squares quadratic through phi_P,
//
//   phi(x) ~ phi_P + g_P . (x - r_P) + 1/2 (x - r_P) . H_P . (x - r_P),
//
// fitted to the values of the vertex-neighbour cells of P (every cell that shares a vertex with P)
// and, at the domain boundary, to the boundary-face values phi_b of the faces that share a vertex
// with P. phi_P is held fixed (the fit passes through it); the dim + dim (dim + 1) / 2 unknowns
// (5 in 2D, 9 in 3D) minimise sum_j w_j (phi_P + g . r_j + 1/2 r_j . H . r_j - phi_j)^2 with
// r_j = x_j - r_P and w_j = 1 / |r_j|^6. The fit is exact for quadratic fields, so g_P is second-
// and H_P first-order accurate for smooth ones: the second-order face normal gradient of the
// Laplacian (FaceGradient::quadratic) uses both.
//
// The weights: g_P's error comes from the cubic Taylor remainder of the stencil values, which grows
// as |r_j|^3, so the far (edge and corner) neighbours should count less than with the 1/|r|^2 of
// the linear vertex fit. On the distorted meshes of tests/core/poisson_convergence (3D, 32^3 cells,
// exact cell values) the max error of g_P is 0.033 with 1/|r|^2, 0.027 with 1/|r|^4, 0.022 with
// 1/|r|^6 and 0.018 with 1/|r|^8, and the max error of the quadratic face normal gradient 0.016,
// 0.012, 0.0088 and 0.0077 (0.0034 with the exact g and H: k . g's error dominates). In the solved
// Poisson problem the observed orders stop improving beyond 1/|r|^6 (doc/results/core.md).
//
// The fit is linear in the data and its matrix depends only on geometry: reinit() stores, per cell
// and stencil entry j, the dim + dim (dim + 1) / 2 coefficients c_j of (g, H) = sum_j c_j (phi_j -
// phi_P) (a 5x5 or 9x9 Cholesky solve per entry), so compute() is a small matrix-vector product
// per cell. Memory: 5 doubles x about 8 entries per cell in 2D (0.4 kB/cell), 9 doubles x about 26
// entries in 3D (2 kB/cell, as much as FVGeometry); set-up about 0.5 us/cell in 2D, 4-5 us/cell in
// 3D; compute() 30-80 ns/cell in 2D, 0.3-0.5 us/cell in 3D (one core, this machine).
//
// Parallel: the p4est ghost layer holds every cell that shares a vertex with an owned cell, so
// the stencil of each owned cell is complete on every rank; compute() fills the owned cells and
// updates the ghosts of g and H (a face to a ghost cell N needs H_N).

#include <deal.II/base/symmetric_tensor.h>

#include <fvfsi/fv/cell_gradient.h>
#include <fvfsi/mesh/fv_geometry.h>

#include <array>
#include <vector>

namespace fvfsi
{
  /// A symmetric second-rank tensor per owned and ghost cell (e.g. the Hessian of a scalar),
  /// stored as dim (dim + 1) / 2 cell vectors of its independent components.
  template <int dim>
  class CellHessian
  {
  public:
    static constexpr unsigned int n_components =
      dealii::SymmetricTensor<2, dim>::n_independent_components;

    CellHessian() = default;
    explicit CellHessian(const FVGeometry<dim>& geometry)
    {
      for (auto& c : components)
      {
        c = geometry.make_cell_vector();
        c.update_ghost_values(); // a new field is readable everywhere, ghosts included
      }
    }

    dealii::SymmetricTensor<2, dim> operator[](const unsigned int cell) const
    {
      dealii::SymmetricTensor<2, dim> H;
      for (unsigned int i = 0; i < n_components; ++i)
        H[dealii::SymmetricTensor<2, dim>::unrolled_to_component_indices(i)] =
          components[i].local_element(cell);
      return H;
    }
    void set(const unsigned int cell, const dealii::SymmetricTensor<2, dim>& H)
    {
      for (unsigned int i = 0; i < n_components; ++i)
        components[i].local_element(cell) =
          H[dealii::SymmetricTensor<2, dim>::unrolled_to_component_indices(i)];
    }
    /// Copy the owners' values into the ghost entries (collective).
    void update_ghost_values() const
    {
      for (const auto& c : components)
        c.update_ghost_values();
    }

    std::array<CellVector, n_components> components;
  };

  template <int dim>
  class QuadraticReconstruction
  {
  public:
    /// Unknowns of the fit: g (dim) and the independent components of H.
    static constexpr unsigned int n_unknowns = dim + CellHessian<dim>::n_components;

    /// Build the stencils (once per mesh topology) and the coefficients (reinit()).
    explicit QuadraticReconstruction(const FVGeometry<dim>& geometry);

    /// Recompute the least-squares coefficients; call after FVGeometry::reinit().
    void reinit();

    /// g_P and H_P of every owned cell, ghosts updated (collective). `phi` must have up-to-date
    /// ghost values; `boundary_values` holds phi_b on every boundary and ghost_boundary face.
    void compute(const CellVector& phi, const FaceVector& boundary_values,
                 CellGradient<dim>& gradient, CellHessian<dim>& hessian) const;

    /// Number of cells (without P) and of boundary faces in the stencil of owned cell c.
    unsigned int n_stencil_cells(unsigned int c) const { return cell_start[c + 1] - cell_start[c]; }
    unsigned int n_stencil_faces(unsigned int c) const { return face_start[c + 1] - face_start[c]; }

  private:
    /// The coefficients of one cell: the rows of (A^T W A)^-1 A^T W for the points r_j - r_P.
    void fit_coefficients(unsigned int c, const std::vector<dealii::Point<dim>>& points,
                          std::vector<std::array<double, n_unknowns>>& coefficients) const;

    const FVGeometry<dim>& geometry;
    // CSR stencils per owned cell: cells [cell_start[c], cell_start[c+1]), boundary faces likewise.
    std::vector<unsigned int> cell_start, stencil_cell;
    std::vector<unsigned int> face_start, stencil_face;
    std::vector<std::array<double, n_unknowns>> cell_coefficient, face_coefficient;
  };
} // namespace fvfsi
