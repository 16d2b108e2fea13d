#include <deal.II/base/utilities.h>

#include <fvfsi/apps/poisson.h> // initialize_function
#include <fvfsi/apps/solid_scene.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/mesh/mesh_builder.h>

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
    prm.add_parameter("Probes", probes,
                      "Named points whose displacement is recorded every time step and reported in "
                      "summary.json as point_<name>_displacement: `A: 0.6, 0.2 | B: 0.3, 0.21`.");
    prm.add_parameter("Force patches", force_patches,
                      "Patches whose total force (sum of face forces, per unit depth in 2D) is "
                      "recorded, comma separated.");
    prm.add_parameter("Exact displacement", exact_displacement,
                      "Exact u(x, y[, z]) (dim expressions separated by `;`) for the error norms; "
                      "empty: no errors.");
    prm.add_parameter("Exact stress", exact_stress,
                      "Exact Cauchy stress: 2D `sxx; syy; sxy`, 3D `sxx; syy; szz; sxy; syz; sxz`; "
                      "empty: no stress errors.");
    prm.add_parameter("Stress error patches", stress_error_patches,
                      "Patches on whose faces the max stress error is measured (summary.json: "
                      "max_<patch>_stress_error).");
    prm.add_parameter("Output interval", output_interval,
                      "Write VTU every this many time steps (0: only the final state).");
    prm.leave_subsection();
  }

  template <int dim>
  SolidScene<dim>::SolidScene(const MeshParameters& mesh_parameters, const SolidParameters& solid_parameters,
                              const SolidSceneParameters& scene_parameters, MPI_Comm comm,
                              const std::string& prm_directory, const std::string& output_directory)
    : comm(comm)
    , mesh_parameters(mesh_parameters)
    , solid_parameters(solid_parameters)
    , scene_parameters(scene_parameters)
    , prm_directory(prm_directory)
    , output_directory(output_directory)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , triangulation(comm)
    , probes(scene_parameters.probes, "Solid scene/Probes")
  {
  }

  template <int dim>
  void SolidScene<dim>::make_grid()
  {
    make_mesh(mesh_parameters, triangulation, prm_directory);
    fv = std::make_unique<FVGeometry<dim>>(triangulation);
    solid = std::make_unique<SolidSolver<dim>>(*fv, mesh_parameters, solid_parameters);
    probes.locate(*fv);
  }

  template <int dim>
  Tensor<1, dim> SolidScene<dim>::probe_displacement(const unsigned int i) const
  {
    return probes.template evaluate<Tensor<1, dim>>(
      i, [this](const unsigned int c, const Tensor<1, dim>& dx) {
        return solid->displacement()[c] + dx * solid->cell_gradient(c);
      });
  }

  template <int dim>
  void SolidScene<dim>::record_time_history()
  {
    // One line per time step: t, outer iterations, probe displacements, patch forces.
    std::ostringstream line;
    line << std::setprecision(10) << solid->time();
    for (unsigned int i = 0; i < probes.size(); ++i)
    {
      const Tensor<1, dim> u = probe_displacement(i);
      for (unsigned int d = 0; d < dim; ++d)
        line << ' ' << u[d];
    }
    for (const auto& patch : scene_parameters.force_patches)
    {
      const Tensor<1, dim> F = solid->patch_force(mesh_parameters.patch_id(patch));
      for (unsigned int d = 0; d < dim; ++d)
        line << ' ' << F[d];
    }
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    const bool first = history_file.empty();
    history_file = output_directory + "/solid_history.txt";
    std::ofstream out(history_file, first ? std::ios::trunc : std::ios::app);
    if (first)
    {
      out << "# t";
      const char* axis[] = {"x", "y", "z"};
      for (unsigned int i = 0; i < probes.size(); ++i)
        for (unsigned int d = 0; d < dim; ++d)
          out << " u" << axis[d] << "_" << probes.name(i);
      for (const auto& patch : scene_parameters.force_patches)
        for (unsigned int d = 0; d < dim; ++d)
          out << " F" << axis[d] << "_" << patch;
      out << "\n";
    }
    out << line.str() << "\n";
  }

  template <int dim>
  void SolidScene<dim>::compute_errors()
  {
    if (!scene_parameters.exact_displacement.empty())
    {
      FunctionParser<dim> exact(dim);
      initialize_function(exact, scene_parameters.exact_displacement, "Solid scene/Exact displacement");
      double max_error = 0;
      for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
        for (unsigned int d = 0; d < dim; ++d)
          max_error = std::max(max_error, std::abs(solid->displacement()[c][d] - exact.value(fv->centroid[c], d)));
      result.max_displacement_error = Utilities::MPI::max(max_error, comm);
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
        const unsigned int id = mesh_parameters.patch_id(patch);
        double max_error = 0;
        for (unsigned int f = 0; f < fv->faces.size(); ++f)
          if (fv->faces[f].kind == FaceKind::boundary && fv->faces[f].patch == id)
          {
            const Tensor<2, dim> sigma = solid->face_stress(f);
            for (unsigned int k = 0; k < n; ++k)
              max_error = std::max(max_error, std::abs(sigma[index[k].first][index[k].second] -
                                                       exact.value(fv->faces[f].centre, k)));
          }
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
  void SolidScene<dim>::output_results() const
  {
    // Displacement, Cauchy stress components and von Mises stress as cell data.
    std::vector<CellVector> fields(dim + dim * dim + 1, fv->make_cell_vector());
    for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
    {
      const Tensor<2, dim> s = solid->cell_stress(c);
      for (unsigned int d = 0; d < dim; ++d)
        fields[d].local_element(c) = solid->displacement()[c][d];
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          fields[dim + dim * i + j].local_element(c) = s[i][j];
      const Tensor<2, dim> dev = s - trace(s) / 3.0 * unit_symmetric_tensor<dim>();
      // 2D: the out-of-plane stress is not stored, so this is the in-plane von Mises measure.
      fields.back().local_element(c) = std::sqrt(1.5 * scalar_product(dev, dev));
    }
    std::vector<std::pair<std::string, const CellVector*>> named;
    const char* axis[] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      named.emplace_back(std::string("u_") + axis[d], &fields[d]);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        named.emplace_back(std::string("sigma_") + axis[i] + axis[j], &fields[dim + dim * i + j]);
    named.emplace_back("von_Mises", &fields.back());
    for (auto& f : fields)
      f.update_ghost_values();
    VtuOutput<dim>(*fv, output_directory, "solid").write(named, solid->step(), solid->time());
  }

  template <int dim>
  void SolidScene<dim>::run()
  {
    make_grid();
    pcout << "fvfsi: solid " << dim << "D, " << fv->n_global_cells() << " cells, "
          << solid_parameters.model << ", variant " << solid_parameters.variant << "\n";
    const unsigned int n_steps =
      solid_parameters.transient
        ? static_cast<unsigned int>(std::round(solid_parameters.end_time / solid_parameters.time_step))
        : 1;
    for (unsigned int step = 1; step <= n_steps; ++step)
    {
      const unsigned int iterations = solid->solve_time_step();
      result.total_outer_iterations += iterations;
      result.n_time_steps = step;
      record_time_history();
      if (solid_parameters.transient && (step % 10 == 0 || step == n_steps))
        pcout << "fvfsi: solid step " << step << "/" << n_steps << ", t = " << solid->time() << " s, "
              << iterations << " outer iterations\n";
      if (scene_parameters.output_interval > 0 && step % scene_parameters.output_interval == 0)
        output_results();
    }
    if (scene_parameters.output_interval == 0)
      output_results();
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
      summary.set_result("point_" + name + "_displacement", std::vector<double>(&u[0], &u[0] + dim));
    summary.set_result("outer_iterations", result.total_outer_iterations);
    summary.set_result("time_steps", result.n_time_steps);
  }

  template class SolidScene<2>;
  template class SolidScene<3>;
} // namespace fvfsi
