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
// face_loop.h for cell sums, FaceMatrix and Laplacian::assemble for matrix rows. The time
// derivative (fvm::ddt, with the clock's BDF coefficients, TimeControl::bdf()) and cell sources
// are per cell and are added by the solvers' cell loops. Whole-field terms: Laplacian::assemble
// (fvm::laplacian over every face with its boundary conditions, Eq. 19's orthogonal part) and
// Laplacian::add_correction (its explicit non-orthogonal part) are what the solid, the mesh
// motion and the Poisson scene assemble their equations with.

#include <deal.II/base/point.h>

#include <fvfsi/base/time_control.h>
#include <fvfsi/fv/convection_scheme.h>
#include <fvfsi/fv/face_loop.h>
#include <fvfsi/fv/face_matrix.h>

#include <algorithm>
#include <vector>

namespace fvfsi
{
  namespace fvm
  {
    /// The coefficients of the time derivative d(V x)/dt at one cell by the BDF formula (Eq. 17)
    /// on a moving mesh: with the volumes the space conservation law gives (c0 V = c1 V^o -
    /// c2 V^oo, fluid_solver.h) it adds `diagonal` = c1 V^o - c2 V^oo [m^dim/s] to A_PP and
    /// `explicit_part(x^o, x^oo)` = c1 V^o x^o - c2 V^oo x^oo to b_P. On a fixed mesh
    /// (V^o = V^oo = V) this is c0 V x - (c1 x^o - c2 x^oo) V.
    struct Ddt
    {
      double diagonal, old_weight, older_weight;
      double explicit_part(const double x_o, const double x_oo) const
      {
        return old_weight * x_o - older_weight * x_oo;
      }
    };

    inline Ddt ddt(const BdfCoefficients& bdf, const double V_o, const double V_oo)
    {
      return {bdf.c1 * V_o - bdf.c2 * V_oo, bdf.c1 * V_o, bdf.c2 * V_oo};
    }

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
    /// The upwind side of a face for a flux phi leaving P: the cell U whose value
    /// fvm::upwind_convection takes, and r_f - r_U.
    template <int dim>
    struct UpwindSide
    {
      bool from_P;
      unsigned int U;
      dealii::Tensor<1, dim> to_face;
    };

    template <int dim>
    inline UpwindSide<dim> upwind_side(const FaceGeometry<dim>& face,
                                       const std::vector<dealii::Point<dim>>& centroid,
                                       const double phi)
    {
      const bool from_P = phi >= 0;
      const unsigned int U = from_P ? face.P : face.N;
      return {from_P, U, face.centre - centroid[U]};
    }

    /// x_f - x_U, the scheme's face value less the upwind one, for the deferred correction
    /// phi_f (x_f - x_U) that lifts fvm::upwind_convection to the scheme (on the right-hand
    /// side, fvc::outflow): linear upwind (r_f - r_U).grad x_U, central the interpolated value
    /// (FaceGeometry::interpolate) less x_U; 0 for upwind.
    template <int dim>
    inline double convection_correction(const ConvectionScheme scheme,
                                        const FaceGeometry<dim>& face, const UpwindSide<dim>& up,
                                        const double x_P, const double x_N,
                                        const dealii::Tensor<1, dim>& grad_U)
    {
      switch (scheme)
      {
        case ConvectionScheme::linear_upwind:
          return up.to_face * grad_U;
        case ConvectionScheme::central:
          return face.interpolate(x_P, x_N) - (up.from_P ? x_P : x_N);
        default:
          return 0;
      }
    }

    /// An explicit face quantity q_f leaving P (a deferred correction, a known flux) moved to the
    /// right-hand side: b_P -= q_f, b_N += q_f.
    template <int dim, typename Cells>
    inline void outflow(const FaceGeometry<dim>& face, const double q, Cells& b)
    {
      add_outflow(face, -q, b);
    }
  } // namespace fvc
} // namespace fvfsi
