#pragma once
// The steps of one PISO time step of the FluidSolver (see fluid_solver.h for the equations):
// momentum assembly and predictor, the pressure equation from continuity with the consistent
// Rhie-Chow flux, and the flux and velocity corrections.

#include <deal.II/base/mpi.h>

#include <fvfsi/fluid/fluid_solver.h>
#include <fvfsi/fv/deferred_correction.h>
#include <fvfsi/fv/face_loop.h>
#include <fvfsi/fv/terms.h>

#include <algorithm>
#include <cmath>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  void FluidSolver<dim>::assemble_momentum()
  {
    TimerOutput::Scope scope(timer_output, "momentum assembly");
    momentum.zero();
    for (unsigned int j = 0; j < dim; ++j)
      B_rest[j] = 0;
    // Eq. 2 over V_P, face by face: phi_f = F_f - F^mesh_f is the flux relative to the moving
    // face. The mesh-flux term + u_P sum_f F^mesh_f and the time term's c0_P (see fluid_solver.h)
    // make the spatial rows sum to sum_f F_f (both zero on a fixed mesh).
    for_each_face(
      geometry,
      [this](const unsigned int f, const FaceGeometry<dim>& face) // between two cells
      {
        const double phi = F[f] - F_mesh[f];
        fvm::mesh_flux(momentum, face, F_mesh[f]);      // + u_P F^mesh_f
        fvm::laplacian(momentum, f, face, prm.nu);      // - nu S_f (n.grad u)_f, Eq. 27 implicit
        fvm::upwind_convection(momentum, f, face, phi); // + phi_f u_f, upwind part implicit
        add_convection_correction(f, phi);              // + phi_f (u_f - u_f^upwind), deferred
      },
      [this](const unsigned int f, const FaceGeometry<dim>& face) // boundary
      {
        fvm::mesh_flux(momentum, face, F_mesh[f]);
        add_boundary_face_momentum(f, F[f] - F_mesh[f]);
      });
    // Explicit non-orthogonal part of Eq. 19 for the viscous term.
    for (unsigned int j = 0; j < dim; ++j)
      operators.laplacian.add_correction(nu_f, velocity_bc, grad_u[j], B_rest[j]);
    add_time_and_body_force_terms();
  }

  template <int dim>
  void FluidSolver<dim>::add_boundary_face_momentum(const unsigned int f, const double phi)
  {
    const auto& face = geometry.faces[f];
    const unsigned int P = face.P;
    const Tensor<1, dim>& u_b = boundary_u[f];
    switch (conditions.type(f))
    {
      case Type::velocity_inlet:
      case Type::wall:
      {
        // u_b given: Eq. 23 for the viscous flux, the convected value is u_b.
        const double a_diffusion = fvm::laplacian(momentum, f, face, prm.nu);
        for (unsigned int j = 0; j < dim; ++j)
          B_rest[j].local_element(P) += (a_diffusion - phi) * u_b[j];
        break;
      }
      case Type::outlet:
        // Zero normal gradient: no viscous flux; outflow convects u_P (implicit) corrected to
        // u_b, backflow convects u_b (explicit).
        momentum.diagonal[P] += std::max(phi, 0.0);
        for (unsigned int j = 0; j < dim; ++j)
          B_rest[j].local_element(P) -=
            std::min(phi, 0.0) * u_b[j] + (prm.convection == FluidParameters::Convection::upwind
                                             ? 0.0
                                             : std::max(phi, 0.0) * (u_b[j] - u[P][j]));
        break;
      case Type::symmetry:
      {
        // No flux through the plane; the viscous force of the normal velocity, explicit.
        const double a_diffusion = prm.nu * face.area / face.d_n; // Eq. 27
        for (unsigned int j = 0; j < dim; ++j)
          B_rest[j].local_element(P) += a_diffusion * (u_b[j] - u[P][j]);
        break;
      }
    }
  }

  template <int dim>
  void FluidSolver<dim>::add_time_and_body_force_terms()
  {
    // Time derivative of V u (backward Euler / BDF2) and body force: c0_P = c1 V^o/V - c2 V^oo/V
    // (= c0 on a fixed mesh). Steady: a local pseudo time step, c0_P = a*_P (1 - alpha) / alpha
    // from the spatial coefficient a*_P assembled so far. Transient outer loops relaxed by
    // alpha < 1 add such a pseudo time step to the physical one, with the previous outer loop's
    // u as its old value (the final loop has alpha = 1: the converged step is unchanged).
    const BdfCoefficients bdf = time_coefficients();
    const double alpha = prm.transient ? outer_alpha : relaxation;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      const double V = geometry.cell_volume[c];
      const double pseudo = momentum.diagonal[c] / V * (1 - alpha) / alpha;
      fvm::Ddt ddt = fvm::ddt(bdf, V_levels.o[c], V_levels.oo[c]); // d(V u)/dt, Eq. 17
      c0_cell[c] = prm.transient ? ddt.diagonal / V + pseudo : pseudo;
      if (!prm.transient) // the pseudo time step alone, from the last iterate u^o
        ddt.old_weight = c0_cell[c] * V;
      momentum.diagonal[c] += c0_cell[c] * V;
      for (unsigned int j = 0; j < dim; ++j)
      {
        B_time[j][c] = ddt.explicit_part(u_levels.o.components[j].local_element(c),
                                         u_levels.oo.components[j].local_element(c));
        if (prm.transient && alpha < 1)
          B_time[j][c] += pseudo * V * u.components[j].local_element(c);
        B_rest[j].local_element(c) += V * body_force_value[j][c];
      }
    }
  }

  template <int dim>
  void FluidSolver<dim>::add_convection_correction(const unsigned int f, const double phi)
  {
    // Deferred correction phi (u_f - u_f^upwind) of the higher-order face value.
    if (prm.convection == FluidParameters::Convection::upwind)
      return;
    const auto& face = geometry.faces[f];
    const auto up = fvc::upwind_side(face, geometry.centroid, phi);
    for (unsigned int j = 0; j < dim; ++j)
      fvc::outflow(face,
                   phi * fvc::convection_correction(prm.convection, face, up, u[face.P][j],
                                                    u[face.N][j], grad_u[j][up.U]),
                   B_rest[j]);
  }

  template <int dim>
  void FluidSolver<dim>::solve_momentum()
  {
    TimerOutput::Scope scope(timer_output, "momentum solve");
    // A u_j = B_j - V (grad p)_j, all components with one matrix.
    momentum.copy_to(momentum_matrix);
    if (refresh_preconditioners() || !momentum_solver.initialized())
      momentum_solver.initialize(momentum_matrix);
    CellVector rhs = geometry.make_cell_vector();
    for (unsigned int j = 0; j < dim; ++j)
    {
      for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
        rhs.local_element(c) =
          B_rest[j].local_element(c) + B_time[j][c] - geometry.cell_volume[c] * grad_p[c][j];
      momentum_solver.solve(momentum_matrix, u.components[j], rhs,
                            "fluid momentum, component " + std::to_string(j));
    }
  }

  template <int dim>
  void FluidSolver<dim>::assemble_pressure_matrix()
  {
    TimerOutput::Scope scope(timer_output, "pressure matrix + preconditioner");
    // a_P = A_P / V_P = c0 + a*_P; a*_f = 1 / (1/a*)_f; Gamma_f = 1 / (c0 + a*_f), the same
    // Gamma_f as in the flux correction, so that the corrected fluxes satisfy continuity.
    const auto [c0, c1, c2] = time_coefficients();
    (void)c0;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      a.local_element(c) = momentum.diagonal[c] / geometry.cell_volume[c];
      a_star.local_element(c) = a.local_element(c) - c0_cell[c];
    }
    a.update_ghost_values();
    a_star.update_ghost_values();
    compute_consistent_coefficients();
    pressure_equation.zero();
    for_each_face(geometry,
                  [this, c1 = c1, c2 = c2](const unsigned int f, const FaceGeometry<dim>& face)
                  { add_pressure_face(f, face, c1, c2); });
    // No outlet: fix the level by doubling the diagonal of global cell 0 (exact for the
    // compatible singular system: its solution with p = 0 there solves the modified one).
    if (!pressure_level_fixed && geometry.n_owned_cells() > 0 && geometry.global_index(0) == 0)
      pressure_equation.diagonal[0] *= 2;
    pressure_equation.copy_to(pressure_matrix);
    if (refresh_preconditioners() || !pressure_solver.initialized())
      pressure_solver.initialize(pressure_matrix);
  }

  template <int dim>
  void FluidSolver<dim>::add_pressure_face(const unsigned int f, const FaceGeometry<dim>& face,
                                           const double c1, const double c2)
  {
    // The face's Gamma_f and its share of -div(Gamma grad p) (Eq. 19 implicit, Eq. 23 at an
    // outlet); on inlets and walls the flux is given (Gamma_f = 0).
    if (face.N == invalid_cell && conditions.type(f) != Type::outlet)
    {
      gamma_p[f] = gamma_c[f] = 0;
      return;
    }
    const auto reciprocal = [&face](const CellVector& x)
    {
      return face.N == invalid_cell
               ? 1 / x.local_element(face.P)
               : face.interpolate_reciprocal(x.local_element(face.P), x.local_element(face.N));
    };
    a_star_f[f] = 1 / reciprocal(a_star);
    const auto r = volume_ratios(f);
    const double alpha = prm.transient ? outer_alpha : relaxation;
    const double pseudo = a_star_f[f] * (1 - alpha) / alpha; // as c0_P's, on the face
    c0_face[f] = prm.transient ? c1 * r[0] - c2 * r[1] + pseudo : pseudo;
    gamma_p[f] = 1 / (c0_face[f] + a_star_f[f]);
    gamma_c[f] = gamma_p[f];
    if (simplec()) // 1 / (a - H1)_f, interpolated as a*_f
      gamma_c[f] = reciprocal(a_tilde);
    fvm::laplacian(pressure_equation, f, face, gamma_c[f]);
  }

  template <int dim>
  void FluidSolver<dim>::compute_consistent_coefficients()
  {
    // a~_P = a_P - H1_P, H1_P = -sum_N a_PN / V_P: with upwind convection a*_P V_P - H1_P V_P is
    // the net outflow plus the boundary faces' diffusion, so a~_P = c0_P + (those): about the
    // pseudo time term alone. Kept >= c0_P where the net outflow is negative (iterates that do
    // not conserve mass yet).
    if (!simplec())
      return;
    std::vector<double> off_sum;
    momentum.off_diagonal_sum(off_sum);
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
      a_tilde.local_element(c) =
        std::max(a.local_element(c) + off_sum[c] / geometry.cell_volume[c], c0_cell[c]);
    a_tilde.update_ghost_values();
  }

  template <int dim>
  void FluidSolver<dim>::compute_flux_parts()
  {
    // The parts of F*_f that the correctors of one outer loop share (they read only the old
    // levels, the mesh, the loop's coefficients and its velocity gradients): the old fluxes
    // c1 r1_f F^o - c2 r2_f F^oo, and the skewness correction m . (grad u)_f of (h / a*)_f.
    const auto [c0, c1, c2] = time_coefficients();
    (void)c0;
    for (const unsigned int f : evaluated_faces(geometry)) // as for_each_face, see face_loop.h
    {
      const auto& face = geometry.faces[f];
      if (face.N == invalid_cell && conditions.type(f) != Type::outlet)
        continue;
      // m from the interpolation point to the face centre; the old velocities at the face.
      const unsigned int P = face.P, N = face.N;
      Tensor<1, dim> m, u_o, u_oo;
      std::array<Tensor<1, dim>, dim> grad;
      if (N == invalid_cell)
      {
        m = face.centre - geometry.centroid[P];
        for (unsigned int j = 0; j < dim; ++j)
          grad[j] = grad_u[j][P];
        u_o = u_levels.o[P];
        u_oo = u_levels.oo[P];
      }
      else
      {
        m = face.centre - face.interpolate(geometry.centroid[P], geometry.centroid[N]);
        for (unsigned int j = 0; j < dim; ++j)
          grad[j] = face.interpolate(grad_u[j][P], grad_u[j][N]);
        u_o = face.interpolate(u_levels.o[P], u_levels.o[N]);
        u_oo = face.interpolate(u_levels.oo[P], u_levels.oo[N]);
      }
      for (unsigned int j = 0; j < dim; ++j)
        h_skewness[f][j] = m * grad[j];
      // Old fluxes carried to the new face: F^o + u^o_f . (S_f - S_f^o) (exactly F^o on a fixed
      // mesh), weighted by the volume ratios r1_f, r2_f.
      const double F_o = F_levels.o[f] + u_o * (face.S - S_levels.o[f]);
      const double F_oo = F_levels.oo[f] + u_oo * (face.S - S_levels.oo[f]);
      const auto r = volume_ratios(f);
      // Steady: the old flux is the last pseudo step's.
      const double c1_f = prm.transient ? c1 * r[0] : c0_face[f];
      F_old_part[f] = c1_f * F_o - c2 * r[1] * F_oo;
    }
  }

  template <int dim>
  void FluidSolver<dim>::compute_predicted_fluxes(const bool new_outer_loop)
  {
    TimerOutput::Scope scope(timer_output, "predicted fluxes");
    if (new_outer_loop)
      compute_flux_parts();
    // h_P = (B^rest_P - sum_N A_PN u_N) / V_P with the latest u.
    std::vector<double> off_diagonal;
    for (unsigned int j = 0; j < dim; ++j)
    {
      momentum.off_diagonal_product(u.components[j], off_diagonal);
      for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
        h.components[j].local_element(c) =
          (B_rest[j].local_element(c) - off_diagonal[c]) / geometry.cell_volume[c];
    }
    h.update_ghost_values();
    // F*_f = (c1 F_f^o - c2 F_f^oo + a*_f S_f . (h / a*)_f) / (c0 + a*_f); on inlets and walls
    // the flux is given.
    const auto [c0, c1, c2] = time_coefficients();
    (void)c0;
    for (const unsigned int f : evaluated_faces(geometry)) // as for_each_face, see face_loop.h
    {
      const auto& face = geometry.faces[f];
      if (face.N == invalid_cell && conditions.type(f) != Type::outlet)
      {
        F_star[f] = conditions.type(f) == Type::velocity_inlet ? face.S * boundary_u[f] : F_mesh[f];
        continue;
      }
      // (h / a*)_f with the skewness correction of compute_flux_parts().
      const unsigned int P = face.P, N = face.N;
      Tensor<1, dim> h_by_a = N == invalid_cell ? h[P] / a_star.local_element(P)
                                                : face.w * h[P] / a_star.local_element(P) +
                                                    (1 - face.w) * h[N] / a_star.local_element(N);
      for (unsigned int j = 0; j < dim; ++j)
        h_by_a[j] += h_skewness[f][j];
      F_star[f] = gamma_p[f] * (F_old_part[f] + a_star_f[f] * (face.S * h_by_a));
      // Transient outer loops relaxed by alpha < 1: also the pseudo time term's, the outer
      // loop's first flux F_outer_start.
      if (prm.transient && outer_alpha < 1)
      {
        const auto r = volume_ratios(f);
        F_star[f] += gamma_p[f] * (c0_face[f] - c1 * r[0] + c2 * r[1]) * F_outer_start[f];
      }
      // SIMPLEC: + (Gamma~_f - Gamma_f) S_f (n.grad p)_f with the pressure of the last corrector,
      // so that F = F* - Gamma~_f S_f (n.grad p)_f is SIMPLE's flux once p stops changing.
      if (gamma_c[f] != gamma_p[f])
        F_star[f] += (gamma_c[f] - gamma_p[f]) * face.area *
                     operators.laplacian.normal_gradient(f, p, grad_p, pressure_bc);
    }
  }

  template <int dim>
  void FluidSolver<dim>::solve_pressure(const bool last)
  {
    TimerOutput::Scope scope(timer_output, "pressure solve");
    // Continuity sum_f F_f = 0 with F_f = F*_f - Gamma_f S_f (n.grad p)_f: the Laplacian of p
    // with Gamma = 1/a_f, the divergence of F* as source, Eq. 19's correction explicit and
    // updated by the non-orthogonal correctors.
    pressure_rhs = 0;
    for_each_face(geometry,
                  [this](const unsigned int f, const FaceGeometry<dim>& face)
                  {
                    fvc::outflow(face, F_star[f], pressure_rhs);                      // - div F*
                    if (face.N == invalid_cell && conditions.type(f) == Type::outlet) // Eq. 23
                      pressure_rhs.local_element(face.P) +=
                        gamma_c[f] * face.area / face.d_n * boundary_p[f];
                  });
    // The flux correction below must use the gradient of the last solve's correction, so the
    // gradient is only updated between solves.
    DeferredCorrection control;
    control.max_iterations = prm.non_orthogonal_correctors + 1;
    control.update_after_last = false;
    // Only the last solve of the time step needs the full reduction: its residual is the
    // continuity error left in F; the earlier ones (started from the previous pressure) are
    // corrected by the solves after them.
    if (prm.pressure_corrector_reduction > 0)
    {
      control.reduction = prm.pressure_corrector_reduction;
      control.last_reduction = last ? -1 : prm.pressure_corrector_reduction;
    }
    solve_deferred_correction(
      control, pressure_solver, pressure_matrix, pressure_rhs, p,
      [this](CellVector& rhs)
      { operators.laplacian.add_correction(gamma_c, pressure_bc, grad_p, rhs); },
      [this]()
      {
        update_pressure_boundary_values();
        update_pressure_gradient();
      },
      "fluid pressure");
  }

  template <int dim>
  void FluidSolver<dim>::correct_fluxes()
  {
    TimerOutput::Scope scope(timer_output, "flux and velocity correction");
    // F_f = F*_f - Gamma_f S_f (n.grad p)_f.
    for_each_face(geometry,
                  [this](const unsigned int f, const FaceGeometry<dim>& face)
                  {
                    F[f] = gamma_c[f] == 0
                             ? F_star[f]
                             : F_star[f] -
                                 gamma_c[f] * face.area *
                                   operators.laplacian.normal_gradient(f, p, grad_p, pressure_bc);
                  });
  }

  template <int dim>
  void FluidSolver<dim>::correct_velocity()
  {
    TimerOutput::Scope scope(timer_output, "flux and velocity correction");
    // u_P = (h_P + B^time_P / V_P - (grad p)_P) / a_P, with h from the latest u. SIMPLEC, as
    // the fluxes: the change of grad p in this corrector divided by a~_P instead.
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      const double V = geometry.cell_volume[c];
      const Tensor<1, dim> gp = simplec() ? grad_p_before[c] : grad_p[c];
      for (unsigned int j = 0; j < dim; ++j)
        u.components[j].local_element(c) =
          (h.components[j].local_element(c) + B_time[j][c] / V - gp[j]) / a.local_element(c);
      if (simplec())
        for (unsigned int j = 0; j < dim; ++j)
          u.components[j].local_element(c) -=
            (grad_p[c][j] - grad_p_before[c][j]) / a_tilde.local_element(c);
    }
    u.update_ghost_values();
  }

  // The members above are defined in this file; instantiate them here.
} // namespace fvfsi
