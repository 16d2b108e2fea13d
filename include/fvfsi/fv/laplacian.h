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
// with g and H of a quadratic reconstruction (QuadraticReconstruction: g second-order accurate,
// which the k-terms need on such faces, and H) and H_f = w H_P + (1 - w) H_N. At a Dirichlet face,
// n_f . (grad phi)_f = (phi_b - phi(P')) / d_fn + 1/2 n.H_P.n d_fn (d_fn = d_Pn). The implicit part
// (phi_N - phi_P) / d_fn is the same for both; the rest is the explicit deferred correction.
// FaceGradient::linear (the default, and what the solid, fluid and mesh-motion solvers use) is
// Eq. 19 as above.

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/cell_gradient.h>
#include <fvfsi/fv/quadratic_reconstruction.h>
#include <fvfsi/mesh/fv_geometry.h>

#include <string>

namespace fvfsi
{
  /// The face normal gradient of the Laplacian (see above).
  enum class FaceGradient
  {
    linear,   ///< Eq. 19 with cell gradients: exact for linear fields
    quadratic ///< Eq. 19 with second-order g and the Hessian terms: exact for quadratic fields
  };

  /// "linear" or "quadratic" (the names of the Poisson parameter `Face gradient`).
  FaceGradient face_gradient_from_string(const std::string& name);

  template <int dim>
  class Laplacian
  {
  public:
    /// With FaceGradient::linear, call the members without a Hessian argument; with
    /// FaceGradient::quadratic, those with one (a mismatch throws std::logic_error).
    explicit Laplacian(const FVGeometry<dim>& geometry,
                       FaceGradient face_gradient = FaceGradient::linear);

    FaceGradient face_gradient() const { return kind; }

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

    /// FaceGradient::quadratic: the members above with the Hessian terms, for g and H of a
    /// QuadraticReconstruction (ghosts up to date). On Neumann faces
    /// phi_b = phi(P') + d_fn g - 1/2 d_fn^2 n.H_P.n.
    void add_correction(const FaceVector& gamma, const ScalarBoundaryConditions<dim>& bc,
                        const CellGradient<dim>& grad, const CellHessian<dim>& hessian,
                        CellVector& rhs) const;
    double normal_gradient(unsigned int f, const CellVector& phi, const CellGradient<dim>& grad,
                           const CellHessian<dim>& hessian,
                           const ScalarBoundaryConditions<dim>& bc) const;
    FaceVector boundary_values(const CellVector& phi, const CellGradient<dim>& grad,
                               const CellHessian<dim>& hessian,
                               const ScalarBoundaryConditions<dim>& bc) const;

  private:
    void require(FaceGradient needed, const char* member) const;
    /// d_fn times the explicit part of the quadratic n_f . (grad phi)_f: on an interior face
    /// phi(N') - phi(P') - (phi_N - phi_P) - 1/2 d_fn (d_Nn - d_Pn) n.H_f.n, on a boundary face
    /// (Dirichlet form) -(phi(P') - phi_P) + 1/2 d_fn^2 n.H_P.n.
    double quadratic_correction(const FaceGeometry<dim>& face, const CellGradient<dim>& grad,
                                const CellHessian<dim>& hessian) const;

    const FVGeometry<dim>& geometry;
    FaceGradient kind;
  };
} // namespace fvfsi
