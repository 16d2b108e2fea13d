#pragma once
// The SolidSolver's face forces: the face gradient of each variant, the boundary values of
// Eqs 23-24, the tractions of the boundary conditions and the residual of Eq. 16 (see
// solid_solver.h).
#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <fvfsi/fv/face_loop.h>
#include <fvfsi/fv/ghost_faces.h>
#include <fvfsi/solid/solid_solver.h>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  Tensor<2, dim> SolidSolver<dim>::face_gradient(const unsigned int f) const
  {
    const auto& face = geometry.faces[f];
    const bool boundary = face.N == invalid_cell;
    if (boundary && takes_traction(conditions.type(f)))
      return boundary_G[f]; // Eq. 24
    const Tensor<2, dim> G_P = cell_gradient(face.P);
    const Tensor<1, dim> u_P = u[face.P];
    // Normal derivative vector g_n = n . grad u: Eq. 19 inside, Eq. 23 on displacement faces.
    Tensor<1, dim> g_n;
    if (boundary)
      g_n = (boundary_u[f] - u_P - face.k_P * G_P) / face.d_n;
    else
    {
      const Tensor<2, dim> G_N = cell_gradient(face.N);
      g_n = (u[face.N] - u_P - face.k_N * G_N - face.k_P * G_P) / face.d_n;
    }
    if (parameters.variant == Variant::present)
    {
      // Tangential part from the vertex values (Eq. 39), also on boundary faces.
      Tensor<2, dim> G = outer_product(face.n, g_n);
      for (unsigned int j = 0; j < dim; ++j)
      {
        const Tensor<1, dim> t = tangential_gradient(face, vertex_u[j]);
        for (unsigned int i = 0; i < dim; ++i)
          G[i][j] += t[i];
      }
      return G;
    }
    // Demirdzic-Muzaferija and Jasak-Weller: the interpolated cell gradient (the cell's own at a
    // boundary), with its normal part replaced by g_n.
    const Tensor<2, dim> G_bar = boundary ? G_P : face.interpolate(G_P, cell_gradient(face.N));
    return G_bar + outer_product(face.n, g_n - face.n * G_bar);
  }

  template <int dim>
  Tensor<1, dim> SolidSolver<dim>::boundary_traction(const unsigned int f,
                                                     const Tensor<2, dim>& G) const
  {
    // The force per reference area of a Cauchy traction t: t S'/S (Eq. 24), S'/S from Nanson.
    const auto& face = geometry.faces[f];
    const Type type = conditions.type(f);
    const Tensor<1, dim> area_ratio_n = deformed_area_vector(G, face.n, lame);
    if (type == Type::external_traction)
      return load_factor * area_ratio_n.norm() * external_traction[f];
    if (type == Type::pressure)
      return -load_factor * given_traction[f][0] * area_ratio_n;
    return load_factor * area_ratio_n.norm() * given_traction[f];
  }

  template <int dim>
  void SolidSolver<dim>::evaluate_given_tractions()
  {
    given_traction.resize(geometry.faces.size());
    for (const unsigned int f : geometry.boundary_faces())
    {
      const Type type = conditions.type(f);
      if (type == Type::pressure)
        given_traction[f][0] = conditions.value(f, geometry.faces[f].centre);
      else if (type == Type::traction)
        for (unsigned int d = 0; d < dim; ++d)
          given_traction[f][d] = conditions.value(f, geometry.faces[f].centre, d);
    }
  }

  template <int dim>
  Tensor<2, dim> SolidSolver<dim>::tangential_part(const unsigned int f) const
  {
    // The tangential part of grad u at boundary face f: from the vertex values (Eq. 39, present
    // variant), or of the cell gradient.
    const auto& face = geometry.faces[f];
    Tensor<2, dim> T;
    if (parameters.variant == Variant::present)
      for (unsigned int j = 0; j < dim; ++j)
      {
        const Tensor<1, dim> t = tangential_gradient(face, vertex_u[j]);
        for (unsigned int i = 0; i < dim; ++i)
          T[i][j] = t[i];
      }
    else
    {
      const Tensor<2, dim> G_P = cell_gradient(face.P);
      T = G_P - outer_product(face.n, face.n * G_P);
    }
    return T;
  }

  template <int dim>
  void SolidSolver<dim>::update_boundary_values()
  {
    for (const unsigned int f : geometry.boundary_faces())
    {
      const auto& face = geometry.faces[f];
      const Type type = conditions.type(f);
      const Tensor<2, dim> G_P = cell_gradient(face.P);
      const Tensor<1, dim> extrapolated = u[face.P] + face.k_P * G_P;
      switch (type)
      {
        case Type::fixed_displacement:
        {
          for (unsigned int d = 0; d < dim; ++d)
            boundary_u[f][d] = load_factor * conditions.value(f, face.centre, d);
          break;
        }
        case Type::symmetry:
        {
          Tensor<1, dim> e = extrapolated;
          if (cell_hessian)
            e += boundary_quadratic_term[f];
          boundary_u[f] = e - (e * face.n) * face.n;
          break;
        }
        default:
        {
          // Eq. 24: K g_n = t S'/S - n . q, with n . q = n.(Sigma.F^T) - K n . grad u at the
          // previous iterate; then u_b from Eq. 23.
          const Tensor<2, dim>& G_old = boundary_G[f];
          const Tensor<1, dim> n_q =
            first_piola_traction(G_old, face.n, lame) - lame.K() * (face.n * G_old);
          const Tensor<1, dim> g_n = (boundary_traction(f, G_old) - n_q) / lame.K();
          boundary_G[f] = outer_product(face.n, g_n) + tangential_part(f);
          boundary_u[f] = extrapolated + face.d_n * g_n;
          if (cell_hessian)
            boundary_u[f] += boundary_quadratic_term[f];
        }
      }
    }
    update_ghost_boundary_faces(geometry, boundary_u);
  }

  template <int dim>
  Tensor<1, dim> SolidSolver<dim>::face_force_density(const unsigned int f) const
  {
    const auto& face = geometry.faces[f];
    if (face.N != invalid_cell)
    {
      if (parameters.variant != Variant::jasak_weller)
        return first_piola_traction(face_gradient(f), face.n, lame);
      // Jasak-Weller: K n.grad u_f (Eq. 19 with interpolated gradients) + n.q of the
      // interpolated cell gradient, as solidDisplacementFoam's laplacian + div(sigmaExp).
      const Tensor<2, dim> G_f = face_gradient(f);
      const Tensor<2, dim> G_bar = face.interpolate(cell_gradient(face.P), cell_gradient(face.N));
      return lame.K() * (face.n * G_f) + first_piola_traction(G_bar, face.n, lame) -
             lame.K() * (face.n * G_bar);
    }
    const auto type = conditions.type(f);
    if (takes_traction(type))
      return boundary_traction(f, boundary_G[f]);
    const Tensor<1, dim> t = first_piola_traction(face_gradient(f), face.n, lame);
    return type == Type::symmetry ? (t * face.n) * face.n : t;
  }

  template <int dim>
  double SolidSolver<dim>::smallest_stretch() const
  {
    // The smallest principal stretch, sqrt of the least eigenvalue of C = F^T F with F = I + G^T
    // (G_ij = d u_j / d x_i; F and G^T share their singular values), over the face gradients
    // the forces use.
    double least = std::numeric_limits<double>::max();
    for_each_face(geometry,
                  [&](const unsigned int f, const FaceGeometry<dim>&)
                  {
                    const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + face_gradient(f);
                    least = std::min(least, eigenvalues(symmetrize(transpose(F) * F))[dim - 1]);
                  });
    return std::sqrt(Utilities::MPI::min(least, geometry.comm()));
  }

  template <int dim>
  void SolidSolver<dim>::compute_residual(std::array<CellVector, dim>& residual) const
  {
    // R_P = sum_f S_f n.(Sigma.F^T)_f + rho V (b - a(u)), the residual of Eq. 16.
    for (auto& r : residual)
      r = 0;
    for_each_face(geometry, [&](const unsigned int f, const FaceGeometry<dim>& face)
                  { add_outflow(face, face.area * face_force_density(f), residual); });
    // The inertia rho V a with a = c0 v - c1 v^o + c2 v^oo and v = c0 u - c1 u^o + c2 u^oo
    // (Eqs 17-18; backward Euler on the first step).
    const BdfCoefficients bdf = clock.bdf();
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      Tensor<1, dim> acceleration;
      if (parameters.transient)
        acceleration = v_levels.derivative(bdf, u_levels.derivative(bdf, u[c], c), c);
      const double rho_V = parameters.rho * geometry.cell_volume[c];
      for (unsigned int j = 0; j < dim; ++j)
        residual[j].local_element(c) +=
          rho_V * (load_factor * body_force_value[j][c] - acceleration[j]);
    }
  }

  template <int dim>
  Tensor<1, dim> SolidSolver<dim>::patch_force(const unsigned int patch) const
  {
    return patch_sum(geometry, patch,
                     [this](const unsigned int f, const FaceGeometry<dim>& face)
                     { return face.area * face_force_density(f); });
  }

} // namespace fvfsi
