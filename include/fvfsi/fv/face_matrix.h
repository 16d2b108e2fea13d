#pragma once
// A finite-volume matrix stored by faces, as OpenFOAM's lduMatrix: one diagonal coefficient per
// owned cell and, per face f between P and N, the coefficient of N in row P (`upper`) and of P in
// row N (`lower`). Face loops assemble into it without touching a sparse-matrix library (one
// Trilinos add per entry is slow); copy_to() then writes whole rows at once. It also gives the
// off-diagonal product sum_N a_PN x_N that the pressure-velocity coupling needs (the H operator).
//
// A processor face (P owned, N a ghost) fills only row P: the rank that owns N has the same face
// with the roles swapped and fills its own row.

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/mesh/fv_geometry.h>

#include <vector>

namespace fvfsi
{
  template <int dim>
  class FaceMatrix
  {
  public:
    explicit FaceMatrix(const FVGeometry<dim>& geometry);

    /// Size the coefficient arrays for the current mesh and set them to zero.
    void reinit();
    /// Set every coefficient to zero.
    void zero();

    /// Add a symmetric face coupling a (a > 0): a (x_P - x_N) in row P, a (x_N - x_P) in row N,
    /// the orthogonal part of a diffusion term with a = Gamma_f S_f / d_fn (Eqs 19, 27).
    void add_face_diffusion(unsigned int f, double a) { add_face_flux(f, a, -a); }
    /// Add an implicit face flux q_f = a_P x_P + a_N x_N leaving P (a face between two cells):
    /// +q_f in row P, -q_f in row N (convection, fv/terms.h).
    void add_face_flux(unsigned int f, double a_P, double a_N)
    {
      const auto& face = geometry.faces[f];
      diagonal[face.P] += a_P;
      upper[f] += a_N;
      if (face.kind == FaceKind::interior)
      {
        diagonal[face.N] -= a_N;
        lower[f] -= a_P;
      }
    }

    /// Write the coefficients into `matrix` (sparsity from Laplacian::reinit_matrix): the first
    /// time row by row, later straight into its rows (the layout is kept; reinit() forgets it).
    void copy_to(dealii::TrilinosWrappers::SparseMatrix& matrix) const;

    /// y_P = sum_N a_PN x_N for every owned cell P (x with up-to-date ghosts).
    void off_diagonal_product(const CellVector& x, std::vector<double>& y) const;
    /// y_P = sum_N a_PN for every owned cell P (the row sums of the off-diagonal part).
    void off_diagonal_sum(std::vector<double>& y) const;

    std::vector<double> diagonal; ///< a_P, per owned cell
    std::vector<double> upper;    ///< per face: a_PN (interior and processor faces)
    std::vector<double> lower;    ///< per face: a_NP (interior faces)

  private:
    /// copy_to() through matrix.set(), row by row; records the layout.
    void set_rows(dealii::TrilinosWrappers::SparseMatrix& matrix) const;

    const FVGeometry<dim>& geometry;
    /// Per stored entry of the owned rows of `layout_of`, in its order: -1 the diagonal, 2 f
    /// upper[f], 2 f + 1 lower[f].
    mutable std::vector<int> entry_source;
    mutable const dealii::TrilinosWrappers::SparseMatrix* layout_of = nullptr;
  };
} // namespace fvfsi
