#pragma once
// The SolidSolver's coupled algorithm (Solid/Algorithm = coupled): Newton's method on the discrete
// equations that the segregated outer iterations converge to (see solid_solver.h).
//
// What is solved. A converged segregated step satisfies, besides R(u) = 0 (Eq. 16), the relations
// its boundary sweeps iterate: the boundary values u_b of the symmetry and traction faces
// (Eqs 23-24), which depend on the vertex values and gradients, which depend on u_b; and at a
// traction face the normal derivative g_n = n . grad u of Eq. 24, computed from its previous value
// (K g_n = t S'/S - n . q(n g_n + T)). These relations couple the boundary faces along the whole
// boundary (one sweep moves information one face further), so R(u) after a fixed number of sweeps
// is a function of u with a non-local Jacobian that is not the Jacobian of the converged equations.
// The coupled algorithm therefore takes u_b and g_n as unknowns of their own:
//
//   x = (u per cell; u_b per symmetry and traction face; g_n per traction face),
//   F(x) = ( -R(u; u_b, g_n)                                      per cell,
//            K S_f / d_fn (u_b - u_b'(u, u_b, g_n))               per symmetry / traction face,
//            K S_f (g_n - g_n'(u, u_b, g_n))                      per traction face ),
//
// where u_b' and g_n' are one boundary update (update_boundary_values) from the vertex values and
// gradients of (u, u_b) (and, with the Hessian correction, the Hessians of (u, u_b, g_n)): F = 0 is
// exactly the fixed point of the segregated iteration, and F is local (a cell's rows depend on the
// cells within 2 vertex-neighbour steps; 3 with the Hessian correction or the Jasak-Weller
// gradients, whose skew correction reads the neighbours' gradients). Its Jacobian is sparse and is
// assembled by probing (ProbedJacobian: F at x + h sum e_(a,j) over the nodes a of one colour, the
// block layout of dim unknowns per node; exact for linear elasticity, a forward difference with
// h = 1e-7 (volume / cells)^(1/dim) for St. Venant-Kirchhoff). The rows of u_b and g_n are scaled
// to forces like the cell rows.
//
// Newton's method: J dx = -F(x) (Solid Newton linear solver: sparse direct or GMRES), then a
// backtracking line search on |F| (halving the step up to 10 times, Armijo's condition); stop when
// |F| has fallen by the Newton tolerance or a step changes u by less than the outer tolerance
// (max |du| / max |u|). Linear elasticity: the Jacobian depends on c0 only and is assembled and
// factorised once (one Newton step, and its factorisation serves every later time step and
// coupling iteration). St. Venant-Kirchhoff: the Jacobian is kept (across time steps too) while
// the simplified correction is less than 0.1 of the Newton step, else assembled anew (Newton
// update every iteration = true: every iteration). A steady
// solve that fails at the full load steps the load (tractions, body force, fixed displacements x
// a factor from 0 to 1, halving the increment on failure); a transient one stops with an error
// naming the time step.
#include <deal.II/base/mpi.h>

