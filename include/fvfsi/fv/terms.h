#pragma once
// The discrete terms the equations are written with (paper section 3). Each adds one face's share
// of one term to an equation: `fvm::` terms are implicit (coefficients of the unknown x in a
// FaceMatrix), `fvc::` terms explicit (known values into the right-hand side b of A x = b). A
// solver writes an equation as one face loop (face_loop.h) that calls the terms of the equation on
// each face, so that the loop reads as the equation, e.g. the fluid's momentum (Eq. 2, upwind
// convection, fluid_piso.templates.h):
//
//   for_each_face(geometry, [&](f, face) {
//     fvm::mesh_flux(momentum, face, F_mesh[f]);         //   u_P sum_f F^mesh_f
//     fvm::laplacian(momentum, f, face, nu);             // - sum_f nu S_f (n.grad u)_f  (Eq. 27)
//     fvm::upwind_convection(momentum, f, face, phi);    // + sum_f phi_f u_f
//   }, boundary_terms);
//
// The owner / neighbour rule (a face adds to N only where this rank owns N) lives in fv/ alone:
// face_loop.h for cell sums, FaceMatrix and Laplacian::assemble for matrix rows. The time derivative (BDF coefficients of the clock, TimeControl::bdf())
// and cell sources are per cell and are added by the solvers' cell loops.

#include <fvfsi/fv/face_loop.h>
#include <fvfsi/fv/face_matrix.h>

#include <algorithm>

namespace fvfsi
{
  namespace fvm
  {
    /// - Gamma_f S_f (n.grad x)_f, the implicit part of the face normal gradient: between two
    /// cells Eq. 19's orthogonal part a_f (x_P - x_N) (Eq. 27), at a boundary face with a given
    /// value x_b Eq. 23's a_f x_P (the caller adds a_f x_b to b). a_f = Gamma_f S_f / d_fn
    /// [Gamma m^(dim-2)], returned.
    template <int dim>
    inline double laplacian(FaceMatrix<dim>& A, const unsigned int f, const FaceGeometry<dim>& face,
                            const double gamma)
    {
      const double a = gamma * face.area / face.d_n;
      if (face.N == invalid_cell)
        A.diagonal[face.P] += a;
      else
        A.add_face_diffusion(f, a);
      return a;
    }

    /// phi_f x_f with the upwind value of x (x_P where the flux phi_f leaves P, x_N where it
    /// enters), phi_f [m^3/s] leaving P through a face between two cells.
    template <int dim>
    inline void upwind_convection(FaceMatrix<dim>& A, const unsigned int f,
                                  const FaceGeometry<dim>& face, const double phi)
    {
      (void)face;
      A.add_face_flux(f, std::max(phi, 0.0), std::min(phi, 0.0));
    }

    /// x_P F^mesh_f: the mesh flux leaving P times the cell's own value, on the diagonal (with
    /// the space conservation law the ALE time derivative and this term together are those of
    /// the fixed mesh, fluid_solver.h).
    template <int dim>
    inline void mesh_flux(FaceMatrix<dim>& A, const FaceGeometry<dim>& face, const double F_mesh)
    {
      add_outflow(face, F_mesh, A.diagonal);
    }
  } // namespace fvm

  namespace fvc
  {
    /// An explicit face quantity q_f leaving P (a deferred correction, a known flux) moved to the
    /// right-hand side: b_P -= q_f, b_N += q_f.
    template <int dim, typename Cells>
    inline void outflow(const FaceGeometry<dim>& face, const double q, Cells& b)
    {
      add_outflow(face, -q, b);
    }
  } // namespace fvc
} // namespace fvfsi
