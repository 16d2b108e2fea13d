// The FluidSolver's set-up, boundary values and gradients, and the time step driver. The PISO
// steps themselves (momentum, pressure, corrections) are in fluid_piso.templates.h.

#include <deal.II/base/mpi.h>

#include <fvfsi/base/exceptions.h>
#include <fvfsi/base/parsed_function.h>
#include <fvfsi/fluid/fluid_solver.h>
#include <fvfsi/fv/divergence_guard.h>
#include <fvfsi/fv/face_loop.h>
#include <fvfsi/fv/ghost_faces.h>

#include "fluid_piso.templates.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  FluidSolver<dim>::FluidSolver(const FVGeometry<dim>& geometry,
                                const MeshParameters& mesh_parameters,
                                const FluidParameters& parameters, const TimeControl& clock)
      : geometry(geometry), prm(parameters), clock(clock),
        pcout(std::cout, Utilities::MPI::this_mpi_process(geometry.comm()) == 0),
        timer_output(MPI_COMM_SELF, pcout, TimerOutput::never, TimerOutput::wall_times),
        operators(geometry), body_force(dim), momentum(geometry), pressure_equation(geometry),
        momentum_solver(parameters.momentum_solver), pressure_solver(parameters.pressure_solver),
        relaxation(parameters.momentum_relaxation)
  {
    initialize_function(body_force, prm.body_force, "Fluid/Body force");
    evaluate_body_force();
    setup_boundary_conditions(mesh_parameters);

    u = h = CellVectorField<dim>(geometry);
    u_levels.start(u);
    for (unsigned int j = 0; j < dim; ++j)
    {
      grad_u[j] = CellGradient<dim>(geometry);
      vertex_u[j].assign(geometry.vertices().size(), 0.0);
      B_rest[j] = geometry.make_cell_vector();
      B_time[j].assign(geometry.n_owned_cells(), 0.0);
    }
    grad_p = CellGradient<dim>(geometry);
    vertex_p.assign(geometry.vertices().size(), 0.0);
    p = geometry.make_cell_vector();
    p.update_ghost_values(); // p = 0 is readable everywhere, ghosts included
    a = geometry.make_cell_vector();
    a_star = geometry.make_cell_vector();
    a_tilde = geometry.make_cell_vector();
    grad_p_before = CellGradient<dim>(geometry);
    pressure_rhs = geometry.make_cell_vector();
    const unsigned int n_faces = geometry.faces.size();
    for (auto* field : {&F, &F_mesh, &F_star, &gamma_p, &gamma_c, &a_star_f, &boundary_p, &swept,
                        &swept_old, &F_before_corrector, &F_outer_start, &F_old_part})
      field->assign(n_faces, 0.0);
    h_skewness.resize(n_faces);
    F_levels.start(F);
    V_levels.start(geometry.cell_volume);
    S_levels.o.resize(n_faces);
    r_f_levels.o.resize(n_faces);
    record_face_geometry();
    S_levels.start(S_levels.o);
    r_f_levels.start(r_f_levels.o);
    boundary_u.assign(n_faces, Tensor<1, dim>());
    c0_cell.assign(geometry.n_owned_cells(), 0.0);
    c0_face.assign(n_faces, 0.0);
    nu_f.assign(n_faces, prm.nu);
    operators.laplacian.reinit_matrix(momentum_matrix);
    operators.laplacian.reinit_matrix(pressure_matrix);
    set_initial_conditions();
    update_volume_ratios();
    domain_length = domain_diameter(geometry);
    scale_U =
      cell_maximum<dim>(geometry, [this](const unsigned int c) { return u[c].norm(); }).value;
  }

  template <int dim>
  void FluidSolver<dim>::setup_boundary_conditions(const MeshParameters& mesh_parameters)
  {
    conditions = FaceConditions<dim, Type>(
      geometry, mesh_parameters, prm.boundary_conditions(),
      [](const Type t) { return t == Type::outlet ? 1u : static_cast<unsigned int>(dim); }, "Fluid",
      "Fluid/Velocity inlet, Outlet, Wall or Symmetry");
    double n_outlet_faces = 0;
    for_each_stored_boundary_face(
      geometry,
      [&](const unsigned int f, const FaceGeometry<dim>& face)
      {
        const Type t = conditions.type(f);
        const bool velocity_given = t == Type::velocity_inlet || t == Type::wall;
        velocity_bc.patch_type[face.patch] =
          velocity_given ? BoundaryType::dirichlet : BoundaryType::neumann;
        pressure_bc.patch_type[face.patch] =
          t == Type::outlet ? BoundaryType::dirichlet : BoundaryType::neumann;
        if (t == Type::outlet)
          n_outlet_faces += 1;
      });
    // Without a pressure boundary the pressure is fixed to 0 in one reference cell.
    pressure_level_fixed = Utilities::MPI::sum(n_outlet_faces, geometry.comm()) > 0;
    velocity_bc.value.assign(geometry.faces.size(), 0.0); // values live in boundary_u
    pressure_bc.value.assign(geometry.faces.size(), 0.0);
  }

  template <int dim>
  void FluidSolver<dim>::set_initial_conditions()
  {
    FunctionParser<dim> u0(dim);
    initialize_function(u0, prm.initial_velocity, "Fluid/Initial velocity");
    set_state(
      [&u0](const Point<dim>& x)
      {
        Tensor<1, dim> value;
        for (unsigned int j = 0; j < dim; ++j)
          value[j] = checked_value(u0, x, j, "Fluid/Initial velocity");
        return value;
      },
      {});
  }

  template <int dim>
  void
  FluidSolver<dim>::set_state(const std::function<Tensor<1, dim>(const Point<dim>&)>& velocity,
                              const std::function<double(const Point<dim>&)>& kinematic_pressure)
  {
    // u at the cell centres, fluxes F_f = S_f . u_f by linear interpolation (boundary: S_f . u_b);
    // all time levels alike.
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      const Tensor<1, dim> value = velocity(geometry.centroid[c]);
      for (unsigned int j = 0; j < dim; ++j)
        u.components[j].local_element(c) = value[j];
      if (kinematic_pressure)
        p.local_element(c) = kinematic_pressure(geometry.centroid[c]);
    }
    u.update_ghost_values();
    p.update_ghost_values();
    update_velocity_boundary_values();
    update_velocity_gradients();
    update_velocity_boundary_values();
    for_each_stored_face(geometry,
                         [this](const unsigned int f, const FaceGeometry<dim>& face)
                         {
                           F[f] = face.S * (face.N == invalid_cell
                                              ? boundary_u[f]
                                              : face.interpolate(u[face.P], u[face.N]));
                         });
    F_levels.start(F);
    u_levels.start(u);
  }

  template <int dim>
  void FluidSolver<dim>::update_velocity_boundary_values()
  {
    for (const unsigned int f : geometry.boundary_faces())
    {
      const auto& face = geometry.faces[f];
      const unsigned int P = face.P;
      Tensor<1, dim> extrapolated = u[P]; // zero normal gradient: u_P + k_P . grad u_P
      for (unsigned int j = 0; j < dim; ++j)
        extrapolated[j] += face.k_P * grad_u[j][P];
      switch (conditions.type(f))
      {
        case Type::velocity_inlet:
          for (unsigned int j = 0; j < dim; ++j)
            boundary_u[f][j] = conditions.value(f, face.centre, j);
          break;
        case Type::wall:
        {
          // The wall moves with the mesh: the tangential part of its face centre's velocity, the
          // normal part from the swept volume (so that S_f . u_b = F_f^mesh exactly).
          const Tensor<1, dim> v_f = r_f_levels.derivative(time_coefficients(), face.centre, f);
          boundary_u[f] = v_f - (v_f * face.n) * face.n + (F_mesh[f] / face.area) * face.n;
          break;
        }
        case Type::outlet:
          boundary_u[f] = extrapolated;
          break;
        case Type::symmetry:
          boundary_u[f] = extrapolated - (extrapolated * face.n) * face.n;
          break;
      }
    }
    update_ghost_boundary_faces(geometry, boundary_u);
  }

  template <int dim>
  void FluidSolver<dim>::update_velocity_gradients()
  {
    TimerOutput::Scope scope(timer_output, "velocity gradients");
    // Vertex values by least squares (App. B) with the boundary values, then Gauss-Green (Eq. 37).
    FaceVector boundary_values(geometry.faces.size());
    for (unsigned int j = 0; j < dim; ++j)
    {
      std::transform(boundary_u.begin(), boundary_u.end(), boundary_values.begin(),
                     [j](const Tensor<1, dim>& u_b) { return u_b[j]; });
      operators.gradient(u.components[j], boundary_values, vertex_u[j], grad_u[j]);
    }
  }

  template <int dim>
  void FluidSolver<dim>::update_pressure_boundary_values()
  {
    // Outlets: the given pressure; elsewhere linear extrapolation from the cell (paper 3.2),
    // p_b = p_P + (r_f - r_P) . (grad p)_P.
    for (const unsigned int f : geometry.boundary_faces())
    {
      const auto& face = geometry.faces[f];
      if (conditions.type(f) == Type::outlet)
        boundary_p[f] = conditions.value(f, face.centre) / prm.rho;
      else
        boundary_p[f] = p.local_element(face.P) + face.d * grad_p[face.P];
      pressure_bc.value[f] = boundary_p[f];
    }
    update_ghost_boundary_faces(geometry, boundary_p);
  }

  template <int dim>
  void FluidSolver<dim>::update_pressure_gradient()
  {
    TimerOutput::Scope scope(timer_output, "pressure gradient");
    operators.gradient(p, boundary_p, vertex_p, grad_p);
  }

  template <int dim>
  BdfCoefficients FluidSolver<dim>::time_coefficients() const
  {
    // Backward Euler on the first step, BDF2 (Eq. 17) after. (Steady runs use local
    // coefficients, see assemble_momentum.)
    return prm.transient ? clock.bdf() : BdfCoefficients();
  }

  template <int dim>
  void FluidSolver<dim>::shift_time_levels()
  {
    u_levels.shift(u);
    u_levels.for_each([](auto& level) { level.update_ghost_values(); });
    F_levels.shift(F);
    V_levels.shift(geometry.cell_volume);
    swept_old = swept;
    std::fill(swept.begin(), swept.end(), 0.0);
    S_levels.shift();
    r_f_levels.shift();
    record_face_geometry(); // the new S^o, r_f^o
    update_volume_ratios();
  }

  template <int dim>
  void FluidSolver<dim>::record_face_geometry()
  {
    for_each_stored_face(geometry,
                         [this](const unsigned int f, const FaceGeometry<dim>& face)
                         {
                           S_levels.o[f] = face.S;
                           r_f_levels.o[f] = face.centre;
                         });
  }

  template <int dim>
  void FluidSolver<dim>::move_mesh(const std::vector<double>& swept_volume)
  {
    AssertDimension(swept_volume.size(), geometry.faces.size());
    // Steady (a steady FSI iteration moves the mesh between steady solves): the state is at rest
    // on the new mesh, no mesh flux (compute_mesh_fluxes() keeps F^mesh = 0), only the geometry
    // changes.
    swept = swept_volume;
    operators.reinit(); // their coefficients depend on the geometry
    update_volume_ratios();
  }

  template <int dim>
  void FluidSolver<dim>::compute_mesh_fluxes()
  {
    // BDF2 form of the SCL: F^mesh = c0 dV^n - c2 dV^(n-1), whose sum over a cell's faces is
    // c0 (V - V^o) - c2 (V^o - V^oo) = c0 V - c1 V^o + c2 V^oo (c1 = c0 + c2).
    const auto [c0, c1, c2] = time_coefficients();
    (void)c1;
    for (unsigned int i = 0; i < F_mesh.size(); ++i)
      F_mesh[i] = prm.transient ? c0 * swept[i] - c2 * swept_old[i] : 0.0;
  }

  template <int dim>
  void FluidSolver<dim>::update_volume_ratios()
  {
    // Once per change of the geometry or the time levels, not per face and PISO corrector.
    face_volume_ratio.resize(geometry.faces.size());
    const auto r1 = [this](const unsigned int c)
    { return V_levels.o[c] / geometry.cell_volume[c]; };
    const auto r2 = [this](const unsigned int c)
    { return V_levels.oo[c] / geometry.cell_volume[c]; };
    for_each_stored_face(geometry,
                         [&](const unsigned int f, const FaceGeometry<dim>& face) {
                           face_volume_ratio[f] = {{face_value(face, r1), face_value(face, r2)}};
                         });
  }

  template <int dim>
  void FluidSolver<dim>::check_finite(const char* field) const
  {
    double sum = 0;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      sum += std::abs(p.local_element(c));
      for (unsigned int j = 0; j < dim; ++j)
        sum += std::abs(u.components[j].local_element(c));
    }
    if (!std::isfinite(Utilities::MPI::sum(sum, geometry.comm())))
      throw std::runtime_error(
        "Fluid: " + std::string(field) + " is not finite at " + step_name() +
        (prm.transient ? "; reduce Fluid/Time step" : "; lower Fluid/Momentum relaxation") +
        " or check the boundary conditions");
  }

  template <int dim>
  std::string FluidSolver<dim>::step_name() const
  {
    return prm.transient ? clock.step_name() : "pseudo time step " + std::to_string(pseudo_step);
  }

  template <int dim>
  void FluidSolver<dim>::evaluate_body_force()
  {
    for (unsigned int j = 0; j < dim; ++j)
    {
      body_force_value[j].resize(geometry.n_owned_cells());
      for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
        body_force_value[j][c] =
          checked_value(body_force, geometry.centroid[c], j, "Fluid/Body force");
    }
  }

  template <int dim>
  void FluidSolver<dim>::begin_time_step()
  {
    body_force.set_time(clock.time());
    evaluate_body_force();
    conditions.set_time(clock.time());
    if (prm.transient && prm.flux_extrapolation && clock.step() > 1)
    {
      // The first outer loop linearises about the extrapolated state: convecting flux
      // F^n + (F^n - F^(n-1)), and velocity 2 u^n - u^(n-1) for the explicit parts (deferred
      // convection and non-orthogonal corrections, boundary values): their lag becomes O(dt^2).
      // The PISO correctors overwrite F and u with the new values.
      // The weights follow the step ratio (the clock's), so that a changed step extrapolates
      // to the right time: (2, -1) for equal steps.
      const auto [w1, w2] = clock.extrapolation_weights();
      for (unsigned int f = 0; f < F.size(); ++f)
        F[f] = F_levels.extrapolated({w1, w2}, f);
      for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
        u.set(c, u_levels.extrapolated({w1, w2}, c));
      u.update_ghost_values();
    }
    // The first pressure solve's start value: w1 p^n + w2 p^(n-1), p^(n-1) being the previous
    // step's p_start. Only a start value (set in solve_outer_iteration after the predicted
    // fluxes): the momentum predictor and the boundary values still see p^n.
    use_p_extrapolated =
      prm.transient && prm.pressure_extrapolation && clock.step() > 1 && p_start_is_previous_level;
    if (use_p_extrapolated)
    {
      const auto [w1, w2] = clock.extrapolation_weights();
      p_extrapolated = p;
      p_extrapolated.sadd(w1, w2, p_start);
    }
    u_start = u;
    p_start = p;
    F_start = F;
    grad_u_start = grad_u;
    grad_p_start = grad_p;
    solves_this_step = 0;
    step_correctors.clear();
  }

  template <int dim>
  void FluidSolver<dim>::solve_current_step()
  {
    if (!prm.transient)
    {
      solve_steady();
      return;
    }
    // A repeated solve of the same time step (a coupling iteration, with the mesh moved again)
    // starts from the same state as the first: PISO with a fixed number of correctors is then
    // a function of the mesh motion alone, which a quasi-Newton coupling needs (started from the
    // last iterate, each solve would also converge the step a little further, and the interface
    // residual would stall at that drift). The gradients belong to that state: the wall pressure
    // p_b = p_P + d . (grad p)_P is extrapolated with them, and with the last iterate's gradient
    // the answer would depend on the previous coupling iteration (in the elastic tube, where the
    // pressure swings by kPa between iterations, IQN-ILS stalled at residuals of 1e-2).
    if (solves_this_step++ > 0)
    {
      u = u_start;
      p = p_start;
      F = F_start;
      grad_u = grad_u_start;
      grad_p = grad_p_start;
      u.update_ghost_values();
      p.update_ghost_values();
    }
    solve_piso_step();
  }

  template <int dim>
  void FluidSolver<dim>::end_time_step()
  {
    // Relative change over the step, max|du| / U. The velocity scale U is max|u|; steady, at
    // least the speed the pressure differences drive, sqrt(max p - min p) (p kinematic,
    // Bernoulli): a fluid at rest under gravity has no speed but a pressure range, and its
    // change relative to max|u| would be round-off over round-off.
    // The error estimate of adaptive steps: the distance of u from its extrapolation to this
    // time, max |u - (w1 u^n + w2 u^(n-1))| / U (zero on the first step).
    const auto [w1, w2] = clock.extrapolation_weights();
    double max_du = 0, max_u = 0, max_p = -1e300, min_p = 1e300, max_e = 0;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      if (w2 != 0)
        max_e = std::max(max_e, (u[c] - w1 * u_levels.o[c] - w2 * u_levels.oo[c]).norm());
      max_du = std::max(max_du, (u[c] - u_levels.o[c]).norm());
      max_u = std::max(max_u, u[c].norm());
      max_p = std::max(max_p, p.local_element(c));
      min_p = std::min(min_p, p.local_element(c));
    }
    max_du = Utilities::MPI::max(max_du, geometry.comm());
    max_u = Utilities::MPI::max(max_u, geometry.comm());
    if (!prm.transient)
      max_u = std::max(max_u, std::sqrt(std::max(Utilities::MPI::max(max_p, geometry.comm()) -
                                                   Utilities::MPI::min(min_p, geometry.comm()),
                                                 0.0)));
    last_error = Utilities::MPI::max(max_e, geometry.comm()) / std::max(scale_U, 1e-300);
    shift_time_levels();
    p_start_is_previous_level = true;
    last_change = max_du / std::max(max_u, 1e-300);
  }

  template <int dim>
  void FluidSolver<dim>::checkpoint(MeshArchive<dim>& archive)
  {
    // Between two time steps u = u^n, F = F^n and V = V^n (end_time_step() shifted the levels);
    // the gradients and boundary values are those the next step's first iteration starts from.
    for (auto* field : {&u, &u_levels.o, &u_levels.oo, &grad_p})
      for (auto& component : field->components)
        archive.cells(component);
    for (auto& g : grad_u)
      for (auto& component : g.components)
        archive.cells(component);
    archive.cells(p);
    archive.cells(V_levels.o);
    archive.cells(V_levels.oo);
    for (auto* flux : {&F, &F_levels.o, &F_levels.oo, &swept_old})
      archive.faces(*flux, Parity::odd);
    archive.faces(S_levels.o, Parity::odd);
    archive.faces(S_levels.oo, Parity::odd);
    archive.faces(r_f_levels.o, Parity::even);
    archive.faces(r_f_levels.oo, Parity::even);
    archive.faces(boundary_u, Parity::even);
    archive.faces(boundary_p, Parity::even);
    if (archive.loading())
    {
      std::fill(swept.begin(), swept.end(), 0.0);
      for (auto* field : {&u, &u_levels.o, &u_levels.oo, &grad_p})
        field->update_ghost_values();
      for (auto& g : grad_u)
        g.update_ghost_values();
      p.update_ghost_values();
      update_volume_ratios();
      p_start_is_previous_level = false; // p^(n-1) is not kept
    }
  }

  template <int dim>
  void FluidSolver<dim>::add_output_fields(OutputFields<dim>& fields) const
  {
    fields.add_vector("u", [this](const unsigned int c) { return u[c]; });
    fields.add("p", [this](const unsigned int c) { return prm.rho * p.local_element(c); });
    fields.add(
      "vorticity",
      [this](const unsigned int c)
      {
        Tensor<2, dim> G; // G[i][j] = d u_j / d x_i
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int i = 0; i < dim; ++i)
            G[i][j] = grad_u[j][c][i];
        if constexpr (dim == 2)
          return G[0][1] - G[1][0];
        else
          return Tensor<1, 3>({G[1][2] - G[2][1], G[2][0] - G[0][2], G[0][1] - G[1][0]}).norm();
      });
  }

  template class FluidSolver<2>;
  template class FluidSolver<3>;
} // namespace fvfsi
