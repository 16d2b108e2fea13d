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
//
// Eq. 19 is exact for linear fields only. For a quadratic field with Hessian H it errs (with exact
// gradients) by
//
//   1/2 n.H.n (d_Nn - d_Pn)  +  (k_P.H.k_P - k_N.H.k_N) / (2 d_fn),
//
// d_Pn = n_f . (r_f - r_P), d_Nn = n_f . (r_N - r_f): O(h^2) where neighbouring cells are alike,
// but O(h) wherever they are not (e.g. on the faces where two distorted cells of a coarse mesh
// meet, on every level of its uniform refinement). FaceGradient::quadratic removes that error: with
// P' = r_P + k_P and N' = r_N - k_N, the two points on the normal line through r_f,
//
//   phi(P') ~ phi_P + k_P . g_P + 1/2 k_P . H_P . k_P,
//   phi(N') ~ phi_N - k_N . g_N + 1/2 k_N . H_N . k_N,
//   n_f . (grad phi)_f = (phi(N') - phi(P')) / d_fn  -  1/2 n.H_f.n (d_Nn - d_Pn)  + O(h^2),
//
// with g and H of a quadratic reconstruction (QuadraticFit: g second-order accurate, which the
// k-terms need on such faces, and H) and H_f = w H_P + (1 - w) H_N. At a Dirichlet face,
// n_f . (grad phi)_f = (phi_b - phi(P')) / d_fn + 1/2 n.H_P.n d_fn (d_fn = d_Pn). The implicit part
// (phi_N - phi_P) / d_fn is the same for both; the rest is the explicit deferred correction.
// Every member that needs the explicit part takes an optional Hessian: without one it is Eq. 19
// (what the solid, fluid and mesh-motion solvers use), with one the quadratic form above (the
// Poisson scene's `Face gradient = quadratic`). One face loop serves both.

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/cell_fields.h>
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

    /// Add the explicit non-orthogonal correction, computed with the cell gradients `grad` (and
    /// Hessians, if given; ghosts up to date), to `rhs`.
    void add_correction(const FaceVector& gamma, const ScalarBoundaryConditions<dim>& bc,
                        const CellGradient<dim>& grad, CellVector& rhs,
                        const CellHessian<dim>* hessian = nullptr) const;

    /// n_f . (grad phi)_f of face f (Eq. 19 or its quadratic form, Eq. 23 / the given value at a
    /// boundary).
    double normal_gradient(unsigned int f, const CellVector& phi, const CellGradient<dim>& grad,
                           const ScalarBoundaryConditions<dim>& bc,
                           const CellHessian<dim>* hessian = nullptr) const;

    /// phi_b on every boundary and ghost-boundary face: the given value on Dirichlet faces; on
    /// Neumann faces (g the given normal gradient) the Dirichlet form of the face gradient solved
    /// for phi_b: phi_P + d_fn g + k_P . (grad phi)_P, with a Hessian phi(P') + d_fn g - 1/2 d_fn^2
    /// n.H_P.n.
    FaceVector boundary_values(const CellVector& phi, const CellGradient<dim>& grad,
                               const ScalarBoundaryConditions<dim>& bc,
                               const CellHessian<dim>* hessian = nullptr) const;

    /// phi_b of boundary face f alone, as boundary_values() gives it (no face vector allocated:
    /// for loops over a few faces).
    double boundary_value(unsigned int f, const CellVector& phi, const CellGradient<dim>& grad,
                          const ScalarBoundaryConditions<dim>& bc,
                          const CellHessian<dim>* hessian = nullptr) const;

  private:
    /// d_fn times the explicit part of n_f . (grad phi)_f. Eq. 19: -(k_P.(grad phi)_P +
    /// k_N.(grad phi)_N) (boundary: -k_P.(grad phi)_P). Quadratic: on an interior face
    /// phi(N') - phi(P') - (phi_N - phi_P) - 1/2 d_fn (d_Nn - d_Pn) n.H_f.n, on a boundary face
    /// (Dirichlet form) -(phi(P') - phi_P) + 1/2 d_fn^2 n.H_P.n.
    double explicit_part(const FaceGeometry<dim>& face, const CellGradient<dim>& grad,
                         const CellHessian<dim>* hessian) const;

    const FVGeometry<dim>& geometry;
  };
} // namespace fvfsi
