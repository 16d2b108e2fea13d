#pragma once
// The SolidSolver's coupled algorithm without an assembled Jacobian (Solid/Jacobian-free Newton):
// GMRES on J v ~ (F(x + eps v) - F(x)) / eps (exact for linear elasticity, eps scaled so that
// max |eps v| is the cell size; 1e-7 of it for St. Venant-Kirchhoff), right-preconditioned by the
// segregated operator: one ML AMG V-cycle of each component's A_j (the matrices of the segregated
// algorithm: -dR_j/du_j without the explicit coupling) on the cell rows, and on the boundary
// rows the inverse of their linear-elastic diagonal (block). See solid_coupled.templates.h for
// the unknowns and the Newton iteration.
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <fvfsi/solid/solid_solver.h>

#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  void SolidSolver<dim>::setup_jacobian_free(const NewtonVector& x, const NewtonVector& F)
  {
    jfnk_x = x;
    jfnk_F = F;
    const double c0 = parameters.transient ? clock.bdf().c0 : 0;
    if (c0 * c0 == jfnk_mass_coefficient)
      return;
    assemble_matrices(c0 * c0);
    TrilinosWrappers::PreconditionAMG::AdditionalData data; // as LinearSolver's
    data.elliptic = true;
    data.higher_order_elements = false;
    data.smoother_sweeps = 2;
    data.aggregation_threshold = 0.02;
    for (unsigned int j = 0; j < dim; ++j)
      jfnk_amg[j].initialize(matrix[j], data);
    jfnk_mass_coefficient = c0 * c0;
  }

  template <int dim>
  void SolidSolver<dim>::apply_segregated_preconditioner(NewtonVector& y,
                                                         const NewtonVector& r) const
  {
    CellVector r_j = geometry.make_cell_vector(), y_j = r_j;
    for (unsigned int j = 0; j < dim; ++j)
    {
      for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
        r_j.local_element(c) = r.local_element(probing->local_node(c) * dim + j);
      jfnk_amg[j].vmult(y_j, r_j);
      for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
        y.local_element(probing->local_node(c) * dim + j) = y_j.local_element(c);
    }
    // Boundary rows, linear elastic: u_b: K S / d_n; g_n: K S (normal part), mu S (tangential).
    const double K = lame.K(), mu = lame.mu;
    for (const unsigned int f : geometry.boundary_faces())
    {
      const auto& face = geometry.faces[f];
      Tensor<1, dim> r_g;
      for (unsigned int j = 0; j < dim; ++j)
      {
        if (ub_node[f] != invalid_cell)
          y.local_element(ub_node[f] * dim + j) =
            r.local_element(ub_node[f] * dim + j) * face.d_n / (K * face.area);
        if (gn_node[f] != invalid_cell)
          r_g[j] = r.local_element(gn_node[f] * dim + j);
      }
      if (gn_node[f] == invalid_cell)
        continue;
      const Tensor<1, dim> y_g =
        r_g / (mu * face.area) +
        (1 / (K * face.area) - 1 / (mu * face.area)) * (face.n * r_g) * face.n;
      for (unsigned int j = 0; j < dim; ++j)
        y.local_element(gn_node[f] * dim + j) = y_g[j];
    }
  }

  template <int dim>
  void SolidSolver<dim>::solve_newton_system(NewtonVector& dx, const NewtonVector& rhs,
                                             const double reduction)
  {
    const std::string what = "the solid's Newton system at " + clock.step_name();
    if (!parameters.jacobian_free)
    {
      n_krylov += jacobian_solver->solve(dx, rhs, what, reduction);
      return;
    }
    struct Operator
    {
      SolidSolver<dim>& solver;
      double h;
      mutable NewtonVector x, F;
      void vmult(NewtonVector& y, const NewtonVector& v) const
      {
        const double eps = h / std::max(v.linfty_norm(), std::numeric_limits<double>::min());
        x = solver.jfnk_x;
        x.add(eps, v);
        solver.coupled_residual(x, F);
        y = F;
        y -= solver.jfnk_F;
        y /= eps;
      }
    } J{*this, (lame.nonlinear ? 1e-7 : 1.0) * cell_size, jfnk_x, jfnk_F};
    struct Preconditioner
    {
      const SolidSolver<dim>& solver;
      void vmult(NewtonVector& y, const NewtonVector& r) const
      {
        solver.apply_segregated_preconditioner(y, r);
      }
    } P{*this};
    const auto& p = parameters.newton_solver;
    SolverControl control(p.max_iterations,
                          (reduction >= 0 ? reduction : p.reduction) * rhs.l2_norm(), false, false);
    SolverGMRES<NewtonVector> gmres(
      control, typename SolverGMRES<NewtonVector>::AdditionalData(p.restart, true));
    try
    {
      gmres.solve(J, dx, rhs, P);
    }
    catch (const std::exception&)
    {
      throw std::runtime_error("Jacobian-free GMRES on " + what + " did not converge: residual " +
                               Utilities::to_string(control.last_value()) + " after " +
                               std::to_string(control.last_step()) + " iterations (target " +
                               Utilities::to_string(control.tolerance()) + ")");
    }
    n_krylov += control.last_step();
  }
} // namespace fvfsi