#include <fvfsi/fv/ghost_faces.h>
#include <fvfsi/solid/solid_solver.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  void SolidSolver<dim>::setup_coupled()
  {
    // Extra Newton nodes of an owned cell: its symmetry and traction faces in face-number order
    // (u_b), and of those the traction faces (g_n, scaled so that its probe changes the gradient
    // as much as a cell's does).
    std::vector<std::vector<unsigned int>> faces_of(geometry.n_owned_cells());
    for (const unsigned int f : geometry.boundary_faces())
      faces_of[geometry.faces[f].P].push_back(f);
    double volume = 0;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
      volume += geometry.cell_volume[c];
    cell_size =
      std::pow(Utilities::MPI::sum(volume, geometry.comm()) / geometry.n_global_cells(), 1.0 / dim);
    std::vector<unsigned int> extra(geometry.n_owned_cells(), 0);
    std::vector<double> scale;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      std::sort(faces_of[c].begin(), faces_of[c].end(),
                [this](const unsigned int a, const unsigned int b)
                { return geometry.faces[a].face_no < geometry.faces[b].face_no; });
      scale.push_back(1);
      for (const unsigned int f : faces_of[c])
      {
        if (conditions.type(f) != Type::fixed_displacement)
          ++extra[c], scale.push_back(1);
        if (takes_traction(conditions.type(f)))
          ++extra[c], scale.push_back(1 / cell_size);
      }
    }
    const bool wide = cell_hessian || parameters.variant == Variant::jasak_weller;
    probing = std::make_unique<ProbedJacobian<dim>>(geometry, extra, scale, dim, wide ? 3 : 2);
    ub_node.assign(geometry.faces.size(), invalid_cell);
    gn_node = ub_node;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      unsigned int i = 1;
      for (const unsigned int f : faces_of[c])
      {
        if (conditions.type(f) != Type::fixed_displacement)
          ub_node[f] = probing->local_node(c, i++);
        if (takes_traction(conditions.type(f)))
          gn_node[f] = probing->local_node(c, i++);
      }
    }
    for (auto& r : coupled_cell_residual)
      r = geometry.make_cell_vector();
    jacobian_solver = std::make_unique<JacobianSolver>(parameters.newton_solver);
  }

  template <int dim>
  void SolidSolver<dim>::coupled_state(NewtonVector& x) const
  {
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
      for (unsigned int j = 0; j < dim; ++j)
        x.local_element(probing->local_node(c) * dim + j) = u.components[j].local_element(c);
    for (const unsigned int f : geometry.boundary_faces())
    {
      const Tensor<1, dim> g_n = geometry.faces[f].n * boundary_G[f];
      for (unsigned int j = 0; j < dim; ++j)
      {
        if (ub_node[f] != invalid_cell)
          x.local_element(ub_node[f] * dim + j) = boundary_u[f][j];
        if (gn_node[f] != invalid_cell)
          x.local_element(gn_node[f] * dim + j) = g_n[j];
      }
    }
  }

  template <int dim>
  void SolidSolver<dim>::set_fixed_boundary_values()
  {
    for (const unsigned int f : geometry.boundary_faces())
      if (conditions.type(f) == Type::fixed_displacement)
        for (unsigned int d = 0; d < dim; ++d)
          boundary_u[f][d] = load_factor * conditions.value(f, geometry.faces[f].centre, d);
  }

  template <int dim>
  void SolidSolver<dim>::coupled_residual(const NewtonVector& x, NewtonVector& F)
  {
    ++n_residuals;
    // The state from x: u, u_b, and g_n as the normal part of the boundary gradient.
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
      for (unsigned int j = 0; j < dim; ++j)
        u.components[j].local_element(c) = x.local_element(probing->local_node(c) * dim + j);
    u.update_ghost_values();
    for (const unsigned int f : geometry.boundary_faces())
      for (unsigned int j = 0; j < dim; ++j)
      {
        if (ub_node[f] != invalid_cell)
          boundary_u[f][j] = x.local_element(ub_node[f] * dim + j);
        if (gn_node[f] != invalid_cell)
          for (unsigned int i = 0; i < dim; ++i)
            boundary_G[f][i][j] = geometry.faces[f].n[i] * x.local_element(gn_node[f] * dim + j);
      }
    update_ghost_boundary_faces(geometry, boundary_u);
    // Hessians (from u, u_b, g_n), vertex values and gradients (from u, u_b); the tangential part
    // of the boundary gradient; then one update of u_b and g_n (Eqs 23-24) and the residual.
    if (cell_hessian)
      update_hessians();
    update_cell_gradients();
    for (const unsigned int f : geometry.boundary_faces())
      if (gn_node[f] != invalid_cell)
        boundary_G[f] += tangential_part(f);
    update_boundary_values();
    compute_residual(coupled_cell_residual);
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
      for (unsigned int j = 0; j < dim; ++j)
        F.local_element(probing->local_node(c) * dim + j) =
          -coupled_cell_residual[j].local_element(c);
    const double K = lame.K();
    for (const unsigned int f : geometry.boundary_faces())
    {
      const auto& face = geometry.faces[f];
      const Tensor<1, dim> g_n = face.n * boundary_G[f];
      for (unsigned int j = 0; j < dim; ++j)
      {
        if (const unsigned int i = ub_node[f] * dim + j; ub_node[f] != invalid_cell)
          F.local_element(i) = K * face.area / face.d_n * (x.local_element(i) - boundary_u[f][j]);
        if (const unsigned int i = gn_node[f] * dim + j; gn_node[f] != invalid_cell)
          F.local_element(i) = K * face.area * (x.local_element(i) - g_n[j]);
      }
    }
  }

  template <int dim>
  double SolidSolver<dim>::relative_change(const NewtonVector& dx, const NewtonVector& x) const
  {
    double max_dx = 0, max_x = 0;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
      for (unsigned int j = 0; j < dim; ++j)
      {
        const unsigned int i = probing->local_node(c) * dim + j;
        max_dx = std::max(max_dx, std::abs(dx.local_element(i)));
        max_x = std::max(max_x, std::abs(x.local_element(i)));
      }
    max_dx = Utilities::MPI::max(max_dx, geometry.comm());
    max_x = Utilities::MPI::max(max_x, geometry.comm());
    return max_x == 0 ? (max_dx == 0 ? 0 : 1) : max_dx / max_x;
  }

  template <int dim>
  void SolidSolver<dim>::assemble_jacobian(const NewtonVector& x, const NewtonVector& F)
  {
    ++n_jacobians;
    if (parameters.jacobian_free)
    {
      setup_jacobian_free(x, F);
      return;
    }
    const double h = (lame.nonlinear ? 1e-7 : 1.0) * cell_size;
    probing->assemble([this](const NewtonVector& x_probe, NewtonVector& F_probe)
                      { coupled_residual(x_probe, F_probe); },
                      x, F, h, /*central=*/false, jacobian);
    jacobian_solver->initialize(jacobian, dim);
  }

  template <int dim>
  double SolidSolver<dim>::damped_step(NewtonVector& x, NewtonVector& F, const NewtonVector& dx,
                                       NewtonVector& dx_bar)
  {
    // Deuflhard's natural monotonicity test (affine covariant): accept x + lambda dx if the
    // simplified Newton correction dx_bar = -J^-1 F(x + lambda dx) is shorter than
    // (1 - lambda / 4) |dx|, else halve lambda (at most 10 times). Not |F|: a geometrically
    // nonlinear beam's residual grows along a good Newton step (the linearised rotation of the
    // first step strains the beam by theta^2 / 2 everywhere), its correction does not.
    const double norm_dx = newton_norm(dx);
    NewtonVector x_try(x), F_try(F), rhs(F);
    for (double lambda = 1; lambda > 1e-3; lambda /= 2)
    {
      x_try = x;
      x_try.add(lambda, dx);
      coupled_residual(x_try, F_try);
      if (!std::isfinite(F_try.l2_norm()))
        continue;
      rhs.equ(-1, F_try);
      dx_bar = 0; // an estimate: to 1 % with GMRES
      solve_newton_system(dx_bar, rhs, 1e-2);
      if (parameters.newton_log)
        pcout << "fvfsi: solid Newton trial step " << lambda
              << ": |dx_bar| / |dx| = " << newton_norm(dx_bar) / norm_dx << " (accepted if at most "
              << 1 - lambda / 4 << ")\n";
      if (newton_norm(dx_bar) <= (1 - lambda / 4) * norm_dx || norm_dx == 0)
      {
        x = x_try;
        F = F_try;
        return lambda;
      }
    }
    return 0;
  }

  template <int dim>
  double SolidSolver<dim>::newton_norm(const NewtonVector& v) const
  {
    // l2 norm with g_n in length units (times the cell size), like u and u_b.
    double sum = 0;
    for (unsigned int i = 0; i < v.locally_owned_size(); ++i)
      sum += v.local_element(i) * v.local_element(i);
    for (const unsigned int f : geometry.boundary_faces())
      if (gn_node[f] != invalid_cell)
        for (unsigned int j = 0; j < dim; ++j)
          sum += (cell_size * cell_size - 1) * std::pow(v.local_element(gn_node[f] * dim + j), 2);
    return std::sqrt(Utilities::MPI::sum(sum, geometry.comm()));
  }

  template <int dim>
  bool SolidSolver<dim>::newton(NewtonVector& x, std::string& failure)
  {
    // dx = -J^-1 F(x), a damped step, and the simplified correction dx_bar = -J^-1 F(x_new), which
    // estimates the remaining error: stop when it changes u by less than the outer tolerance, or
    // when |F| has fallen by the Newton tolerance.
    NewtonVector F = probing->make_vector(), dx = F, dx_bar = F, rhs = F;
    coupled_residual(x, F);
    const double r0 = F.l2_norm();
    if (!std::isfinite(r0))
      return failure = "the residual is not finite at the start", false;
    bool stale = false; // the kept Jacobian of St. Venant-Kirchhoff no longer converges fast
    double r = r0, contraction = 0;
    for (unsigned int k = 1; k <= parameters.max_newton_iterations && r > 0; ++k)
    {
      const double c0 = parameters.transient ? clock.bdf().c0 : 0;
      bool fresh = false;
      if (jacobian_mass_coefficient != c0 * c0 ||
          (lame.nonlinear && (parameters.newton_update_every_iteration || stale)))
      {
        assemble_jacobian(x, F);
        jacobian_mass_coefficient = c0 * c0;
        fresh = true;
      }
      // dx = -J^-1 F(x). With the Jacobian kept and a direct solver, that is the simplified
      // correction dx_bar = -J^-1 F(x) the last damped step computed at the accepted x: reuse it
      // (one solve per Newton iteration instead of two; a Krylov dx_bar is only a 1 % estimate).
      if (!fresh && k > 1 && !parameters.jacobian_free && jacobian_solver->direct_method())
        dx = dx_bar;
      else
      {
        rhs.equ(-1, F);
        dx = 0;
        solve_newton_system(dx, rhs);
      }
      const double lambda = damped_step(x, F, dx, dx_bar);
      if (lambda == 0)
      {
        if (!fresh && lame.nonlinear)
        {
          stale = true; // retry from x with a new Jacobian
          continue;
        }
        return failure = "no damped Newton step passes the monotonicity test (iteration " +
                         std::to_string(k) + ", |F| / |F_0| = " + Utilities::to_string(r / r0) +
                         ")",
               false;
      }
      ++last_outer_iterations;
      r = F.l2_norm();
      contraction = newton_norm(dx_bar) / newton_norm(dx);
      const double error = relative_change(dx_bar, x);
      if (parameters.newton_log)
        pcout << "fvfsi: solid " << clock.step_name() << ", Newton iteration " << k << ": step "
              << lambda << ", |F| / |F_0| " << r / r0 << ", correction " << error
              << ", Krylov iterations so far " << n_krylov << (fresh ? ", new Jacobian" : "")
              << "\n";
      if ((lambda == 1 && error < parameters.outer_tolerance) ||
          r <= parameters.newton_tolerance * r0)
      {
        if (parameters.jacobian_free)
          coupled_residual(x, F); // the state of x (the Krylov solve probed other points)
        return true;
      }
      stale = contraction > 0.1;
    }
    if (r == 0)
      return true;
    return failure = "no convergence in " + std::to_string(parameters.max_newton_iterations) +
                     " iterations (|F| / |F_0| = " + Utilities::to_string(r / r0) + ")",
           false;
  }

  template <int dim>
  void SolidSolver<dim>::solve_coupled()
  {
    last_outer_iterations = 0;
    NewtonVector x = probing->make_vector();
    coupled_state(x);
    load_factor = 1;
    set_fixed_boundary_values();
    std::string failure;
    if (newton(x, failure))
      return;
    const std::string what =
      "Solid (coupled): Newton's method did not converge at " + clock.step_name() + ": " + failure;
    if (parameters.transient)
      throw std::runtime_error(what + " (reduce the time step, or raise Solid/Max Newton "
                                      "iterations)");
    // Load stepping from the unloaded state (u = 0, u_b = 0, g_n = 0 solves it).
    pcout << "fvfsi: " << what << "; stepping the load\n";
    NewtonVector x_done = probing->make_vector();
    double done = 0, increment = 0.5;
    while (done < 1)
    {
      load_factor = std::min(1.0, done + increment);
      set_fixed_boundary_values();
      x = x_done;
      if (newton(x, failure))
      {
        done = load_factor;
        x_done = x;
        increment = std::min(2 * increment, 1.0);
      }
      else if ((increment /= 2) < 1.0 / 256)
      {
        load_factor = 1;
        throw std::runtime_error(what + "; load stepping stopped at load factor " +
                                 Utilities::to_string(done) + ": " + failure);
      }
    }
  }
} // namespace fvfsi
