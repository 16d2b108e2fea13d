#include <deal.II/base/utilities.h>

#include <fvfsi/mesh/mesh_builder.h>
#include <fvfsi/scenes/fsi_scene.h>

#include <cmath>
#include <iomanip>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  FsiScene<dim>::FsiScene(const FsiSceneInput& input, MPI_Comm comm,
                          const std::string& prm_directory, const std::string& output_directory)
      : comm(comm), fluid_mesh_parameters(input.fluid_mesh),
        solid_mesh_parameters(input.solid_mesh), fluid_parameters(input.fluid),
        fluid_scene_parameters(input.fluid_scene), solid_parameters(input.solid),
        solid_scene_parameters(input.solid_scene), prm(input.fsi), prm_directory(prm_directory),
        output_directory(output_directory), steady(!input.fluid.transient),
        pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0),
        timer(comm, pcout, TimerOutput::never, TimerOutput::wall_times), clock(input.time),
        max_halvings(input.time.halvings), fluid_tria(comm), solid_tria(comm),
        probes(input.solid_scene.probes, "Solid scene/Probes"),
        fluid_probes(input.fluid_scene.probes, "Fluid scene/Probes")
  {
    // Transient fluid with a transient or quasi-static solid; or both steady (solve_steady()).
    if (steady && solid_parameters.transient)
      throw std::runtime_error("FSI: a steady fluid (Fluid/Transient = false) needs a steady "
                               "solid: set Solid/Transient = false");
    if (steady && prm.coupling.start_time > 0)
      throw std::runtime_error("FSI: Coupling/Start time has no meaning in a steady run "
                               "(Fluid/Transient = false): set it to 0");
    if (fluid_scene_parameters.mesh_motion.type != MeshMotionParameters::Type::laplace)
      throw std::runtime_error(
        "FSI: the fluid mesh must follow the interface: set Mesh motion/Type = "
        "Laplace and list the fluid interface patches in Mesh motion/Moving "
        "patches");
    for (unsigned int i = 0; i < fluid_probes.size(); ++i)
      for (unsigned int j = 0; j < probes.size(); ++j)
        if (fluid_probes.name(i) == probes.name(j))
          throw std::runtime_error("FSI: the probe name `" + probes.name(j) +
                                   "` is in both Fluid scene/Probes and Solid scene/Probes: "
                                   "name them apart (the history has one column per name)");
    if (prm.coupling.fluid_interface.empty() || prm.coupling.solid_interface.empty())
      throw std::runtime_error("FSI: name the interface patches (Coupling/Fluid interface and "
                               "Coupling/Solid interface)");
  }

  template <int dim>
  void FsiScene<dim>::make_grids()
  {
    // Restarting: the meshes as saved (refinement, partition for this number of ranks, vertex
    // positions) instead of the .prm's refinement; the fluid mesh at its reference positions
    // first (the interface maps are made there), moved later by restore_checkpoint().
    const CheckpointFiles restart(checkpoints.restart_from);
    if (!checkpoints.restart_from.empty())
    {
      restart.check_readable("Restart from", comm);
      fluid_restart = load_mesh(restart, "fluid_mesh", fluid_mesh_parameters, fluid_tria,
                                prm_directory, restart_vertices);
    }
    else
      make_mesh(fluid_mesh_parameters, fluid_tria, prm_directory);
    fluid_fv = std::make_unique<FVGeometry<dim>>(fluid_tria);
    fluid_reference_fv = std::make_unique<FVGeometry<dim>>(fluid_tria);
    fluid =
      std::make_unique<FluidSolver<dim>>(*fluid_fv, fluid_mesh_parameters, fluid_parameters, clock);
    motion = std::make_unique<MeshMotion<dim>>(*fluid_reference_fv, fluid_mesh_parameters,
                                               fluid_scene_parameters.mesh_motion, clock);

    // The solid's mesh never moves (total Lagrangian): the positions saved with it are its
    // reference ones, read only because every saved mesh has them.
    std::vector<Point<dim>> reference_positions;
    if (!checkpoints.restart_from.empty())
      solid_restart = load_mesh(restart, "solid_mesh", solid_mesh_parameters, solid_tria,
                                prm_directory, reference_positions);
    else
      make_mesh(solid_mesh_parameters, solid_tria, prm_directory);
    solid_fv = std::make_unique<FVGeometry<dim>>(solid_tria);
    solid =
      std::make_unique<SolidSolver<dim>>(*solid_fv, solid_mesh_parameters, solid_parameters, clock);
    probes.locate(*solid_fv);
    fluid_probes.locate(*fluid_fv);
  }

  template <int dim>
  void FsiScene<dim>::make_interface()
  {
    // The interface, whole on every rank, and the maps between its two sides (computed once,
    // on the undeformed meshes, where the two sides coincide).
    interface = std::make_unique<FsiInterface<dim>>(
      *fluid_fv,
      fluid_mesh_parameters.patch_ids(prm.coupling.fluid_interface, "Coupling/Fluid interface"),
      "Coupling/Fluid interface", *solid_fv,
      solid_mesh_parameters.patch_ids(prm.coupling.solid_interface, "Coupling/Solid interface"),
      "Coupling/Solid interface");
    coupling =
      std::make_unique<PartitionedCoupling>(prm.coupling, interface->n_values(), pcout, &timer);
  }

  template <int dim>
  void FsiScene<dim>::make_output()
  {
    fluid_output = std::make_unique<VtuOutput<dim>>(*fluid_fv, output_directory, "fluid");
    solid_output = std::make_unique<VtuOutput<dim>>(*solid_fv, output_directory, "solid");
    // Transient: one line per time step; steady: one per coupling iteration (its convergence).
    std::vector<std::string> columns =
      steady
        ? std::vector<std::string>{"coupling_iteration",
                                   "relative_residual",
                                   "fluid_pseudo_steps",
                                   "solid_outer_iterations",
                                   "drag",
                                   "lift"}
        : std::vector<std::string>{"t", "coupling_iterations", "relative_residual", "drag", "lift"};
    for (unsigned int i = 0; i < probes.size(); ++i)
      for (const auto& c : vector_columns<dim>("u", "_" + probes.name(i)))
        columns.push_back(c);
    if (!steady) // fluid velocity U and pressure p at the fluid probes
      for (unsigned int i = 0; i < fluid_probes.size(); ++i)
      {
        for (const auto& c : vector_columns<dim>("U", "_" + fluid_probes.name(i)))
          columns.push_back(c);
        columns.push_back("p_" + fluid_probes.name(i));
      }
    columns.push_back("min_volume_ratio"); // min over the fluid cells of V_P / V_P(reference)
    if (!steady)
    {
      columns.push_back("courant");    // the fluid's largest Courant number
      columns.push_back("outer");      // the fluid's outer (PIMPLE) loops per solve
      columns.push_back("correctors"); // the fluid's PISO pressure correctors per solve
      columns.push_back("dt"); // the time step of the line (Time step control, Time/Adaptive)
    }
    const std::string name = steady ? "/fsi_steady_history.txt" : "/fsi_history.txt";
    if (checkpoints.restart_from.empty())
      history = std::make_unique<HistoryFile>(output_directory + name, columns, comm);
    else
    {
      const OutputState earlier =
        load_output_state(CheckpointFiles(checkpoints.restart_from), comm);
      history =
        std::make_unique<HistoryFile>(output_directory + name, columns, comm,
                                      checkpoints.restart_from + name, earlier.history_length);
      fluid_output->continue_from(earlier.series.at(0), checkpoints.restart_from);
      solid_output->continue_from(earlier.series.at(1), checkpoints.restart_from);
    }
  }

  template <int dim>
  void FsiScene<dim>::move_fluid_mesh(const InterfaceVector& displacement)
  {
    {
      TimerOutput::Scope scope(timer, "mesh motion");
      // Every interface vertex this rank's cells touch (ghost cells' too), found in the zone by
      // its reference position.
      std::vector<Tensor<1, dim>> vertex_displacement(fluid_fv->vertices().size());
      for (const auto& patch : prm.coupling.fluid_interface)
      {
        for (const unsigned int v : motion->patch_vertices(patch))
          vertex_displacement[v] = point_value<dim>(
            displacement, interface->fluid_side().point_index(fluid_reference_fv->vertices()[v]));
        motion->set_patch_displacement(patch, vertex_displacement);
      }
    }
    const std::vector<Point<dim>> x = [&]
    {
      TimerOutput::Scope scope(timer, "mesh motion");
      return motion->vertex_positions();
    }();
    TimerOutput::Scope scope(timer, "geometry");
    // Swept volumes from the positions at t^n (Eq. 3 holds over the whole time step, whatever the
    // iteration), then the geometry once, at the new positions.
    const std::vector<double> swept = move_mesh(*fluid_fv, fluid_tria, vertices_old, x);
    volume_ratio = min_volume_ratio(*fluid_fv, *fluid_reference_fv, clock.time());
    result.min_volume_ratio = std::min(result.min_volume_ratio, volume_ratio);
    fluid->move_mesh(swept);
  }

  template <int dim>
  void FsiScene<dim>::transfer_tractions()
  {
    TimerOutput::Scope scope(timer, "traction transfer");
    solid->set_external_traction(interface->tractions_to_solid(
      [this](const unsigned int f) { return fluid->wall_traction(f); }));
  }

  template <int dim>
  InterfaceVector FsiScene<dim>::solid_interface_displacement() const
  {
    TimerOutput::Scope scope(timer, "displacement transfer");
    if (prm.coupling.face_average_displacement)
      // The boundary-face displacements the fluid traction acts on, averaged to the vertices;
      // on the rim of the interface (a clamped end) the vertex values.
      return interface->displacements_to_fluid([this](const unsigned int f)
                                               { return solid->boundary_displacement(f); },
                                               solid->vertex_displacements());
    return interface->displacements_to_fluid(solid->vertex_displacements());
  }

  template <int dim>
  InterfaceVector FsiScene<dim>::coupling_iteration(const InterfaceVector& displacement)
  {
    move_fluid_mesh(displacement); // 2a: the fluid mesh follows d
    {
      TimerOutput::Scope scope(timer, "fluid");
      fluid->solve_current_step(); // 2b
    }
    transfer_tractions(); // 2c: Eqs 32-33
    {
      TimerOutput::Scope scope(timer, "solid");
      solid->solve_current_step(); // 2d
      result.solid_outer_iterations += solid->outer_iterations();
    }
    return solid_interface_displacement(); // 2e: d~ (section 3.5.2)
  }

  template <int dim>
  unsigned int FsiScene<dim>::solve_time_step()
  {
    // 1: the new time level, and the predictor: linear extrapolation of d.
    clock.advance();
    if (clock.time() <= prm.coupling.start_time + 1e-9 * clock.time_step())
    {
      // Before the coupling starts: the fluid alone on the fixed mesh, the solid at rest (its
      // time levels stay zero, so the first coupled step starts it from rest).
      TimerOutput::Scope scope(timer, "fluid");
      fluid->solve_time_step();
      record_time_history(0, 0);
      return 0;
    }
    fluid->begin_time_step();
    solid->begin_time_step();
    vertices_old = fluid_fv->vertices();
    coupling->begin_time_step(clock);
    const unsigned int k = converge_interface(); // 2
    // 3: accept the step.
    fluid->end_time_step();
    solid->end_time_step();
    coupling->end_time_step();
    record_time_history(k, coupling->relative_residual());
    return k;
  }

  template <int dim>
  unsigned int FsiScene<dim>::converge_interface()
  {
    const std::string impulsive_start_hint =
      !steady && result.n_coupled_steps == 0
        ? "\n(the first coupled time step: if the flow starts impulsively, let it develop on the "
          "fixed mesh first, Coupling/Start time)"
        : "";
    PartitionedCoupling::IterationObserver observer;
    if (steady) // a line of the steady history per iteration, and the iteration limit
      observer = [this](const unsigned int k, const double residual)
      {
        record_steady_iteration(k, residual);
        return clock.step_limit_reached(k);
      };
    return coupling->converge([this](const InterfaceVector& d) { return coupling_iteration(d); },
                              step_name(), impulsive_start_hint, observer);
  }

  template <int dim>
  std::string FsiScene<dim>::step_name() const
  {
    return steady ? std::string("the steady coupled solve") : clock.step_name();
  }

  template <int dim>
  Tensor<1, dim> FsiScene<dim>::fluid_force() const
  {
    return fluid->patches_force(fluid_mesh_parameters.patch_ids(
      fluid_scene_parameters.force_patches, "Fluid scene/Force patches"));
  }

  template <int dim>
  Tensor<1, dim> FsiScene<dim>::solid_probe(const unsigned int i) const
  {
    return solid->probe_displacement(probes, i);
  }

  template <int dim>
  void FsiScene<dim>::record_time_history(const unsigned int iterations, const double residual)
  {
    const Tensor<1, dim> force = fluid_force();
    last_force = force;
    std::vector<double> line = {clock.time(), double(iterations), residual, force[0], force[1]};
    for (unsigned int i = 0; i < probes.size(); ++i)
    {
      const Tensor<1, dim> u = solid_probe(i);
      append(line, u);
    }
    append_fluid_probes(line);
    line.push_back(volume_ratio);
    line.push_back(fluid->courant_number());
    line.push_back(fluid->outer_iterations_used());
    line.push_back(fluid->pressure_correctors_used());
    line.push_back(clock.time_step());
    history->write_line(line);
  }

  template <int dim>
  void FsiScene<dim>::append_fluid_probes(std::vector<double>& line)
  {
    if (fluid_probes.size() == 0)
      return;
    fluid_probes.locate(*fluid_fv); // the cells holding the points move with the mesh
    for (unsigned int i = 0; i < fluid_probes.size(); ++i)
    {
      const auto [velocity, pressure] = fluid->probe_values(fluid_probes, i);
      append(line, velocity);
      line.push_back(pressure);
    }
  }

  template <int dim>
  void FsiScene<dim>::output_results() const
  {
    OutputFields<dim> fluid_fields(*fluid_fv), solid_fields(*solid_fv);
    fluid->add_output_fields(fluid_fields);
    solid->add_output_fields(solid_fields);
    fluid_output->write(fluid_fields, clock.step(), clock.time());
    solid_output->write(solid_fields, clock.step(), clock.time());
  }

  template <int dim>
  void FsiScene<dim>::run()
  {
    if (!steady && !checkpoints.initial_state_from.empty())
      throw std::runtime_error("FSI: Initial state from applies to steady runs "
                               "(Fluid/Transient = false); a transient run continues an earlier "
                               "one with Restart from");
    make_grids();
    make_interface();
    if (!checkpoints.restart_from.empty())
      restore_checkpoint();
    make_output();
    print_set_up();
    if (steady)
      run_steady(); // fsi_scene_steady.cc
    else
      run_transient(); // fsi_scene_time_loop.cc
    timer.print_summary();
    if (!steady)
      print_result();
  }

  template <int dim>
  void FsiScene<dim>::print_set_up() const
  {
    pcout << "fvfsi: FSI " << dim << "D, fluid " << fluid_fv->n_global_cells() << " cells, solid "
          << solid_fv->n_global_cells() << " cells ("
          << selection_name(SolidParameters::model_names, solid_parameters.model) << "), interface "
          << interface->fluid_side().n_faces() << " fluid / " << interface->solid_side().n_faces()
          << " solid faces, coupling " << prm.coupling.method;
    if (!steady && prm.coupling.start_time > 0)
      pcout << " from Coupling/Start time = " << prm.coupling.start_time
            << " s (before it the fluid runs alone on the fixed mesh)";
    pcout << "\n";
    const auto [least, most] = interface->coverage_range();
    pcout << "fvfsi: interface: the fluid faces cover each solid face " << least << " to " << most
          << " times (1 where the sides match), the fluid points lie within "
          << interface->max_gap() << " m of the solid faces\n";
  }

  template <int dim>
  void FsiScene<dim>::print_result() const
  {
    // The key figures of the last time step (also in summary.json), for the log.
    pcout << "fvfsi: FSI result at t = " << clock.time() << " s:";
    for (unsigned int i = 0; i < probes.size(); ++i)
    {
      const Tensor<1, dim> u = solid_probe(i);
      pcout << " u(" << probes.name(i) << ") = (";
      for (unsigned int d = 0; d < dim; ++d)
        pcout << (d ? ", " : "") << u[d];
      pcout << ") m;";
    }
    if (last_force)
      pcout << " drag " << (*last_force)[0] << " N/m, lift " << (*last_force)[1] << " N/m;";
    pcout << " " << std::setprecision(3) << result.mean_coupling_iterations()
          << " coupling iterations per coupled step (max " << result.max_coupling_iterations
          << ")\n"
          << std::setprecision(6);
    if (result.n_coupled_steps == 0 && prm.coupling.start_time > 0)
      pcout << "fvfsi: the run ended before Coupling/Start time = " << prm.coupling.start_time
            << " s: the fluid ran alone on the fixed mesh, the solid stayed at rest\n";
  }

  template <int dim>
  void FsiScene<dim>::write_summary(Summary& summary) const
  {
    summary.set("n_cells", fluid_fv->n_global_cells() + solid_fv->n_global_cells());
    summary.set_result("fluid_cells", fluid_fv->n_global_cells());
    summary.set_result("solid_cells", solid_fv->n_global_cells());
    summary.set_result("time_steps", result.n_time_steps);
    summary.set_result("coupling_iterations", result.total_coupling_iterations);
    summary.set_result("coupled_time_steps", result.n_coupled_steps);
    summary.set_result("mean_coupling_iterations_per_step", result.mean_coupling_iterations());
    summary.set_result("max_coupling_iterations_per_step", result.max_coupling_iterations);
    summary.set_result("min_cell_volume_ratio", result.min_volume_ratio);
    if (!steady) // the divergence guards' margins (Fluid/Velocity bound, Solid/Displacement bound)
    {
      summary.set_result("max_velocity_over_scale", fluid->largest_velocity_ratio());
      summary.set_result("max_displacement_over_scale", solid->largest_displacement_ratio());
    }
    summary.set_result("solid_outer_iterations", result.solid_outer_iterations);
    summary.set_result("solid_least_stretch", solid->least_stretch()); // 1: linear elasticity
    summary.set_result("coupled_wall_seconds", result.coupled_wall_seconds);
    const auto [least, most] = interface->coverage_range();
    summary.set_result("interface_coverage_min", least);
    summary.set_result("interface_coverage_max", most);
    summary.set_result("interface_max_gap", interface->max_gap());
    // The global interface zones' traffic: the bytes every rank receives from the others in the
    // two gathers of a coupling iteration, summed over the ranks (0 on one rank).
    const double bytes = Utilities::MPI::sum(double(interface->received_bytes()), comm);
    summary.set_result(
      "interface_bytes_per_coupling_iteration",
      result.total_coupling_iterations > 0 ? bytes / result.total_coupling_iterations : 0.0);
    if (!fluid_scene_parameters.force_patches.empty() && last_force)
    {
      summary.set_result("drag", (*last_force)[0]);
      summary.set_result("lift", (*last_force)[1]);
    }
    if (steady)
      summary.set_result("fluid_pseudo_steps", fluid->pseudo_steps());
    for (unsigned int i = 0; i < probes.size(); ++i)
    {
      const Tensor<1, dim> u = solid_probe(i);
      summary.set_result("point_" + probes.name(i) + "_displacement",
                         std::vector<double>(&u[0], &u[0] + dim));
    }
    for (unsigned int i = 0; i < fluid_probes.size(); ++i) // located by the last record
    {
      const auto [velocity, pressure] = fluid->probe_values(fluid_probes, i);
      summary.set_result("point_" + fluid_probes.name(i) + "_velocity",
                         std::vector<double>(&velocity[0], &velocity[0] + dim));
      summary.set_result("point_" + fluid_probes.name(i) + "_pressure", pressure);
    }
    for (const auto& [section, seconds] : timer.get_summary_data(TimerOutput::total_wall_time))
      summary.set_timing(section, seconds);
    for (const auto& [name, solver] :
         {std::pair{"fluid_pressure", &fluid->pressure_linear_solver()},
          std::pair{"fluid_momentum", &fluid->momentum_linear_solver()}})
    {
      summary.set_result(std::string(name) + "_linear_solves", double(solver->n_solves()));
      summary.set_result(std::string(name) + "_iterations_per_solve",
                         solver->n_iterations() / std::max(1.0, double(solver->n_solves())));
    }
    const auto [solid_solves, solid_iterations] = solid->linear_solves_and_iterations();
    summary.set_result("solid_linear_solves", double(solid_solves));
    summary.set_result("solid_iterations_per_solve",
                       solid_iterations / std::max(1.0, double(solid_solves)));
    // The fluid's own sections (pressure solve, momentum solve, ...) inside "fluid".
    for (const auto& [section, seconds] :
         fluid->timer().get_summary_data(TimerOutput::total_wall_time))
      summary.set_timing("fluid: " + section, seconds);
  }

  template class FsiScene<2>;
  template class FsiScene<3>;
} // namespace fvfsi
