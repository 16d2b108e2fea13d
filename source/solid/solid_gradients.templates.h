#pragma once
// The SolidSolver's gradients: the sweeps of boundary values, vertex values and cell gradients of
// an outer iteration, the vertex constraints, and the Hessian correction (see solid_solver.h).
#include <deal.II/base/mpi.h>

#include <fvfsi/fv/ghost_faces.h>
#include <fvfsi/solid/solid_solver.h>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  void SolidSolver<dim>::update_gradients()
  {
    // Boundary values (Eqs 23-24), vertex values and gradients depend on each other; a few sweeps
    // make them (nearly) a function of u alone, so that the outer iteration is a fixed-point map
    // of u that Anderson acceleration can model.
    if (cell_hessian)
      update_hessians();
    // A sweep reads the gradients of owned cells only (the extrapolation to their boundary
    // faces): the neighbours' copies (ghosts) are exchanged after the last sweep alone, which
    // takes dim^2 exchanges (one per component of each grad u_j) out of every other sweep.
    for (unsigned int sweep = 0; sweep < parameters.boundary_sweeps; ++sweep)
    {
      update_boundary_values();
      update_cell_gradients(/*with_ghosts=*/sweep + 1 == parameters.boundary_sweeps);
    }
  }

  template <int dim>
  void SolidSolver<dim>::update_cell_gradients(const bool with_ghosts)
  {
    // From u and the boundary values u_b (and the Hessians' terms): the vertex values (present
    // variant) and the cell gradients; their ghosts too unless `with_ghosts` is false (present
    // variant only).
    FaceVector boundary_values(geometry.faces.size()); // only boundary entries are read
    for (unsigned int j = 0; j < dim; ++j)
    {
      for (const unsigned int f : geometry.all_boundary_faces())
        boundary_values[f] = boundary_u[f][j];
      const CellVector& u_j = u.components[j];
      if (parameters.variant == Variant::present)
      {
        vertex_interpolation.interpolate(u_j, boundary_values, vertex_u[j]);
        if (cell_hessian)
          for (const unsigned int v : vertex_interpolation.vertices())
            vertex_u[j][v] += vertex_quadratic_term[j][v];
      }
      else if (parameters.variant == Variant::demirdzic_muzaferija)
        least_squares.compute(u_j, boundary_values, grad_u[j]);
      else
        gauss_linear_gradient(geometry, u_j, boundary_values, grad_u[j], /*skew_corrected=*/true);
    }
    if (parameters.variant == Variant::present)
    {
      impose_vertex_constraints();
      for (unsigned int j = 0; j < dim; ++j)
        gauss_green.compute(vertex_u[j], grad_u[j], with_ghosts);
    }
  }

  // Hessian correction (Solid/Hessian correction, present variant): the paper's method plus an
  // extension that makes the vertex values exact for quadratic fields.
  //
  // Why the paper's forms lose a log at a traction corner. The linear least-squares vertex fit
  // (App. B) has the error sum_j a_j 1/2 s_j.H.s_j (s_j = r_j - x_v): O(h^2), with a coefficient set
  // by the stencil's shape. Between interior vertices of a smooth mesh it varies smoothly, so the
  // tangential gradient of Eq. 39 (a difference of neighbouring vertex values over a face) stays
  // O(h^2), and what error the face forces carry cancels between the two faces of a cell. A
  // boundary vertex has a one-sided stencil that includes the boundary-face values, and at a
  // traction face these come from Eq. 23, u_b = u_P + k_P.grad u_P + d_n g_n, a first-order Taylor
  // step with the error -1/2 (k_P.H.k_P - d_n^2 n.H.n). The vertex error at the boundary then has
  // another O(1) coefficient than one vertex in; on the faces of the first cell row that end on the
  // boundary the tangential gradient is O(h) wrong, an O(h^2) force per face. Along the row these
  // forces cancel between neighbouring cells, except where the row ends: at a corner between two
  // traction boundaries the neighbouring faces carry the exact traction, and the unbalanced O(h^2)
  // force acts like a point load, whose displacement in 2D grows like log(1/r). The max
  // displacement error converges like h^2 (a + b log(1/h)) there: plate with a hole, outer corner
  // (2, 2), observed orders 1.96, 1.81, 1.85, 1.87 (up to 256k cells). With the exact displacement
  // imposed on the two outer sides instead, the orders are 1.96 and 2.01.
  //
  // What the correction does, with Hessians H_P of each u_j per cell from a least-squares quadratic
  // fit (QuadraticFit: the cells sharing a vertex with P; at a traction face the normal derivative
  // g_n of Eq. 24, which fixes the second normal derivative; mirror images across symmetry planes;
  // given values on displacement faces):
  //  - vertex values: phi_v = sum_j a_j (phi_j - 1/2 s_j.H_j.s_j), exact for quadratics, so the
  //    vertex error is O(h^3) on the boundary and inside alike;
  //  - boundary values extrapolated at traction and symmetry faces: Eq. 23 plus
  //    1/2 (k_P.H.k_P - d_n^2 n.H.n), exact for quadratics (at a symmetry face for the tangential
  //    components, with d_n n.grad u_t = 0).
  // Both are needed: the second alone (vertex values still linear fits) lifts the finest-pair order
  // to 2.04 but leaves 1.88 on the coarsest pair, and the first alone puts the O(h^2) error of the
  // traction-face values into every boundary vertex (hole-stress orders 1.66, 1.51 even with the
  // exact Hessian). With both the orders
  // are 1.99, 2.00, 2.00 (displacement) and 1.97, 1.99, 1.99 (hole stress), and the max error moves
  // from the corner to the hole. H is computed once per outer iteration, before the sweeps (from u
  // and the g_n of the previous sweeps: consistent at convergence); the price is about 15 % more
  // outer iterations at nu = 0.3. The explicitly treated Hessian terms couple more cells, and where
  // the explicit part is strong already (nearly incompressible plane strain, lambda div u) the
  // segregated iteration then contracts much more slowly: plate with a hole, 968 cells, 274 instead
  // of 131 outer iterations at nu = 0.45, 4866 instead of 274 at nu = 0.49, no convergence in 5000
  // at nu = 0.499 (updating H in every sweep or under-relaxing it helps only partly: 900-1500).
  template <int dim>
  void SolidSolver<dim>::update_hessians()
  {
    for (const unsigned int f : geometry.boundary_faces())
      if (takes_traction(conditions.type(f)))
        boundary_g_n[f] = geometry.faces[f].n * boundary_G[f];
    cell_hessian->compute(u, boundary_u, boundary_g_n, hessian);
    // 1/2 (k_P.H.k_P - d_n^2 n.H.n) per extrapolated boundary face, and the vertex fit's terms:
    // fixed while the sweeps iterate the boundary and vertex values for this u.
    for (const unsigned int f : geometry.boundary_faces())
    {
      const auto& face = geometry.faces[f];
      if (conditions.type(f) == Type::fixed_displacement)
        continue;
      for (unsigned int j = 0; j < dim; ++j)
      {
        const Tensor<2, dim> H = hessian[j][face.P];
        boundary_quadratic_term[f][j] =
          0.5 * (face.k_P * H * face.k_P - face.d_n * face.d_n * (face.n * H * face.n));
      }
    }
    for (unsigned int j = 0; j < dim; ++j)
    {
      vertex_quadratic_term[j].assign(geometry.vertices().size(), 0.0);
      vertex_interpolation.subtract_quadratic_terms(hessian[j], vertex_quadratic_term[j]);
    }
  }

  template <int dim>
  void SolidSolver<dim>::impose_vertex_constraints()
  {
    // The least-squares fit of App. B does not know that a symmetry plane forces u . n = 0 and a
    // displacement boundary gives u exactly; a vertex on such a boundary takes that knowledge
    // (otherwise the fit's O(h^2) error differs between the corner vertices and their
    // neighbours, and the tangential gradient of Eq. 39 drops to first order there).
    for (const auto& [v, n] : symmetry_vertex_normals)
    {
      double u_n = 0;
      for (unsigned int j = 0; j < dim; ++j)
        u_n += vertex_u[j][v] * n[j];
      for (unsigned int j = 0; j < dim; ++j)
        vertex_u[j][v] -= u_n * n[j];
    }
    for (const auto& [v, fn] : fixed_vertex_function)
      for (unsigned int j = 0; j < dim; ++j)
        vertex_u[j][v] = load_factor * fn->value(geometry.vertices()[v], j);
  }

  template <int dim>
  void SolidSolver<dim>::find_constrained_vertices()
  {
    for (const unsigned int f : geometry.all_boundary_faces())
    {
      const auto& face = geometry.faces[f];
      for (const unsigned int v : face.vertices)
        if (conditions.type(f) == Type::symmetry)
        {
          // Each distinct plane once (two planes meet at a corner: project on both).
          bool known = false;
          for (const auto& [w, n] : symmetry_vertex_normals)
            known = known || (w == v && std::abs(n * face.n) > 1 - 1e-8);
          if (!known)
            symmetry_vertex_normals.emplace_back(v, face.n);
        }
        else if (conditions.type(f) == Type::fixed_displacement)
          fixed_vertex_function[v] = &conditions.function(f);
    }
  }

} // namespace fvfsi
