#include <deal.II/base/utilities.h>

#include <fvfsi/apps/fsi_scene.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/mesh/mesh_builder.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    std::vector<double> flatten(const std::vector<Tensor<1, dim>>& x)
    {
      std::vector<double> y;
      for (const auto& t : x)
        for (unsigned int d = 0; d < dim; ++d)
          y.push_back(t[d]);
      return y;
    }
    template <int dim>
    std::vector<Tensor<1, dim>> unflatten(const std::vector<double>& y)
    {
      std::vector<Tensor<1, dim>> x(y.size() / dim);
      for (unsigned int i = 0; i < x.size(); ++i)
        for (unsigned int d = 0; d < dim; ++d)
          x[i][d] = y[i * dim + d];
      return x;
    }
    std::vector<unsigned int> patch_ids(const MeshParameters& mesh, const std::vector<std::string>& names)
    {
      std::vector<unsigned int> ids;
      for (const auto& name : names)
        ids.push_back(mesh.patch_id(name));
      return ids;
    }
  } // namespace

  void FsiSceneParameters::declare(ParameterHandler& prm)
  {
    prm.enter_subsection("FSI");
    prm.add_parameter("Fluid interface", fluid_interface,
                      "Fluid patches (of `Mesh`) that touch the solid, comma separated: walls that "
                      "are also `Mesh motion/Moving patches` (the coupling sets their displacement).");
    prm.add_parameter("Solid interface", solid_interface,
                      "Solid patches (of `Solid mesh`) that touch the fluid, comma separated: "
                      "`Solid/External traction` patches (the coupling sets their traction).");
    prm.leave_subsection();
    coupling.declare(prm);
  }

  template <int dim>
  FsiScene<dim>::FsiScene(const MeshParameters& fluid_mesh, const FluidParameters& fluid_parameters,
                          const FluidSceneParameters& fluid_scene, const MeshParameters& solid_mesh,
                          const SolidParameters& solid_parameters,
                          const SolidSceneParameters& solid_scene,
                          const FsiSceneParameters& fsi_parameters, MPI_Comm comm,
                          const std::string& prm_directory, const std::string& output_directory)
    : comm(comm)
    , fluid_mesh_parameters(fluid_mesh)
    , solid_mesh_parameters(solid_mesh)
    , fluid_parameters(fluid_parameters)
    , fluid_scene_parameters(fluid_scene)
    , solid_parameters(solid_parameters)
    , solid_scene_parameters(solid_scene)
    , prm(fsi_parameters)
    , prm_directory(prm_directory)
    , output_directory(output_directory)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , fluid_tria(comm)
    , solid_tria(comm)
    , probes(solid_scene.probes, "Solid scene/Probes")
  {
    if (!fluid_parameters.transient)
      throw std::runtime_error("FSI: the fluid must be transient (Fluid/Transient = true)");
    if (fluid_scene.mesh_motion.type != "Laplace")
      throw std::runtime_error("FSI: the fluid mesh must follow the interface: set Mesh motion/Type = "
                               "Laplace and list the fluid interface patches in Mesh motion/Moving "
                               "patches");
    if (prm.fluid_interface.empty() || prm.solid_interface.empty())
      throw std::runtime_error("FSI: name the interface patches (FSI/Fluid interface and FSI/Solid "
                               "interface)");
    // One clock: the solid steps with the fluid's time step (a steady solid is quasi-static).
    this->solid_parameters.time_step = fluid_parameters.time_step;
    this->solid_parameters.end_time = fluid_parameters.end_time;
  }

  template <int dim>
  void FsiScene<dim>::make_grids()
  {
    make_mesh(fluid_mesh_parameters, fluid_tria, prm_directory);
    fluid_fv = std::make_unique<FVGeometry<dim>>(fluid_tria);
    fluid_reference_fv = std::make_unique<FVGeometry<dim>>(fluid_tria);
    fluid = std::make_unique<FluidSolver<dim>>(*fluid_fv, fluid_mesh_parameters, fluid_parameters);
    motion = std::make_unique<MeshMotion<dim>>(*fluid_reference_fv, fluid_mesh_parameters,
                                               fluid_scene_parameters.mesh_motion);

    make_mesh(solid_mesh_parameters, solid_tria, prm_directory);
    solid_fv = std::make_unique<FVGeometry<dim>>(solid_tria);
    solid = std::make_unique<SolidSolver<dim>>(*solid_fv, solid_mesh_parameters, solid_parameters);
    probes.locate(*solid_fv);

    // The interface, whole on every rank, and the maps between its two sides (computed once,
    // on the undeformed meshes, where the two sides coincide).
    fluid_zone = std::make_unique<InterfaceZone<dim>>(
      *fluid_fv, patch_ids(fluid_mesh_parameters, prm.fluid_interface), "FSI/Fluid interface");
    solid_zone = std::make_unique<InterfaceZone<dim>>(
      *solid_fv, patch_ids(solid_mesh_parameters, prm.solid_interface), "FSI/Solid interface");
    traction_map = std::make_unique<FaceInterpolation<dim>>(*fluid_zone, *solid_zone);
    displacement_map = std::make_unique<VertexProjection<dim>>(*solid_zone, *fluid_zone);
    acceleration = std::make_unique<CouplingAcceleration>(prm.coupling);
    d.assign(fluid_zone->n_points(), Tensor<1, dim>());
    d_old = d_older = d;
  }

  template <int dim>
  void FsiScene<dim>::move_fluid_mesh(const std::vector<Tensor<1, dim>>& displacement)
  {
    // Every interface vertex this rank's cells touch (ghost cells' too), found in the zone by
    // its reference position.
    std::vector<Tensor<1, dim>> vertex_displacement(fluid_fv->vertices().size());
    for (const auto& patch : prm.fluid_interface)
    {
      for (const unsigned int v : motion->patch_vertices(patch))
        vertex_displacement[v] = displacement[fluid_zone->point_index(fluid_reference_fv->vertices()[v])];
      motion->set_patch_displacement(patch, vertex_displacement);
    }
    const std::vector<Point<dim>> x = motion->vertex_positions(fluid->time());
    // Swept volumes from the positions at t^n (Eq. 3 holds over the whole time step, whatever
    // the iteration), then the geometry at the new positions.
    fluid_fv->reinit(vertices_old);
    const std::vector<double> swept = fluid_fv->swept_volumes(x);
    fluid_fv->reinit(x);
    for (const auto& cell : fluid_tria.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          cell->vertex(v) = x[cell->vertex_index(v)];
    double min_volume = std::numeric_limits<double>::max();
    for (unsigned int c = 0; c < fluid_fv->n_owned_cells(); ++c)
      min_volume = std::min(min_volume, fluid_fv->cell_volume[c]);
    if (!(Utilities::MPI::min(min_volume, comm) > 0))
      throw std::runtime_error("FSI: a fluid cell is inverted (volume <= 0): the interface "
                               "displacement is too large for this fluid mesh");
    fluid->move_mesh(swept);
  }

  template <int dim>
  void FsiScene<dim>::transfer_tractions()
  {
    std::vector<Tensor<1, dim>> fluid_traction(fluid_fv->faces.size());
    for (const auto& [f, i] : fluid_zone->local_faces())
      fluid_traction[f] = fluid->wall_traction(f);
    const auto on_solid = traction_map->interpolate(fluid_zone->gather_face_field(fluid_traction));
    std::vector<Tensor<1, dim>> solid_traction(solid_fv->faces.size());
    for (const auto& [f, j] : solid_zone->local_faces())
      solid_traction[f] = on_solid[j];
    solid->set_external_traction(solid_traction);
  }

  template <int dim>
  std::vector<Tensor<1, dim>> FsiScene<dim>::solid_interface_displacement() const
  {
    return displacement_map->interpolate(
      solid_zone->gather_point_field(solid->vertex_displacements()));
  }

  template <int dim>
  unsigned int FsiScene<dim>::solve_time_step()
  {
    fluid->begin_time_step();
    solid->begin_time_step();
    acceleration->new_time_step();
    vertices_old = fluid_fv->vertices();
    // Predictor: linear extrapolation of the interface displacement.
    const unsigned int step = fluid->step();
    for (unsigned int i = 0; i < d.size(); ++i)
      d[i] = step > 2 ? 2 * d_old[i] - d_older[i] : d_old[i];

    double residual = 0;
    for (unsigned int k = 1; k <= prm.coupling.max_iterations; ++k)
    {
      std::vector<double> next;
      try
      {
        move_fluid_mesh(d);
        fluid->solve_current_step();
        transfer_tractions();
        solid->solve_current_step();
        next = acceleration->next(flatten(d), flatten(solid_interface_displacement()));
      }
      catch (const std::exception& e)
      {
        throw std::runtime_error(
          "FSI: at time step " + std::to_string(step) + " (t = " + Utilities::to_string(fluid->time()) +
          " s), coupling iteration " + std::to_string(k) +
          (k > 1 ? " (relative interface residual before it: " + Utilities::to_string(residual) + ")"
                 : std::string()) +
          ": " + e.what() +
          (k > 2 ? "\n(a coupling iteration that diverges ends like this: use Coupling/Method = "
                   "IQN-ILS or Aitken, or a smaller Coupling/Relaxation)"
                 : std::string()));
      }
      residual = acceleration->relative_residual();
      if (!std::isfinite(residual))
        throw std::runtime_error("FSI: the interface residual is not finite at time step " +
                                 std::to_string(step) + ", coupling iteration " + std::to_string(k));
      if (residual <= prm.coupling.tolerance)
      {
        fluid->end_time_step();
        d_older = d_old;
        d_old = d;
        record_time_history(k, residual);
        return k;
      }
      d = unflatten<dim>(next);
    }
    throw std::runtime_error(
      "FSI: the coupling iterations did not converge at time step " + std::to_string(step) +
      " (t = " + Utilities::to_string(fluid->time()) + " s): relative interface residual " +
      Utilities::to_string(residual) + " after " + std::to_string(prm.coupling.max_iterations) +
      " iterations (Coupling/Method = IQN-ILS converges where relaxation does not; or raise "
      "Coupling/Max iterations)");
  }

  template <int dim>
  Tensor<1, dim> FsiScene<dim>::solid_probe(const unsigned int i) const
  {
    return probes.template evaluate<Tensor<1, dim>>(
      i, [this](const unsigned int c, const Tensor<1, dim>& dx) {
        return solid->displacement()[c] + dx * solid->cell_gradient(c);
      });
  }

  template <int dim>
  void FsiScene<dim>::record_time_history(const unsigned int iterations, const double residual)
  {
    Tensor<1, dim> force;
    for (const auto& patch : fluid_scene_parameters.force_patches)
      force += fluid->patch_force(fluid_mesh_parameters.patch_id(patch));
    std::vector<Tensor<1, dim>> u;
    for (unsigned int i = 0; i < probes.size(); ++i)
      u.push_back(solid_probe(i));
    history_t.push_back(fluid->time());
    history_drag.push_back(force[0]);
    history_lift.push_back(force[1]);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::ofstream out(output_directory + "/fsi_history.txt",
                      history_t.size() == 1 ? std::ios::trunc : std::ios::app);
    const char* axis[] = {"x", "y", "z"};
    if (history_t.size() == 1)
    {
      out << "# t coupling_iterations relative_residual drag lift";
      for (unsigned int i = 0; i < probes.size(); ++i)
        for (unsigned int c = 0; c < dim; ++c)
          out << " u" << axis[c] << "_" << probes.name(i);
      out << "\n";
    }
    out << std::setprecision(10) << fluid->time() << ' ' << iterations << ' ' << residual << ' '
        << force[0] << ' ' << force[1];
    for (const auto& x : u)
      for (unsigned int c = 0; c < dim; ++c)
        out << ' ' << x[c];
    out << "\n";
  }

  template <int dim>
  void FsiScene<dim>::output_results() const
  {
    const char* axis[] = {"x", "y", "z"};
    {
      std::vector<CellVector> fields(dim + 1, fluid_fv->make_cell_vector());
      for (unsigned int c = 0; c < fluid_fv->n_owned_cells(); ++c)
      {
        for (unsigned int j = 0; j < dim; ++j)
          fields[j].local_element(c) = fluid->velocity()[c][j];
        fields[dim].local_element(c) =
          fluid_parameters.rho * fluid->kinematic_pressure().local_element(c);
      }
      std::vector<std::pair<std::string, const CellVector*>> named;
      for (unsigned int j = 0; j < dim; ++j)
        named.emplace_back(std::string("u_") + axis[j], &fields[j]);
      named.emplace_back("p", &fields[dim]);
      for (auto& f : fields)
        f.update_ghost_values();
      VtuOutput<dim>(*fluid_fv, output_directory, "fluid").write(named, fluid->step(), fluid->time());
    }
    std::vector<CellVector> fields(dim, solid_fv->make_cell_vector());
    for (unsigned int c = 0; c < solid_fv->n_owned_cells(); ++c)
      for (unsigned int j = 0; j < dim; ++j)
        fields[j].local_element(c) = solid->displacement()[c][j];
    std::vector<std::pair<std::string, const CellVector*>> named;
    for (unsigned int j = 0; j < dim; ++j)
      named.emplace_back(std::string("u_") + axis[j], &fields[j]);
    for (auto& f : fields)
      f.update_ghost_values();
    VtuOutput<dim>(*solid_fv, output_directory, "solid").write(named, fluid->step(), fluid->time());
  }

  template <int dim>
  void FsiScene<dim>::run()
  {
    make_grids();
    pcout << "fvfsi: FSI " << dim << "D, fluid " << fluid_fv->n_global_cells() << " cells, solid "
          << solid_fv->n_global_cells() << " cells (" << solid_parameters.model << "), interface "
          << fluid_zone->n_faces() << " fluid / " << solid_zone->n_faces() << " solid faces, coupling "
          << prm.coupling.method << "\n";
    const unsigned int total =
      static_cast<unsigned int>(std::round(fluid_parameters.end_time / fluid_parameters.time_step));
    for (unsigned int step = 1; step <= total; ++step)
    {
      unsigned int iterations = 0;
      try
      {
        iterations = solve_time_step();
      }
      catch (...)
      {
        pcout << "fvfsi: FSI run stopped at time step " << step << "; fsi_history.txt holds every "
              << "converged time step before it (and the VTU files of Fluid scene/Output interval)\n";
        throw;
      }
      result.n_time_steps = step;
      result.total_coupling_iterations += iterations;
      result.max_coupling_iterations = std::max(result.max_coupling_iterations, iterations);
      if (step % fluid_scene_parameters.progress_interval == 0 || step == total)
        pcout << "fvfsi: FSI step " << step << "/" << total << ", t = " << fluid->time() << " s, "
              << iterations << " coupling iterations (mean "
              << double(result.total_coupling_iterations) / step << ")\n";
      if (fluid_scene_parameters.output_interval > 0 && step % fluid_scene_parameters.output_interval == 0)
        output_results();
    }
    if (fluid_scene_parameters.output_interval == 0)
      output_results();
  }

  template <int dim>
  void FsiScene<dim>::write_summary(Summary& summary) const
  {
    summary.set("n_cells", fluid_fv->n_global_cells() + solid_fv->n_global_cells());
    summary.set_result("fluid_cells", fluid_fv->n_global_cells());
    summary.set_result("solid_cells", solid_fv->n_global_cells());
    summary.set_result("time_steps", result.n_time_steps);
    summary.set_result("coupling_iterations", result.total_coupling_iterations);
    summary.set_result("max_coupling_iterations_per_step", result.max_coupling_iterations);
    if (!fluid_scene_parameters.force_patches.empty() && !history_drag.empty())
    {
      summary.set_result("drag", history_drag.back());
      summary.set_result("lift", history_lift.back());
    }
    for (unsigned int i = 0; i < probes.size(); ++i)
    {
      const Tensor<1, dim> u = solid_probe(i);
      summary.set_result("point_" + probes.name(i) + "_displacement",
                         std::vector<double>(&u[0], &u[0] + dim));
    }
  }

  template class FsiScene<2>;
  template class FsiScene<3>;
} // namespace fvfsi
