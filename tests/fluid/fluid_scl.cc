// Space conservation law (Eq. 3) on moving meshes, 2D and 3D, serial and mpirun=2: the uniform flow
// of prm/ale_uniform_flow.prm, u = (1, 0.5[, 0.25]) m/s, p = 0, through the unit square (cube)
// whose interior vertices move smoothly in time by up to 0.1 m (0.8 cells of the 8^dim mesh,
// randomly distorted by 0.25), 16 time steps (backward Euler, then BDF2).
//
// Asserted, with the mesh fluxes the solver builds from the swept volumes
// (FVGeometry::swept_volumes):
//  - the discrete SCL in BDF2 form, c0 V_P - c1 V_P^o + c2 V_P^oo = sum_f F_f^mesh, in every cell
//    and time step, to 1e-12 of V_P / dt (measured ~1e-15);
//  - the flow stays uniform: max |u - U| / |U| < 1e-10 and max |p| / |U|^2 < 1e-10 (measured
//    ~1e-15).
// Control: with mesh fluxes from the face-centre displacement, dV_f = S_f . (r_f^new - r_f^old),
// the SCL check fails (printed). The uniform flow survives even those fluxes: the solver writes
// the time and convection terms with the SCL already substituted (fluid_solver.h), which is
// identical to the conservative form exactly when the SCL holds; inconsistent mesh fluxes cost
// conservation, not the uniform flow. So the SCL itself is what the first check guards.
#include <fvfsi/ale/mesh_motion.h>
#include <fvfsi/fluid/fluid_solver.h>
#include <fvfsi/mesh/mesh_builder.h>

#include "../test_utilities.h"

#include <cmath>

using namespace fvfsi_test;

template <int dim>
std::vector<std::string> overrides_for_dim()
{
  if (dim == 2)
    return {};
  const std::string U = "1; 0.5; 0.25";
  return {"Dimension=3",
          "Fluid/Body force=0; 0; 0",
          "Mesh/Patch names=0: left, 1: right, 2: bottom, 3: top, 4: front, 5: back",
          "Fluid/Initial velocity=" + U,
          "Fluid/Velocity inlet=left: " + U + " | bottom: " + U + " | top: " + U +
            " | front: " + U + " | back: " + U,
          "Mesh motion/Displacement=0.1*sin(2*pi*t)*sin(pi*x)*sin(2*pi*y)*sin(pi*z); "
          "0.1*sin(3*pi*t)*sin(2*pi*x)*sin(pi*y)*sin(pi*z); "
          "0.1*sin(pi*t)*sin(pi*x)*sin(pi*y)*sin(2*pi*z)"};
}

/// Max over cells and time steps of the SCL residual / (V_P / dt), |u - U| / |U| and |p| / |U|^2.
template <int dim>
std::array<double, 3> run(const bool swept_volumes)
{
  const auto prm = shipped_case("ale_uniform_flow", overrides_for_dim<dim>());
  dealii::parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
  fvfsi::make_mesh(prm->mesh, tria);
  fvfsi::FVGeometry<dim> fv(tria), reference(tria);
  fvfsi::TimeControl clock(prm->time);
  fvfsi::FluidSolver<dim> fluid(fv, prm->mesh, prm->fluid, clock);
  fvfsi::MeshMotion<dim> motion(reference, prm->mesh, prm->fluid_scene.mesh_motion, clock);
  dealii::Tensor<1, dim> U;
  for (unsigned int d = 0; d < dim; ++d)
    U[d] = std::pow(0.5, d);

  std::array<double, 3> error{};
  const double dt = clock.time_step();
  std::vector<double> V_old = fv.cell_volume, V_old2 = fv.cell_volume;
  const unsigned int n_steps = clock.last_step();
  for (unsigned int step = 0; step < n_steps; ++step)
  {
    clock.advance();
    const auto x = motion.vertex_positions();
    std::vector<double> dV = fv.swept_volumes(fv.vertices(), x);
    if (!swept_volumes)
    {
      std::vector<dealii::Point<dim>> old_centres;
      for (const auto& face : fv.faces)
        old_centres.push_back(face.centre);
      fv.reinit(x);
      for (unsigned int f = 0; f < fv.faces.size(); ++f)
        dV[f] = fv.faces[f].S * (fv.faces[f].centre - old_centres[f]);
    }
    else
      fv.reinit(x);
    fluid.move_mesh(dV);
    fluid.solve_time_step();

    const double c0 = (step == 0 ? 1.0 : 1.5) / dt, c1 = (step == 0 ? 1.0 : 2.0) / dt,
                 c2 = (step == 0 ? 0.0 : 0.5) / dt;
    std::vector<double> net(fv.n_owned_cells(), 0.0);
    for (unsigned int f = 0; f < fv.faces.size(); ++f)
    {
      const auto& face = fv.faces[f];
      if (face.kind == fvfsi::FaceKind::ghost_boundary)
        continue;
      net[face.P] += fluid.mesh_flux()[f];
      if (face.kind == fvfsi::FaceKind::interior)
        net[face.N] -= fluid.mesh_flux()[f];
    }
    for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
    {
      const double V = fv.cell_volume[c];
      error[0] =
        std::max(error[0], std::abs(c0 * V - c1 * V_old[c] + c2 * V_old2[c] - net[c]) * dt / V);
      error[1] = std::max(error[1], (fluid.velocity()[c] - U).norm() / U.norm());
      error[2] =
        std::max(error[2], std::abs(fluid.kinematic_pressure().local_element(c)) / U.norm_square());
    }
    V_old2 = V_old;
    V_old = fv.cell_volume;
  }
  for (double& e : error)
    e = dealii::Utilities::MPI::max(e, MPI_COMM_WORLD);
  return error;
}

template <int dim>
void check(std::ofstream& out)
{
  const auto e = run<dim>(true);
  out << dim << "D, mesh fluxes from swept volumes: discrete SCL in every cell and step (< 1e-12): "
      << yes_no(e[0] < 1e-12) << "\n";
  out << dim << "D, uniform flow kept: max |u - U| / |U| < 1e-10: " << yes_no(e[1] < 1e-10)
      << ", max |p| / |U|^2 < 1e-10: " << yes_no(e[2] < 1e-10) << "\n";
  const auto control = run<dim>(false);
  out << dim
      << "D, control, face-centre mesh fluxes: SCL residual > 1e-6: " << yes_no(control[0] > 1e-6)
      << "\n";
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  check<2>(out);
  check<3>(out);
}
