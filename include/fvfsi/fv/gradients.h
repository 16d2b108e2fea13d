#pragma once
// Gradients of a cell-centred scalar field (paper Appendix A, Eqs 37 and 39), and the weighted
// least-squares cell gradient used by the Demirdzic-Muzaferija discretisation.

#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/mesh/fv_geometry.h>

#include <vector>

namespace fvfsi
{
  /**
   * Vertex-based Gauss-Green cell gradient (Eq. 37): (grad phi)_P = 1/V_P sum_tau n_tau phi_tau S_tau,
   * over the triangles tau of all faces of P, with phi_tau the mean of its corner values. Exact for
   * linear fields on any mesh. The geometry is folded into one coefficient vector per cell and
   * vertex, (grad phi)_P = sum_v c_Pv phi_v, by reinit() (the face loop, with its many reads of
   * the large face records, done once per mesh motion): compute() is a short sparse product.
   */
  template <int dim>
  class GaussGreenGradient
  {
  public:
    explicit GaussGreenGradient(const FVGeometry<dim>& geometry);
    /// Recompute the coefficients; call after FVGeometry::reinit().
    void reinit();
    /// Fills the owned cells and, `with_ghosts`, updates the ghosts (an exchange between ranks:
    /// skip it where only owned cells' gradients are read, e.g. the solid's boundary sweeps).
    void compute(const std::vector<double>& vertex_values, CellGradient<dim>& gradient,
                 bool with_ghosts = true) const;

  private:
    const FVGeometry<dim>& geometry;
    std::vector<unsigned int> start, vertex;
    std::vector<dealii::Tensor<1, dim>> coefficient;
    /// One term of Eq. 37's sum: face vertex `face_vertex` of face `face` adds to coefficient
    /// `entry`; cell c's terms are terms[term_start[c]..term_start[c+1]).
    struct Term
    {
      unsigned int face, face_vertex, entry;
    };
    std::vector<Term> terms;
    std::vector<unsigned int> term_start;
  };

  /**
   * Cell-based Gauss gradient with linearly interpolated face values ("Gauss linear", what
   * OpenFOAM's solidDisplacementFoam uses): (grad phi)_P = 1/V_P sum_f S_f phi_f. Exact for linear
   * fields only where face centres lie on the lines between cell centres. With `skew_corrected`
   * (OpenFOAM's "Gauss skewCorrected linear"), phi_f is moved from r_f' = w r_P + (1 - w) r_N on
   * the line P-N to the face centre with the plain gradient interpolated the same way: one more
   * face loop, and an O(h) error of skewed faces (e.g. where mesh blocks meet at a kink) becomes
   * O(h^2). Fills the owned cells and updates the ghosts.
   */
  template <int dim>
  void gauss_linear_gradient(const FVGeometry<dim>& geometry, const CellVector& phi,
                             const FaceVector& boundary_values, CellGradient<dim>& gradient,
                             bool skew_corrected = false);

  /// Face tangential gradient (Eq. 39): (grad_s phi)_f from the vertex values of face f.
  template <int dim>
  dealii::Tensor<1, dim> tangential_gradient(const FaceGeometry<dim>& face,
                                             const std::vector<double>& vertex_values)
  {
    dealii::Tensor<1, dim> g;
    for (unsigned int i = 0; i < face.vertices.size(); ++i)
      g += face.tangential_weight[i] * vertex_values[face.vertices[i]];
    return g;
  }

  /**
   * Weighted least-squares cell gradient from the face neighbours (and boundary-face values):
   * minimise sum_f w_f (phi_P + G . d_f - phi_f)^2 with w_f = 1/|d_f|^2. The dim x dim normal
   * matrices depend only on geometry and are inverted once in reinit().
   */
  template <int dim>
  class LeastSquaresGradient
  {
  public:
    explicit LeastSquaresGradient(const FVGeometry<dim>& geometry);
    void reinit();
    /// Fills the owned cells and updates the ghosts.
    void compute(const CellVector& phi, const FaceVector& boundary_values,
                 CellGradient<dim>& gradient) const;

  private:
    const FVGeometry<dim>& geometry;
    std::vector<dealii::Tensor<2, dim>> inverse_normal_matrix;
  };
} // namespace fvfsi
