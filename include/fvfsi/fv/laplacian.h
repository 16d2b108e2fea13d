#pragma once
// The finite-volume Laplacian  -div(Gamma grad phi)  with the face normal gradient of Eq. 19:
//
//   n_f . (grad phi)_f = (phi_N - phi_P) / d_fn  -  (k_N . (grad phi)_N + k_P . (grad phi)_P) / d_fn,
//
// which is exact for linear fields (with k_P, k_N of Eqs 21-22 the correction reads
// phi(N') - phi(P') along the normal line through r_f; the paper prints the correction with the
// opposite sign convention for k_N). The first term is implicit (the sparse matrix, symmetric and
// weakly diagonally dominant), the correction is explicit, with the gradients of the previous
// deferred-correction iteration. Dirichlet faces use Eq. 23, Neumann faces add the given flux.
// The solid momentum equation, the fluid's pressure and viscous terms and the mesh-motion equation
// all use this operator (the paper's remark in section 3.2).

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/cell_gradient.h>
#include <fvfsi/mesh/fv_geometry.h>

namespace fvfsi
{
  template <int dim>
  class Laplacian
  {
  public:
    explicit Laplacian(const FVGeometry<dim>& geometry);

    /// A matrix with the cell + face-neighbour sparsity of this mesh.
    void reinit_matrix(dealii::TrilinosWrappers::SparseMatrix& matrix) const;

    /// Add the implicit part of -div(Gamma grad phi) to `matrix` and its boundary sources to
    /// `rhs` (owned rows). `gamma` is Gamma_f per face. The matrix is not compressed.
    void assemble(const FaceVector& gamma, const ScalarBoundaryConditions<dim>& bc,
                  dealii::TrilinosWrappers::SparseMatrix& matrix, CellVector& rhs) const;

    /// Add the explicit non-orthogonal correction, computed with the cell gradients `grad`
    /// (ghosts up to date), to `rhs`.
    void add_correction(const FaceVector& gamma, const ScalarBoundaryConditions<dim>& bc,
                        const CellGradient<dim>& grad, CellVector& rhs) const;

    /// n_f . (grad phi)_f of face f (Eq. 19, or Eq. 23 / the given value at a boundary).
    double normal_gradient(unsigned int f, const CellVector& phi, const CellGradient<dim>& grad,
                           const ScalarBoundaryConditions<dim>& bc) const;

    /// phi_b on every boundary and ghost-boundary face: the given value on Dirichlet faces,
    /// phi_P + d_fn g + k_P . (grad phi)_P on Neumann faces (g the given normal gradient).
    FaceVector boundary_values(const CellVector& phi, const CellGradient<dim>& grad,
                               const ScalarBoundaryConditions<dim>& bc) const;

  private:
    const FVGeometry<dim>& geometry;
  };
} // namespace fvfsi
