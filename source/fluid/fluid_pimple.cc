// The control of one transient fluid step (or steady pseudo step): PIMPLE's outer loops, each a
// PISO sequence with its self-converging pressure correctors, and the face-velocity change that
// stops both. The terms and corrections a sequence is made of are in fluid_piso.templates.h; the
// equations are in fluid_solver.h.
#include <deal.II/base/mpi.h>

#include <fvfsi/base/exceptions.h>
#include <fvfsi/fluid/fluid_solver.h>
#include <fvfsi/fv/face_loop.h>

#include <cmath>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  void FluidSolver<dim>::solve_piso_step()
  {
    compute_mesh_fluxes();
    try
    {
      // PIMPLE: outer loops, each relaxed by Outer relaxation but the final one, until one
      // changed the face velocities by less than Outer tolerance (then one final loop) or
      // Outer correctors of them are done. A repeated solve of the step (a coupling iteration)
      // takes the first solve's count, as for the correctors.
      const bool repeated = solves_this_step > 1 && !step_correctors.empty();
      const unsigned int most = repeated ? step_correctors.size() : prm.outer_correctors;
      correctors_used = 0;
      bool final = most == 1;
      for (outer_used = 1;; ++outer_used)
      {
        outer_alpha = final || !prm.transient ? 1 : prm.outer_relaxation;
        F_outer_start = F;
        solve_outer_iteration(outer_used - 1, final);
        if (final)
          break;
        final =
          outer_used + 1 == most || (!repeated && prm.outer_tolerance > 0 &&
                                     face_velocity_change(F_outer_start) < prm.outer_tolerance);
      }
    }
    catch (const std::exception& e)
    {
      const std::string what = concise_message(e);
      throw std::runtime_error(
        what.rfind("Fluid:", 0) == 0 ? what : "Fluid: at " + step_name() + ": " + what);
    }
    update_velocity_boundary_values();
    update_velocity_gradients();
    check_bounded_velocity();
  }

  template <int dim>
  void FluidSolver<dim>::solve_outer_iteration(const unsigned int outer, const bool last)
  {
    // One PISO sequence: momentum predictor with the latest fluxes, then pressure correctors.
    update_velocity_boundary_values();
    update_velocity_gradients();
    update_pressure_boundary_values();
    update_pressure_gradient();
    assemble_momentum();
    if (prm.momentum_predictor)
    {
      solve_momentum();
      check_finite("velocity (momentum predictor)");
    }
    assemble_pressure_matrix();
    // PISO's correctors (Issa 1986): at least `least`, then more while the last one still
    // changed the face velocities F_f / S_f by more than the Pressure corrector tolerance times
    // their largest value, at most `most`. Each corrector from the least on may be the last, so
    // its pressure solve gets the full Residual reduction.
    const auto [least, most] = corrector_range(outer);
    unsigned int k = 1;
    for (;; ++k)
    {
      const bool may_be_last = k >= least;
      if (may_be_last && k < most)
        F_before_corrector = F;
      compute_predicted_fluxes(k == 1);
      if (simplec())
        grad_p_before = grad_p;
      if (use_p_extrapolated && outer == 0 && k == 1)
        p = p_extrapolated; // a start value only (Fluid/Pressure extrapolation)
      solve_pressure(last && may_be_last);
      correct_fluxes();
      update_pressure_boundary_values();
      update_pressure_gradient();
      correct_velocity();
      check_finite("pressure or velocity (pressure corrector)");
      if (k >= most || (may_be_last && face_velocity_change(F_before_corrector) <
                                         prm.pressure_corrector_tolerance))
        break;
    }
    if (solves_this_step == 1)
      step_correctors.push_back(k);
    correctors_used += k;
  }

  template <int dim>
  std::pair<unsigned int, unsigned int>
  FluidSolver<dim>::corrector_range(const unsigned int outer) const
  {
    // A repeated solve of the step (a coupling iteration) takes the first solve's counts: the
    // solve is then a smooth function of the mesh motion, as a quasi-Newton coupling needs.
    if (solves_this_step > 1 && outer < step_correctors.size())
      return {step_correctors[outer], step_correctors[outer]};
    if (!prm.transient)
      return {prm.pressure_correctors, prm.pressure_correctors};
    return {prm.pressure_correctors,
            std::max(prm.pressure_correctors, prm.max_pressure_correctors)};
  }

  template <int dim>
  double FluidSolver<dim>::face_velocity_change(const FaceVector& before) const
  {
    // max_f |F_f - before_f| / S_f over max_f |F_f| / S_f.
    const double change =
      face_maximum(geometry, [&](const unsigned int f, const FaceGeometry<dim>& face)
                   { return std::abs(F[f] - before[f]) / face.area; });
    const double largest =
      face_maximum(geometry, [&](const unsigned int f, const FaceGeometry<dim>& face)
                   { return std::abs(F[f]) / face.area; });
    return largest > 0 ? change / largest : 0;
  }

  // fluid_solver.cc instantiates the class; the members defined here are instantiated here.
  template void FluidSolver<2>::solve_piso_step();
  template void FluidSolver<2>::solve_outer_iteration(unsigned int, bool);
  template std::pair<unsigned int, unsigned int>
  FluidSolver<2>::corrector_range(unsigned int) const;
  template double FluidSolver<2>::face_velocity_change(const FaceVector&) const;
  template void FluidSolver<3>::solve_piso_step();
  template void FluidSolver<3>::solve_outer_iteration(unsigned int, bool);
  template std::pair<unsigned int, unsigned int>
  FluidSolver<3>::corrector_range(unsigned int) const;
  template double FluidSolver<3>::face_velocity_change(const FaceVector&) const;
} // namespace fvfsi
