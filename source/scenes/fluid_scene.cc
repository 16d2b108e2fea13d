#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <fvfsi/base/parsed_function.h>
#include <fvfsi/io/progress.h>
#include <fvfsi/mesh/mesh_builder.h>
#include <fvfsi/scenes/fluid_scene.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  void FluidSceneParameters::declare(ParameterHandler& prm)
  {
    prm.enter_subsection("Fluid scene");
    declare_entries(prm,
                    "velocity [m/s] and pressure [Pa] (summary.json: point_<name>_velocity, "
                    "point_<name>_pressure; the points are fixed in space, also on a moving mesh)",
                    "fluid force (drag = x, lift = y)");
    prm.add_parameter("Exact velocity", exact_velocity,
                      "Exact u(x, y[, z], t) (dim expressions separated by `;`) for "
                      "results.max_velocity_error; empty: none.");
    prm.add_parameter("Exact pressure", exact_pressure,
                      "Exact p(x, y[, z], t) [Pa] for results.max_pressure_error; empty: none.");
    prm.add_parameter("Analysis window", analysis_window,
                      "Transient: mean, amplitude and frequency of drag and lift over the last "
                      "this many seconds (0: none).",
                      Patterns::Double(0));
    prm.leave_subsection();
    mesh_motion.declare(prm);
  }

  PeriodicStatistics periodic_statistics(const std::vector<double>& t, const std::vector<double>& q)
  {
    PeriodicStatistics s;
    if (q.size() < 3)
      return s;
    const auto [lo, hi] = std::minmax_element(q.begin(), q.end());
    s.mean = (*hi + *lo) / 2;
    s.amplitude = (*hi - *lo) / 2;
    // Up-crossings of the mean, linearly interpolated; frequency from the first and last.
    std::vector<double> crossings;
    for (unsigned int i = 1; i < q.size(); ++i)
      if (q[i - 1] < s.mean && q[i] >= s.mean)
        crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * (s.mean - q[i - 1]) / (q[i] - q[i - 1]));
    if (crossings.size() < 2)
    {
      s.mean = s.amplitude = s.frequency = std::numeric_limits<double>::quiet_NaN();
      return s;
    }
    s.n_periods = crossings.size() - 1;
    s.frequency = (crossings.size() - 1) / (crossings.back() - crossings.front());
    return s;
  }

  template <int dim>
  FluidScene<dim>::FluidScene(const MeshParameters& mesh_parameters,
                              const FluidParameters& fluid_parameters,
                              const FluidSceneParameters& scene_parameters,
                              const TimeParameters& time, MPI_Comm comm,
                              const std::string& prm_directory, const std::string& output_directory)
      : Base(mesh_parameters, time, scene_parameters, "Fluid scene/Probes", comm, prm_directory,
             output_directory),
        fluid_parameters(fluid_parameters), scene_parameters(scene_parameters)
  {
  }

  template <int dim>
  void FluidScene<dim>::make_grid()
  {
    this->make_mesh_and_writer("fluid");
    fluid = std::make_unique<FluidSolver<dim>>(*fv, mesh_parameters, fluid_parameters, clock);
    if (scene_parameters.mesh_motion.moves())
    {
      if (!fluid_parameters.transient)
        throw std::runtime_error(
          "Mesh motion/Type = " +
          selection_name(MeshMotionParameters::type_names, scene_parameters.mesh_motion.type) +
          " needs a transient flow (Fluid/Transient = true)");
      reference_fv = std::make_unique<FVGeometry<dim>>(triangulation);
      motion = std::make_unique<MeshMotion<dim>>(*reference_fv, mesh_parameters,
                                                 scene_parameters.mesh_motion, clock);
    }
    // The history: t, forces, diagnostics, then u and p at every probe.
    std::vector<std::string> columns = {"t", "drag", "lift", "courant", "continuity_error"};
    for (unsigned int i = 0; i < probes.size(); ++i)
    {
      for (const auto& c : vector_columns<dim>("u", "_" + probes.name(i)))
        columns.push_back(c);
      columns.push_back("p_" + probes.name(i));
    }
    columns.push_back("outer");      // outer (PIMPLE) loops of the step
    columns.push_back("correctors"); // PISO pressure correctors of the step (all outer loops)
    columns.push_back("dt");         // the step (Time/Adaptive changes it)
    this->open_history("fluid_history.txt", columns);
  }

  template <int dim>
  void FluidScene<dim>::checkpoint_state(MeshArchive<dim>& archive)
  {
    fluid->checkpoint(archive);
    if (motion)
      motion->checkpoint(archive);
  }

  template <int dim>
  void FluidScene<dim>::checkpoint_state(GlobalArchive& archive)
  {
    archive& history_t& history_drag& history_lift& result;
  }

  template <int dim>
  void FluidScene<dim>::restore()
  {
    if (!fluid_parameters.transient)
      throw std::runtime_error("Restart from applies to transient runs (Fluid/Transient = true)");
    if (motion)
    {
      const std::vector<Point<dim>> reference = fv->vertices();
      fvfsi::move_mesh(*fv, triangulation, reference, this->restart_vertices);
      fluid->move_mesh(std::vector<double>(fv->faces.size(), 0.0));
      probes.locate(*fv);
    }
    this->restore_checkpoint([this](MeshArchive<dim>& a) { checkpoint_state(a); },
                             [this](GlobalArchive& a) { checkpoint_state(a); });
  }

  template <int dim>
  void FluidScene<dim>::move_mesh()
  {
    const std::vector<Point<dim>> x = motion->vertex_positions();
    const std::vector<double> swept = fvfsi::move_mesh(*fv, triangulation, fv->vertices(), x);
    result.min_volume_ratio =
      std::min(result.min_volume_ratio, min_volume_ratio(*fv, *reference_fv, clock.time()));
    fluid->move_mesh(swept);
    probes.locate(*fv);
  }

  template <int dim>
  std::pair<Tensor<1, dim>, double> FluidScene<dim>::probe_values(const unsigned int i) const
  {
    return fluid->probe_values(probes, i);
  }

  template <int dim>
  Tensor<1, dim> FluidScene<dim>::body_force() const
  {
    return fluid->patches_force(
      mesh_parameters.patch_ids(scene_parameters.force_patches, "Fluid scene/Force patches"));
  }

  template <int dim>
  void FluidScene<dim>::record_time_history()
  {
    // One line per time step (collective: forces and diagnostics are MPI reductions).
    const Tensor<1, dim> force = body_force();
    final_probe_values.clear();
    for (unsigned int i = 0; i < probes.size(); ++i)
      final_probe_values.push_back(probe_values(i));
    history_t.push_back(clock.time());
    history_drag.push_back(force[0]);
    history_lift.push_back(force[1]);
    std::vector<double> line = {clock.time(), force[0], force[1], fluid->courant_number(),
                                fluid->continuity_error()};
    for (const auto& [u, p] : final_probe_values)
    {
      append(line, u);
      line.push_back(p);
    }
    line.push_back(fluid->outer_iterations_used());
    line.push_back(fluid->pressure_correctors_used());
    line.push_back(clock.time_step());
    history->write_line(line);
  }

  template <int dim>
  void FluidScene<dim>::compute_errors()
  {
    if (!scene_parameters.exact_velocity.empty())
    {
      const CellErrors e = this->cell_errors(
        scene_parameters.exact_velocity, "Fluid scene/Exact velocity", dim,
        [this](const unsigned int c, const unsigned int j) { return fluid->velocity()[c][j]; });
      result.max_velocity_error = e.max;
      result.l2_velocity_error = e.l2;
    }
    if (!scene_parameters.exact_pressure.empty())
    {
      // Without an outlet the pressure is known up to a constant: compare p - mean(p).
      const CellErrors e = this->cell_errors(
        scene_parameters.exact_pressure, "Fluid scene/Exact pressure", 1,
        [this](const unsigned int c, unsigned int)
        { return fluid_parameters.rho * fluid->kinematic_pressure().local_element(c); },
        !fluid->pressure_level_is_fixed());
      result.max_pressure_error = e.max;
      result.l2_pressure_error = e.l2;
    }
  }

  template <int dim>
  void FluidScene<dim>::run()
  {
    make_grid();
    if (this->restarting())
      restore();
    pcout << "fvfsi: fluid " << dim << "D, " << fv->n_global_cells() << " cells, "
          << (fluid_parameters.transient ? "transient (PISO, BDF2)" : "steady (pseudo-transient)")
          << (motion ? ", moving mesh" : "") << "\n";
    if (!fluid_parameters.transient)
    {
      if (this->checkpoints.interval > 0)
        throw std::runtime_error("Checkpoint interval applies to transient runs (Fluid/Transient "
                                 "= true)");
      fluid->begin_time_step();
      result.n_time_steps = fluid->solve_steady();
      record_time_history();
      pcout << "fvfsi: fluid steady solution after " << result.n_time_steps
            << " pseudo time steps\n";
      this->write_output(*fluid);
    }
    else
      run_transient();
    compute_errors();
    fluid->timer().print_summary();
    const auto& pressure = fluid->pressure_linear_solver();
    pcout << "fvfsi: fluid pressure: " << pressure.n_solves() << " linear solves, "
          << pressure.n_iterations() / std::max(1.0, double(pressure.n_solves()))
          << " iterations per solve\n";
  }

  template <int dim>
  void FluidScene<dim>::run_transient()
  {
    const auto mesh_state = [this](MeshArchive<dim>& a) { checkpoint_state(a); };
    const auto global_state = [this](GlobalArchive& a) { checkpoint_state(a); };
    Progress progress;
    progress.new_phase(clock.step()); // a restarted run: the time left from its own steps
    while (!clock.at_end())
    {
      const unsigned int step = clock.step() + 1;
      this->capture_step_start(mesh_state, global_state);
      try
      {
        clock.advance();
        if (motion)
          move_mesh();
        fluid->solve_time_step();
      }
      catch (...)
      {
        // Back to the last converged state (the mesh too), which is written.
        const auto move_to = [this](const std::vector<Point<dim>>& x)
        {
          if (!motion)
            return;
          const std::vector<Point<dim>> now = fv->vertices();
          fvfsi::move_mesh(*fv, triangulation, now, x);
          fluid->move_mesh(std::vector<double>(fv->faces.size(), 0.0));
          probes.locate(*fv);
        };
        this->return_to_step_start(move_to, mesh_state, global_state);
        this->write_last_converged_state(*fluid, "fluid", mesh_state, global_state);
        throw;
      }
      result.n_time_steps = step;
      record_time_history();
      // Adaptive steps: the next one from this one's Courant number or error estimate; the
      // total is then the count at the new dt (for the progress line).
      clock.adapt_time_step(fluid->courant_number(), fluid->step_error());
      const unsigned int total = clock.last_step();
      if (this->progress_due(step, total))
        pcout << "fvfsi: fluid step " << step << "/" << total << ", t = " << clock.time()
              << " s, Courant " << fluid->courant_number() << ", drag " << history_drag.back()
              << ", lift " << history_lift.back()
              << (motion ? ", min V/V_ref " + std::to_string(result.min_volume_ratio)
                         : std::string())
              << ", " << progress.elapsed_and_left(step, total) << "\n";
      if (this->output_due(step))
        this->write_output(*fluid);
      if (this->checkpoint_due(step))
        this->write_checkpoint(mesh_state, global_state);
    }
    if (scene_parameters.output_interval == 0)
      this->write_output(*fluid);
  }

  template <int dim>
  void FluidScene<dim>::write_summary(Summary& summary) const
  {
    summary.set("n_cells", fv->n_global_cells());
    summary.set_result("time_steps", result.n_time_steps);
    summary.set_result("continuity_error", fluid->continuity_error());
    if (fluid_parameters.transient) // the divergence guard's margin (Fluid/Velocity bound)
      summary.set_result("max_velocity_over_scale", fluid->largest_velocity_ratio());
    if (!scene_parameters.force_patches.empty() && !history_drag.empty()) // no steps: none
    {
      summary.set_result("drag", history_drag.back());
      summary.set_result("lift", history_lift.back());
    }
    if (motion)
      summary.set_result("min_cell_volume_ratio", result.min_volume_ratio);
    for (unsigned int i = 0; i < final_probe_values.size(); ++i) // none before the first step
    {
      const auto& [u, p] = final_probe_values[i];
      summary.set_result("point_" + probes.name(i) + "_velocity",
                         std::vector<double>(&u[0], &u[0] + dim));
      summary.set_result("point_" + probes.name(i) + "_pressure", p);
    }
    if (result.max_velocity_error >= 0)
    {
      summary.set_result("max_velocity_error", result.max_velocity_error);
      summary.set_result("l2_velocity_error", result.l2_velocity_error);
    }
    if (result.max_pressure_error >= 0)
    {
      summary.set_result("max_pressure_error", result.max_pressure_error);
      summary.set_result("l2_pressure_error", result.l2_pressure_error);
    }
    if (fluid_parameters.transient && scene_parameters.analysis_window > 0 && !history_t.empty())
    {
      std::vector<double> t, drag, lift;
      for (unsigned int i = 0; i < history_t.size(); ++i)
        if (history_t[i] >= clock.time() - scene_parameters.analysis_window - 1e-12)
        {
          t.push_back(history_t[i]);
          drag.push_back(history_drag[i]);
          lift.push_back(history_lift[i]);
        }
      const auto d = periodic_statistics(t, drag), l = periodic_statistics(t, lift);
      if (d.n_periods > 0 && l.n_periods > 0)
      {
        summary.set_result("drag_mean_amplitude_frequency", {d.mean, d.amplitude, d.frequency});
        summary.set_result("lift_mean_amplitude_frequency", {l.mean, l.amplitude, l.frequency});
      }
      else // no numbers rather than NaN (a JSON null) in summary.json
        summary.set_text_result(
          "periodic_statistics_note",
          "none: the last " + Utilities::to_string(scene_parameters.analysis_window) +
            " s (Fluid scene/Analysis window) hold no full period of drag or lift");
    }
  }

  template class FluidScene<2>;
  template class FluidScene<3>;
} // namespace fvfsi
