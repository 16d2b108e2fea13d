#pragma once
// Per-cell Hessians of the components of a cell-centred vector field by a weighted least-squares
// quadratic fit that knows the boundary conditions of a displacement field: symmetry planes
// (mirror images), given values and given normal derivatives (traction faces). Used by the solid
// solver's `Hessian correction` (an extension of the paper, see solid_solver.cc).

#include <fvfsi/fv/cell_gradient.h>
#include <fvfsi/mesh/fv_geometry.h>

#include <array>
#include <vector>

namespace fvfsi
{
  /// Number of independent entries of a symmetric dim x dim tensor.
  template <int dim>
  constexpr unsigned int n_hessian_entries = dim * (dim + 1) / 2;

  /// A symmetric tensor field per cell, entry k = (a, b), a <= b, in the order (0,0), (0,1), ...,
  /// (1,1), ...: one cell vector per entry (ghost values usable after update_ghost_values()).
  template <int dim>
  struct CellHessianField
  {
    std::array<CellVector, n_hessian_entries<dim>> entries;
    dealii::Tensor<2, dim> operator[](unsigned int cell) const;
  };

  /**
   * For every owned cell P, the Hessian of each component u_j of a vector field from a weighted
   * least-squares fit of the quadratic
   *
   *   u_j(r) ~ u_j,P + g . (r - r_P) + 1/2 (r - r_P) . H . (r - r_P)
   *
   * (through the cell value; g and H fitted) to
   *  - the values of the cells that share a vertex with P (weights 1 / |r_c - r_P|^2);
   *  - if P has a `mirror` face (a symmetry plane with normal m): the same cells mirrored across
   *    that plane, with the mirrored vector value u - 2 (u . m) m (a field symmetric about the
   *    plane continues smoothly through it);
   *  - the values on the `known_value` boundary faces of those cells (e.g. fixed displacement);
   *  - the normal derivatives n . grad u_j at the `known_normal_derivative` faces of P (traction
   *    faces: from Eq. 24): next to such a face the cells of the stencil lie in two layers only, and
   *    these data fix the second normal derivative.
   * A cell whose data do not determine a quadratic gets H = 0. The fit is linear in the data, so
   * reinit() stores per cell and datum the coefficients of the n_hessian_entries outputs; compute()
   * is a sparse product.
   *
   * Parallel: the data of an owned cell are in the ghost layer (cells that share a vertex with an
   * owned cell, with their boundary faces); compute() updates the ghost values of H.
   */
  template <int dim>
  /// (Named apart from QuadraticReconstruction's CellHessian, a stored Hessian field.)
  class DisplacementHessian
  {
  public:
    /// Flags indexed like geometry.faces (only boundary and ghost_boundary entries are read).
    DisplacementHessian(const FVGeometry<dim>& geometry, const std::vector<bool>& mirror,
                const std::vector<bool>& known_value, const std::vector<bool>& known_normal_derivative);

    /// Recompute the coefficients; call after FVGeometry::reinit().
    void reinit();

    /// H of each component of `u` (ghost values up to date) in all owned cells, then the ghosts
    /// updated. `face_values` and `face_normal_derivatives` (indexed like geometry.faces) hold the
    /// vector data on the known-value faces (boundary and ghost_boundary) and the
    /// known-normal-derivative faces (boundary).
    void compute(const CellVectorField<dim>& u, const std::vector<dealii::Tensor<1, dim>>& face_values,
                 const std::vector<dealii::Tensor<1, dim>>& face_normal_derivatives,
                 std::array<CellHessianField<dim>, dim>& hessian) const;

    /// Number of owned cells whose data do not determine a quadratic (H = 0 there).
    unsigned int n_undetermined() const { return n_without_fit; }

  private:
    enum class Kind : unsigned char
    {
      cell,             ///< value of cell `index` (mirrored if m is not zero)
      face_value,       ///< value on face `index`
      normal_derivative ///< n . grad u on face `index`
    };
    struct Entry
    {
      Kind kind;
      unsigned int index;
      dealii::Tensor<1, dim> m; ///< unit normal of the mirror plane, or zero
      dealii::Point<dim> plane; ///< a point of the mirror plane
      std::array<double, n_hessian_entries<dim>> coefficient{};
    };

    const FVGeometry<dim>& geometry;
    std::vector<unsigned int> start; ///< per owned cell: its entries [start[c], start[c + 1])
    std::vector<Entry> entries;
    /// Per owned cell: coefficients of u_P (the fit passes through it).
    std::vector<std::array<double, n_hessian_entries<dim>>> self_coefficient;
    unsigned int n_without_fit = 0;
  };
} // namespace fvfsi
