// What the solved flow gives the scenes: wall forces and tractions, probe values, and the
// continuity error and Courant number of the diagnostics. The rest of the FluidSolver is in
// fluid_solver.cc.

#include <deal.II/base/mpi.h>

#include <fvfsi/fluid/fluid_solver.h>
#include <fvfsi/fv/face_loop.h>

#include <algorithm>
#include <cmath>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  Tensor<1, dim> FluidSolver<dim>::patch_force(const unsigned int patch) const
  {
    return patch_sum(geometry, patch,
                     [this](const unsigned int f, const FaceGeometry<dim>& face)
                     { return face.area * wall_traction(f); });
  }

  template <int dim>
  std::pair<Tensor<1, dim>, double> FluidSolver<dim>::probe_values(const PointProbes<dim>& probes,
                                                                   const unsigned int i) const
  {
    const Tensor<1, dim> velocity = probes.template evaluate<Tensor<1, dim>>(
      i,
      [this](const unsigned int c, const Tensor<1, dim>& dx)
      {
        Tensor<1, dim> value = u[c];
        for (unsigned int j = 0; j < dim; ++j)
          value[j] += dx * grad_u[j][c];
        return value;
      });
    const double kinematic =
      probes.template evaluate<double>(i, [this](const unsigned int c, const Tensor<1, dim>& dx)
                                       { return p.local_element(c) + dx * grad_p[c]; });
    return {velocity, prm.rho * kinematic};
  }

  template <int dim>
  Tensor<1, dim> FluidSolver<dim>::patches_force(const std::vector<unsigned int>& ids) const
  {
    Tensor<1, dim> force;
    for (const unsigned int id : ids)
      force += patch_force(id);
    return force;
  }

  template <int dim>
  Tensor<1, dim> FluidSolver<dim>::wall_traction(const unsigned int f) const
  {
    const auto& face = geometry.faces[f];
    Tensor<1, dim> du_dn = boundary_u[f] - u[face.P]; // Eq. 23
    for (unsigned int j = 0; j < dim; ++j)
      du_dn[j] -= face.k_P * grad_u[j][face.P];
    du_dn /= face.d_n;
    return prm.rho * (boundary_p[f] * face.n - prm.nu * du_dn);
  }

  template <int dim>
  double FluidSolver<dim>::continuity_error() const
  {
    std::vector<double> net(geometry.n_owned_cells(), 0.0), total(geometry.n_owned_cells(), 0.0);
    for_each_face(geometry,
                  [&](const unsigned int f, const FaceGeometry<dim>& face)
                  {
                    add_outflow(face, F[f], net);                              // sum_f F_f
                    add_to_cells(face, std::abs(F[f]), std::abs(F[f]), total); // sum_f |F_f|
                  });
    double error = 0;
    for (unsigned int c = 0; c < net.size(); ++c)
      error = std::max(error, std::abs(net[c]) / std::max(total[c], 1e-300));
    return Utilities::MPI::max(error, geometry.comm());
  }

  template <int dim>
  double FluidSolver<dim>::courant_number() const
  {
    std::vector<double> outflow(geometry.n_owned_cells(), 0.0);
    for_each_face(geometry,
                  [&](const unsigned int f, const FaceGeometry<dim>& face)
                  {
                    const double phi = std::abs(F[f] - F_mesh[f]); // relative to the face
                    add_to_cells(face, phi, phi, outflow);
                  });
    double courant = 0;
    for (unsigned int c = 0; c < outflow.size(); ++c)
      courant = std::max(courant, clock.time_step() * outflow[c] / (2 * geometry.cell_volume[c]));
    return Utilities::MPI::max(courant, geometry.comm());
  }

  // The members defined here (the class itself is instantiated in fluid_solver.cc).
  template Tensor<1, 2> FluidSolver<2>::patch_force(unsigned int) const;
  template std::pair<Tensor<1, 2>, double> FluidSolver<2>::probe_values(const PointProbes<2>&,
                                                                        unsigned int) const;
  template Tensor<1, 2> FluidSolver<2>::patches_force(const std::vector<unsigned int>&) const;
  template Tensor<1, 2> FluidSolver<2>::wall_traction(unsigned int) const;
  template double FluidSolver<2>::continuity_error() const;
  template double FluidSolver<2>::courant_number() const;
  template Tensor<1, 3> FluidSolver<3>::patch_force(unsigned int) const;
  template std::pair<Tensor<1, 3>, double> FluidSolver<3>::probe_values(const PointProbes<3>&,
                                                                        unsigned int) const;
  template Tensor<1, 3> FluidSolver<3>::patches_force(const std::vector<unsigned int>&) const;
  template Tensor<1, 3> FluidSolver<3>::wall_traction(unsigned int) const;
  template double FluidSolver<3>::continuity_error() const;
  template double FluidSolver<3>::courant_number() const;
} // namespace fvfsi
