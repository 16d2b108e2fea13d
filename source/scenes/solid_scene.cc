#include <deal.II/base/utilities.h>

#include <fvfsi/base/parsed_function.h>
#include <fvfsi/fv/face_loop.h>
#include <fvfsi/io/progress.h>
#include <fvfsi/mesh/mesh_builder.h>
#include <fvfsi/scenes/solid_scene.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  void SolidSceneParameters::declare(ParameterHandler& prm)
  {
    prm.enter_subsection("Solid scene");
    declare_entries(prm, "displacements (summary.json: point_<name>_displacement)",
                    "force (sum of face forces)");
    prm.add_parameter("Exact displacement", exact_displacement,
                      "Exact u(x, y[, z]) (dim expressions separated by `;`) for the error norms; "
                      "empty: no errors.");
    prm.add_parameter("Exact stress", exact_stress,
                      "Exact Cauchy stress: 2D `sxx; syy; sxy`, 3D `sxx; syy; szz; sxy; syz; sxz`; "
                      "empty: no stress errors.");
    prm.add_parameter("Stress error patches", stress_error_patches,
                      "Patches on whose faces the max stress error is measured (summary.json: "
                      "max_<patch>_stress_error).");
    prm.leave_subsection();
  }

  template <int dim>
  SolidScene<dim>::SolidScene(const MeshParameters& mesh_parameters,
                              const SolidParameters& solid_parameters,
                              const SolidSceneParameters& scene_parameters,
                              const TimeParameters& time, MPI_Comm comm,
                              const std::string& prm_directory, const std::string& output_directory)
      : Base(mesh_parameters, time, scene_parameters, "Solid scene/Probes", comm, prm_directory,
             output_directory),
        solid_parameters(solid_parameters), scene_parameters(scene_parameters)
  {
  }

  template <int dim>
  void SolidScene<dim>::make_grid()
  {
    this->make_mesh_and_writer("solid");
    solid = std::make_unique<SolidSolver<dim>>(*fv, mesh_parameters, solid_parameters, clock);
    // The history: t, probe displacements, patch forces.
    std::vector<std::string> columns = {"t"};
    for (unsigned int i = 0; i < probes.size(); ++i)
      for (const auto& c : vector_columns<dim>("u", "_" + probes.name(i)))
        columns.push_back(c);
    for (const auto& patch : scene_parameters.force_patches)
      for (const auto& c : vector_columns<dim>("F", "_" + patch))
        columns.push_back(c);
    this->open_history("solid_history.txt", columns);
  }

  template <int dim>
  Tensor<1, dim> SolidScene<dim>::probe_displacement(const unsigned int i) const
  {
    return solid->probe_displacement(probes, i);
  }

  template <int dim>
  void SolidScene<dim>::record_time_history()
  {
    // One line per time step (collective: probes and forces are MPI reductions).
    std::vector<double> line = {clock.time()};
    for (unsigned int i = 0; i < probes.size(); ++i)
    {
      const Tensor<1, dim> u = probe_displacement(i);
      append(line, u);
    }
    for (const auto& patch : scene_parameters.force_patches)
    {
      const Tensor<1, dim> F =
        solid->patch_force(mesh_parameters.patch_id(patch, "Solid scene/Force patches"));
      append(line, F);
    }
    history->write_line(line);
  }

  template <int dim>
  void SolidScene<dim>::compute_errors()
  {
    if (!scene_parameters.exact_displacement.empty())
    {
      result.max_displacement_error =
        this
          ->cell_errors(scene_parameters.exact_displacement, "Solid scene/Exact displacement", dim,
                        [this](const unsigned int c, const unsigned int d)
                        { return solid->displacement()[c][d]; })
          .max;
    }
    if (!scene_parameters.exact_stress.empty())
    {
      constexpr unsigned int n = dim == 2 ? 3 : 6;
      const std::array<std::pair<unsigned int, unsigned int>, 6> index = {
        {{0, 0}, {1, 1}, {dim == 2 ? 0u : 2u, dim == 2 ? 1u : 2u}, {0, 1}, {1, 2}, {0, 2}}};
      FunctionParser<dim> exact(n);
      initialize_function(exact, scene_parameters.exact_stress, "Solid scene/Exact stress");
      for (const auto& patch : scene_parameters.stress_error_patches)
      {
        const unsigned int id = mesh_parameters.patch_id(patch, "Solid scene/Stress error patches");
        double max_error = 0;
        for_each_patch_face(*fv, id,
                            [&](const unsigned int f, const FaceGeometry<dim>& face)
                            {
                              const Tensor<2, dim> sigma = solid->face_stress(f);
                              for (unsigned int k = 0; k < n; ++k)
                                max_error = std::max(
                                  max_error, std::abs(sigma[index[k].first][index[k].second] -
                                                      exact.value(face.centre, k)));
                            });
        result.max_stress_error.emplace_back(patch, Utilities::MPI::max(max_error, comm));
      }
    }
    result.probe_displacement.clear();
    for (unsigned int i = 0; i < probes.size(); ++i)
    {
      const Tensor<1, dim> u = probe_displacement(i);
      Tensor<1, 3> u3;
      for (unsigned int d = 0; d < dim; ++d)
        u3[d] = u[d];
      result.probe_displacement.emplace_back(probes.name(i), u3);
    }
  }

  template <int dim>
  void SolidScene<dim>::run()
  {
    make_grid();
    pcout << "fvfsi: solid " << dim << "D, " << fv->n_global_cells() << " cells, "
          << selection_name(SolidParameters::model_names, solid_parameters.model) << ", variant "
          << selection_name(SolidParameters::variant_names, solid_parameters.variant) << "\n";
    const auto mesh_state = [this](MeshArchive<dim>& a) { solid->checkpoint(a); };
    const auto global_state = [this](GlobalArchive& a) { a& result; };
    if (!solid_parameters.transient && (this->restarting() || this->checkpoints.interval > 0))
      throw std::runtime_error("Checkpoint interval and Restart from apply to transient runs "
                               "(Solid/Transient = true)");
    if (this->restarting())
      this->restore_checkpoint(mesh_state, global_state);
    // Counted from the restored clock (its time and dt) on a restart. Steady: one solve (at
    // t = dt, for loads that depend on t).
    const unsigned int n_steps = solid_parameters.transient ? clock.last_step() : 1;
    Progress progress;
    progress.new_phase(clock.step()); // a restarted run: the time left from its own steps
    for (unsigned int step = clock.step() + 1; step <= n_steps; ++step)
    {
      if (solid_parameters.transient)
        this->capture_step_start(mesh_state, global_state);
      try
      {
        clock.advance();
        solid->solve_time_step();
      }
      catch (...)
      {
        // Transient: back to the last converged state, which is written.
        if (solid_parameters.transient)
        {
          this->return_to_step_start([](const std::vector<Point<dim>>&) {}, mesh_state,
                                     global_state);
          this->write_last_converged_state(*solid, "solid", mesh_state, global_state);
        }
        throw;
      }
      const unsigned int iterations = solid->outer_iterations();
      result.total_outer_iterations += iterations;
      result.n_time_steps = step;
      record_time_history();
      if (solid_parameters.transient && this->progress_due(step, n_steps))
        pcout << "fvfsi: solid step " << step << "/" << n_steps << ", t = " << clock.time()
              << " s, " << iterations << " outer iterations, "
              << progress.elapsed_and_left(step, n_steps) << "\n";
      if (this->output_due(step))
        this->write_output(*solid);
      if (this->checkpoint_due(step))
        this->write_checkpoint(mesh_state, global_state);
    }
    if (scene_parameters.output_interval == 0)
      this->write_output(*solid);
    compute_errors();
  }

  template <int dim>
  void SolidScene<dim>::write_summary(Summary& summary) const
  {
    summary.set("n_cells", fv->n_global_cells());
    if (result.max_displacement_error >= 0)
      summary.set_result("max_displacement_error", result.max_displacement_error);
    for (const auto& [patch, e] : result.max_stress_error)
      summary.set_result("max_" + patch + "_stress_error", e);
    for (const auto& [name, u] : result.probe_displacement)
      summary.set_result("point_" + name + "_displacement",
                         std::vector<double>(&u[0], &u[0] + dim));
    summary.set_result("outer_iterations", result.total_outer_iterations);
    summary.set_result("least_stretch", solid->least_stretch()); // 1: linear elasticity
    // The divergence guard's margin (Solid/Displacement bound).
    summary.set_result("max_displacement_over_scale", solid->largest_displacement_ratio());
    if (solid_parameters.algorithm == SolidParameters::Algorithm::coupled)
    {
      // outer_iterations are Newton iterations here
      summary.set_result("jacobian_assemblies", double(solid->jacobian_assemblies()));
      summary.set_result("residual_evaluations", double(solid->residual_evaluations()));
      summary.set_result("krylov_iterations", double(solid->krylov_iterations()));
    }
    summary.set_result("time_steps", result.n_time_steps);
  }

  template class SolidScene<2>;
  template class SolidScene<3>;
} // namespace fvfsi
