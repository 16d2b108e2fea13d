// The fluid's divergence guard (fv/divergence_guard.h): max |u| against the velocity scale U of
// the run's data.

#include <deal.II/base/mpi.h>

#include <fvfsi/fluid/fluid_solver.h>
#include <fvfsi/fv/divergence_guard.h>

#include <algorithm>
#include <cmath>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  double FluidSolver<dim>::data_velocity_scale() const
  {
    // Given velocities (inlets; walls move with the mesh), the Bernoulli speed of the outlets'
    // pressure differences, and the free-fall speed sqrt(|g| L) of the body force.
    double speed = 0, p_max = -1e300, p_min = 1e300, g = 0;
    for (const unsigned int f : geometry.boundary_faces())
    {
      const Type t = conditions.type(f);
      if (t == Type::velocity_inlet || t == Type::wall)
        speed = std::max(speed, boundary_u[f].norm());
      else if (t == Type::outlet)
      {
        p_max = std::max(p_max, boundary_p[f]);
        p_min = std::min(p_min, boundary_p[f]);
      }
    }
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      double g2 = 0;
      for (unsigned int j = 0; j < dim; ++j)
        g2 += body_force_value[j][c] * body_force_value[j][c];
      g = std::max(g, g2);
    }
    const MPI_Comm comm = geometry.comm();
    speed = Utilities::MPI::max(speed, comm);
    const double dp = Utilities::MPI::max(p_max, comm) + Utilities::MPI::max(-p_min, comm);
    return std::max({speed, std::sqrt(std::max(dp, 0.0)),
                     std::sqrt(std::sqrt(Utilities::MPI::max(g, comm)) * domain_length)});
  }

  template <int dim>
  void FluidSolver<dim>::check_bounded_velocity()
  {
    // Transient runs only: a steady run's pseudo time steps may pass through large values on
    // their way (alpha too large, before solve_steady() lowers it), and a steady run that does
    // not converge stops with an error of its own.
    if (!prm.transient)
      return;
    scale_U = std::max(scale_U, data_velocity_scale());
    const CellMaximum<dim> largest =
      cell_maximum<dim>(geometry, [this](const unsigned int c) { return u[c].norm(); });
    // Nothing drives the flow (U = 0): no scale to compare with.
    if (scale_U == 0)
      return;
    largest_velocity_ratio_seen = std::max(largest_velocity_ratio_seen, largest.value / scale_U);
    check_bounded(largest, prm.velocity_bound * scale_U, "Fluid", step_name(), "max |u|", "m/s",
                  Utilities::to_string(prm.velocity_bound) +
                    " x the velocity scale U = " + Utilities::to_string(scale_U) +
                    " m/s of the boundary data, body force and initial velocity; "
                    "Fluid/Velocity bound",
                  "reduce Time/Time step (or set Time/Adaptive = Courant), raise Fluid/Max "
                  "pressure correctors, or at large Courant numbers take relaxed PIMPLE outer "
                  "loops (Fluid/Outer correctors = 20, Outer tolerance = 1e-3, Outer "
                  "relaxation = 0.7; doc/results/hard_cases.md)");
  }

  template double FluidSolver<2>::data_velocity_scale() const;
  template void FluidSolver<2>::check_bounded_velocity();
  template double FluidSolver<3>::data_velocity_scale() const;
  template void FluidSolver<3>::check_bounded_velocity();
} // namespace fvfsi
