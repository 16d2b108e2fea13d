#include <fvfsi/mesh/mesh_builder.h>
#include <fvfsi/scenes/scene_base.h>

namespace fvfsi
{
  using namespace dealii;

  void SceneOutputParameters::declare_entries(ParameterHandler& prm,
                                              const std::string& probe_values,
                                              const std::string& force)
  {
    prm.add_parameter("Probes", probes,
                      "Named points whose " + probe_values +
                        " are recorded every time step in the history file and reported in "
                        "summary.json: `A: 0.6, 0.2 | B: 0.3, 0.21`.");
    prm.add_parameter("Force patches", force_patches,
                      "Patches whose summed " + force +
                        " is recorded [N, per unit depth in 2D], comma separated.");
    prm.add_parameter("Output interval", output_interval,
                      "Write VTU every this many time steps (0: only the final state).");
    prm.add_parameter("Progress interval", progress_interval,
                      "Print a progress line every this many time steps.", Patterns::Integer(1));
  }

  template <int dim>
  SingleMeshScene<dim>::SingleMeshScene(const MeshParameters& mesh_parameters,
                                        const TimeParameters& time,
                                        const SceneOutputParameters& output,
                                        const std::string& probe_parameter, MPI_Comm comm,
                                        const std::string& prm_directory,
                                        const std::string& output_directory)
      : comm(comm), mesh_parameters(mesh_parameters), output_parameters(output),
        prm_directory(prm_directory), output_directory(output_directory),
        pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0), clock(time),
        triangulation(comm), probes(output.probes, probe_parameter)
  {
  }

  template <int dim>
  void SingleMeshScene<dim>::make_mesh_and_writer(const std::string& output_name)
  {
    if (restarting())
    {
      const CheckpointFiles restart(checkpoints.restart_from);
      restart.check_readable("Restart from", comm);
      restart_archive =
        load_mesh(restart, "mesh", mesh_parameters, triangulation, prm_directory, restart_vertices);
    }
    else
      make_mesh(mesh_parameters, triangulation, prm_directory);
    fv = std::make_unique<FVGeometry<dim>>(triangulation);
    reference_vertices = fv->vertices();
    probes.locate(*fv);
    vtu_output = std::make_unique<VtuOutput<dim>>(*fv, output_directory, output_name);
  }

  template <int dim>
  void SingleMeshScene<dim>::open_history(const std::string& file_name,
                                          const std::vector<std::string>& columns)
  {
    history_name = file_name;
    if (!restarting())
    {
      history = std::make_unique<HistoryFile>(output_directory + "/" + file_name, columns, comm);
      return;
    }
    const OutputState earlier = load_output_state(CheckpointFiles(checkpoints.restart_from), comm);
    history = std::make_unique<HistoryFile>(output_directory + "/" + file_name, columns, comm,
                                            checkpoints.restart_from + "/" + file_name,
                                            earlier.history_length);
    vtu_output->continue_from(earlier.series.at(0), checkpoints.restart_from);
  }

  template <int dim>
  bool SingleMeshScene<dim>::progress_due(const unsigned int step, const unsigned int n_steps) const
  {
    return step % output_parameters.progress_interval == 0 || step == n_steps;
  }

  template <int dim>
  bool SingleMeshScene<dim>::output_due(const unsigned int step) const
  {
    return output_parameters.output_interval > 0 && step % output_parameters.output_interval == 0;
  }

  template class SingleMeshScene<2>;
  template class SingleMeshScene<3>;
} // namespace fvfsi
