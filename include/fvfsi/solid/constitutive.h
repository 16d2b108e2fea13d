#pragma once
// St. Venant-Kirchhoff and linear elasticity in the paper's notation (Eqs 4-9): the displacement
// gradient G = grad u has G_ij = d u_j / d x_i, F = I + G^T, E = (G + G^T + G.G^T)/2,
// Sigma = 2 mu E + lambda tr(E) I, and the force per reference area on a face with reference unit
// normal n is n . (Sigma . F^T)  (first Piola-Kirchhoff traction).

#include <deal.II/base/tensor.h>

namespace fvfsi
{
  struct LameParameters
  {
    double mu = 0; ///< shear modulus [Pa]
    double lambda =
      0; ///< first Lame parameter [Pa] (2D plane stress: the reduced 2 mu nu / (1 - nu))
    bool nonlinear = false; ///< St. Venant-Kirchhoff (true) or linear elastic
    /// The implicit diffusivity K = 2 mu + lambda of Eq. 8.
    double K() const { return 2 * mu + lambda; }
  };

  /// Second Piola-Kirchhoff stress Sigma (Eq. 6); linear: sigma = mu (G + G^T) + lambda tr(G) I.
  template <int dim>
  dealii::Tensor<2, dim> second_piola(const dealii::Tensor<2, dim>& G, const LameParameters& m)
  {
    dealii::Tensor<2, dim> E = 0.5 * (G + transpose(G));
    if (m.nonlinear)
      E += 0.5 * G * transpose(G);
    return 2 * m.mu * E + m.lambda * trace(E) * dealii::unit_symmetric_tensor<dim>();
  }

  /// Force per reference area n . (Sigma . F^T) on a face with reference normal n.
  template <int dim>
  dealii::Tensor<1, dim> first_piola_traction(const dealii::Tensor<2, dim>& G,
                                              const dealii::Tensor<1, dim>& n,
                                              const LameParameters& m)
  {
    const dealii::Tensor<2, dim> S = second_piola(G, m);
    if (!m.nonlinear)
      return n * S;
    return n * S + (n * S) * G; // n . Sigma . (I + G)
  }

  /// Cauchy stress sigma = F Sigma F^T / det F (Eq. 5); linear: the small-strain stress.
  template <int dim>
  dealii::Tensor<2, dim> cauchy_stress(const dealii::Tensor<2, dim>& G, const LameParameters& m)
  {
    const dealii::Tensor<2, dim> S = second_piola(G, m);
    if (!m.nonlinear)
      return S;
    const dealii::Tensor<2, dim> F = dealii::unit_symmetric_tensor<dim>() + transpose(G);
    return F * S * transpose(F) / determinant(F);
  }

  /// Deformed area vector per reference area: n' S'/S = det(F) F^-T n (Nanson's formula).
  template <int dim>
  dealii::Tensor<1, dim> deformed_area_vector(const dealii::Tensor<2, dim>& G,
                                              const dealii::Tensor<1, dim>& n,
                                              const LameParameters& m)
  {
    if (!m.nonlinear)
      return n;
    const dealii::Tensor<2, dim> F = dealii::unit_symmetric_tensor<dim>() + transpose(G);
    return determinant(F) * transpose(invert(F)) * n;
  }
} // namespace fvfsi
