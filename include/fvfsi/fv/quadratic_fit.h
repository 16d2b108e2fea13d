#pragma once
// A weighted least-squares quadratic per cell: for every owned cell P, the gradient g_P and the
// Hessian H_P of
//
//   phi(r) ~ phi_P + g_P . s + 1/2 s . H_P . s,    s = r - r_P,
//
// fitted (through phi_P) to the data of P's neighbourhood:
//  - the values of the cells that share a vertex with P (its vertex neighbours);
//  - optionally boundary-face values, of the faces that touch a vertex of P (the Poisson face
//    gradient) or of the faces of P and its vertex neighbours (the solid's Hessian correction);
//  - optionally, for the symmetry-plane faces of P (`mirror`), P and its vertex neighbours mirrored
//    across the plane (a vector field symmetric about the plane, u - 2 (u.m) m, continues smoothly
//    through it; a scalar keeps its value);
//  - optionally normal derivatives n . grad phi at faces of P (traction faces of the solid: next
//    to such a face the stencil has two cell layers only, and these data fix the second normal
//    derivative).
// The data are weighted by w_j = (L^2 / |s_j|^2)^(p/2), L^2 the mean of |s_j|^2 over the value
// data: p = 6 for the Poisson face gradient (g_P's error is the cubic Taylor remainder, which
// grows like |s|^3, so far neighbours should count less: on the distorted 32^3 meshes of
// tests/core/poisson_convergence the max error of the quadratic face normal gradient is 0.016,
// 0.012, 0.0088 and 0.0077 for p = 2, 4, 6, 8, and the solved problem's orders stop improving
// beyond 6; doc/results/core.md), p = 2 for the solid's Hessians.
//
// The fit is linear in the data and its matrix depends on geometry only: reinit() solves the
// small least-squares problems once (deal.II's LAPACKFullMatrix SVD, on offsets scaled by L so
// that the matrix is O(1)) and stores per cell and datum the coefficients of (g, H); compute() is
// then a sparse product. Memory: (dim + dim (dim + 1) / 2) doubles per datum, about 8 data per
// cell in 2D and 26 in 3D.
//
// Parallel: the p4est ghost layer holds every cell that shares a vertex with an owned cell (with
// their boundary faces), so each owned cell's data are complete on every rank; compute() fills the
// owned cells and updates the ghosts (a face to a ghost cell N needs H_N).

#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/mesh/fv_geometry.h>

#include <array>
#include <vector>

namespace fvfsi
{
  /// Which data a QuadraticFit uses (face masks indexed like FVGeometry::faces; empty: none).
  struct QuadraticFitData
  {
    /// p of the weights (L / |s|)^p.
    double weight_exponent = 6;
    /// Boundary faces whose values enter the fit.
    std::vector<bool> value_faces;
    /// true: of those, the faces that touch a vertex of P; false: the faces of P and of its
    /// vertex neighbours.
    bool value_faces_touch_P = true;
    /// Faces of P on a symmetry plane.
    std::vector<bool> mirror_faces;
    /// Faces of P with a known normal derivative.
    std::vector<bool> normal_derivative_faces;
    /// A cell whose data do not determine a quadratic: true stops with an error, false gives it
    /// g = H = 0 (its user then keeps a first-order form there).
    bool undetermined_is_error = true;
    /// The data determine a quadratic when the scaled least-squares matrix has
    /// sigma_min^2 > this x sigma_max^2.
    double rank_tolerance = 1e-12;
  };

  template <int dim>
  class QuadraticFit
  {
  public:
    /// Unknowns of the fit: g (dim), then H's independent components (CellHessian's order).
    static constexpr unsigned int n_unknowns = dim + CellHessian<dim>::n_components;

    /// Build the stencils (once per mesh topology) and the coefficients (reinit()).
    QuadraticFit(const FVGeometry<dim>& geometry, const QuadraticFitData& data);

    /// Recompute the coefficients; call after FVGeometry::reinit().
    void reinit();

    /// g and H of the scalar `phi` (ghosts up to date) in every owned cell, ghosts updated
    /// (collective). `face_values` and `normal_derivatives` (indexed like FVGeometry::faces) hold
    /// the data of the value and normal-derivative faces (may be empty if there are none).
    void compute(const CellVector& phi, const FaceVector& face_values,
                 const FaceVector& normal_derivatives, CellGradient<dim>& gradient,
                 CellHessian<dim>& hessian) const;

    /// H of each component of the vector field `u` (ghosts up to date); the face data are vectors.
    void compute(const CellVectorField<dim>& u,
                 const std::vector<dealii::Tensor<1, dim>>& face_values,
                 const std::vector<dealii::Tensor<1, dim>>& normal_derivatives,
                 std::array<CellHessian<dim>, dim>& hessian) const;

    /// Number of owned cells whose data do not determine a quadratic (g = H = 0 there).
    unsigned int n_undetermined() const { return n_without_fit; }
    /// Number of data (cells, mirror images, faces) of owned cell c.
    unsigned int n_data(const unsigned int c) const { return start[c + 1] - start[c]; }

  private:
    enum class Kind : unsigned char
    {
      cell,             ///< the value of cell `index`, mirrored across (plane, m) if m != 0
      face_value,       ///< the value on face `index`
      normal_derivative ///< n . grad phi on face `index`
    };
    struct Datum
    {
      Kind kind;
      unsigned int index;
      dealii::Tensor<1, dim> m; ///< unit normal of the mirror plane, or zero
      dealii::Point<dim> plane; ///< a point of the mirror plane
    };
    using Coefficients = std::array<double, n_unknowns>;

    void build_stencil(unsigned int P, const std::vector<std::vector<unsigned int>>& cells_of,
                       const std::vector<std::vector<unsigned int>>& faces_of);
    /// The offsets s_j of cell P's data from r_P; returns L^2 (0 without value data).
    double offsets(unsigned int P, std::vector<dealii::Tensor<1, dim>>& s) const;
    /// The coefficients of cell P's data; false if they do not determine a quadratic.
    bool fit(unsigned int P);

    const FVGeometry<dim>& geometry;
    QuadraticFitData options;
    std::vector<unsigned int> start; ///< per owned cell: its data [start[c], start[c + 1])
    std::vector<Datum> data;
    std::vector<Coefficients> coefficient; ///< per datum
    std::vector<Coefficients> self;        ///< per owned cell: the coefficients of phi_P
    unsigned int n_without_fit = 0;
  };
} // namespace fvfsi
