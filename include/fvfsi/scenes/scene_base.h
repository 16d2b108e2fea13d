#pragma once
// What the scenes share: the output entries of their `... scene` subsections, and the parts of a
// scene on one mesh (the solid and fluid scenes): where it runs and writes, its clock, its mesh and
// FV geometry, its probes, its VTU writer and its history file. A scene program (scenes/*_scene)
// adds its solver and says what to record.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <fvfsi/base/parsed_function.h>
#include <fvfsi/base/time_control.h>
#include <fvfsi/fv/point_probes.h>
#include <fvfsi/io/checkpoint.h>
#include <fvfsi/io/history_file.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_parameters.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fvfsi
{
  /// The entries of a `... scene` subsection that say what a run records.
  struct SceneOutputParameters
  {
    /// Named probe points, `A: 0.6, 0.2 | B: 0.2, 0.21`.
    std::string probes = "";
    /// Patches whose summed force is recorded, comma separated.
    std::vector<std::string> force_patches;
    /// Write VTU every this many time steps (0: only the final state).
    unsigned int output_interval = 0;
    /// Print a progress line every this many time steps.
    unsigned int progress_interval = 100;

    /// Declare the four entries in the current subsection; `probe_values` and `force` say what
    /// the probes and the force patches record (for the documentation).
    void declare_entries(dealii::ParameterHandler& prm, const std::string& probe_values,
                         const std::string& force);
  };

  /// Max and L2 norms of a cell error, max_P |e_P| and sqrt(sum_P V_P e_P^2).
  struct CellErrors
  {
    double max = 0, l2 = 0;
  };

  template <int dim>
  class SingleMeshScene
  {
  public:
    const FVGeometry<dim>& geometry() const { return *fv; }
    const TimeControl& time() const { return clock; }
    /// Write a checkpoint every `interval` time steps; continue from `restart_from`'s checkpoint.
    void set_checkpoints(const CheckpointParameters& parameters)
    {
      if (!parameters.initial_state_from.empty())
        throw std::runtime_error("Initial state from: only steady FSI runs (Scene = fsi, "
                                 "Fluid/Transient = false) start from an earlier run's state");
      checkpoints = parameters;
    }

  protected:
    /// `probe_parameter` names the probes' .prm entry in messages.
    SingleMeshScene(const MeshParameters& mesh_parameters, const TimeParameters& time,
                    const SceneOutputParameters& output, const std::string& probe_parameter,
                    MPI_Comm comm, const std::string& prm_directory,
                    const std::string& output_directory);

    /// The mesh of `Mesh` (restarting: the checkpoint's, at its reference positions), its FV
    /// geometry, and the VTU writer `<output_name>.pvd`.
    void make_mesh_and_writer(const std::string& output_name);
    /// Create `<output directory>/<file_name>` with the given columns (restarting: continue the
    /// earlier run's file and .pvd record).
    void open_history(const std::string& file_name, const std::vector<std::string>& columns);

    bool restarting() const { return !checkpoints.restart_from.empty(); }
    bool checkpoint_due(const unsigned int step) const
    {
      return checkpoints.interval > 0 && step % checkpoints.interval == 0;
    }
    /// Write a checkpoint (io/checkpoint.h): the mesh with what `mesh_state(MeshArchive&)` adds
    /// (the solvers' checkpoint()), and the clock with what `global_state(GlobalArchive&)` adds.
    template <typename MeshState, typename GlobalState>
    void write_checkpoint(const MeshState& mesh_state, const GlobalState& global_state);
    /// Restarting, once the solvers are made on the geometry: the same calls, reading.
    template <typename MeshState, typename GlobalState>
    void restore_checkpoint(const MeshState& mesh_state, const GlobalState& global_state);
    /// The same state kept in memory at the start of a time step...
    template <typename MeshState, typename GlobalState>
    void capture_step_start(const MeshState& mesh_state, const GlobalState& global_state);
    /// ...and the return to it after a failed step: `move_to(x)` moves the mesh back to the
    /// vertex positions x of the step's start (a moving mesh), then the states are read.
    template <typename MoveTo, typename MeshState, typename GlobalState>
    void return_to_step_start(const MoveTo& move_to, const MeshState& mesh_state,
                              const GlobalState& global_state);
    /// After a failed step: the last converged state (returned to) as VTU and a checkpoint, and
    /// the message saying so.
    template <typename Solver, typename MeshState, typename GlobalState>
    void write_last_converged_state(const Solver& solver, const std::string& scene,
                                    const MeshState& mesh_state, const GlobalState& global_state);
    /// True if a progress line or VTU output is due after time step `step` of `n_steps`.
    bool progress_due(unsigned int step, unsigned int n_steps) const;
    bool output_due(unsigned int step) const;
    /// The errors e = value(c, k) - exact_k(r_P, t) over the owned cells and the n_components
    /// components k of the expression `exact` (`parameter` names it in messages), collective.
    /// With `up_to_a_constant` the volume mean of e is subtracted first (a pressure without a
    /// level).
    template <typename Value>
    CellErrors cell_errors(const std::string& exact, const std::string& parameter,
                           unsigned int n_components, const Value& value,
                           bool up_to_a_constant = false) const;
    /// Write the output fields of `solver` (its add_output_fields()) as the clock's step.
    template <typename Solver>
    void write_output(const Solver& solver) const
    {
      OutputFields<dim> fields(*fv);
      solver.add_output_fields(fields);
      vtu_output->write(fields, clock.step(), clock.time());
    }

    MPI_Comm comm;
    MeshParameters mesh_parameters;
    SceneOutputParameters output_parameters;
    std::string prm_directory, output_directory;
    dealii::ConditionalOStream pcout;
    TimeControl clock;
    dealii::parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<FVGeometry<dim>> fv;
    PointProbes<dim> probes;
    std::unique_ptr<VtuOutput<dim>> vtu_output;
    std::unique_ptr<HistoryFile> history;
    std::string history_name; ///< its file name
    CheckpointParameters checkpoints;
    /// The vertex positions the mesh was made with; restarting, also those it had at the
    /// checkpoint, and its records until restore_checkpoint() reads them.
    std::vector<dealii::Point<dim>> reference_vertices, restart_vertices;
    std::unique_ptr<MeshArchive<dim>> restart_archive;
    std::unique_ptr<MeshArchive<dim>> step_start;
    std::stringstream step_start_global;

  private:
    /// The clock and what `global_state` adds, saved to step_start_global or loaded from it.
    template <typename GlobalState>
    void archive_step_start_global(bool loading, const GlobalState& global_state)
    {
      GlobalArchive global(step_start_global, loading);
      global& clock;
      global_state(global);
    }
  };

  template <int dim>
  template <typename MeshState, typename GlobalState>
  void SingleMeshScene<dim>::capture_step_start(const MeshState& mesh_state,
                                                const GlobalState& global_state)
  {
    capture_mesh<dim>(step_start, *fv, reference_vertices, mesh_state);
    archive_step_start_global(false, global_state);
  }

  template <int dim>
  template <typename MoveTo, typename MeshState, typename GlobalState>
  void SingleMeshScene<dim>::return_to_step_start(const MoveTo& move_to,
                                                  const MeshState& mesh_state,
                                                  const GlobalState& global_state)
  {
    move_to(rewind_mesh(*step_start, *fv));
    mesh_state(*step_start);
    archive_step_start_global(true, global_state);
  }

  template <int dim>
  template <typename Solver, typename MeshState, typename GlobalState>
  void SingleMeshScene<dim>::write_last_converged_state(const Solver& solver,
                                                        const std::string& scene,
                                                        const MeshState& mesh_state,
                                                        const GlobalState& global_state)
  {
    write_output(solver);
    write_checkpoint(mesh_state, global_state);
    pcout << "fvfsi: " << scene << " run stopped at time step " << clock.step() + 1
          << "; written: the last converged state (t = " << clock.time()
          << " s) as VTU and a checkpoint (continue with Restart from = " << output_directory
          << "); " << history_name << " holds every converged time step\n";
  }

  template <int dim>
  template <typename MeshState, typename GlobalState>
  void SingleMeshScene<dim>::write_checkpoint(const MeshState& mesh_state,
                                              const GlobalState& global_state)
  {
    const CheckpointFiles files(output_directory);
    files.begin_writing(comm);
    save_mesh<dim>(files, "mesh", *fv, reference_vertices, mesh_state);
    {
      GlobalArchive global(files.path("state", true), false, comm);
      global& clock;
      global_state(global);
    }
    save_output_state(files, {history->length(), {vtu_output->written()}}, comm);
    files.finish_writing(comm);
    pcout << "fvfsi: checkpoint at " << clock.step_name() << " in " << files.directory << "\n";
  }

  template <int dim>
  template <typename MeshState, typename GlobalState>
  void SingleMeshScene<dim>::restore_checkpoint(const MeshState& mesh_state,
                                                const GlobalState& global_state)
  {
    const CheckpointFiles files(checkpoints.restart_from);
    restart_archive->set_geometry(*fv);
    mesh_state(*restart_archive);
    restart_archive.reset();
    GlobalArchive global(files.path("state"), true, comm);
    global& clock;
    global_state(global);
    pcout << "fvfsi: restarted from " << files.directory << " at " << clock.step_name() << "\n";
  }

  template <int dim>
  template <typename Value>
  CellErrors SingleMeshScene<dim>::cell_errors(const std::string& exact,
                                               const std::string& parameter,
                                               const unsigned int n_components, const Value& value,
                                               const bool up_to_a_constant) const
  {
    dealii::FunctionParser<dim> f(n_components);
    initialize_function(f, exact, parameter);
    f.set_time(clock.time());
    // A non-finite or huge exact value is an input error; found on any rank, it stops all.
    std::string bad_value;
    const auto exact_value = [&](const unsigned int c, const unsigned int k)
    {
      try
      {
        return checked_value(f, fv->centroid[c], k, parameter);
      }
      catch (const std::exception& e)
      {
        bad_value = e.what();
        return 0.0;
      }
    };
    double offset = 0;
    if (up_to_a_constant)
    {
      double volume = 0;
      for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
        for (unsigned int k = 0; k < n_components; ++k)
        {
          offset += fv->cell_volume[c] * (value(c, k) - exact_value(c, k));
          volume += fv->cell_volume[c];
        }
      offset =
        dealii::Utilities::MPI::sum(offset, comm) / dealii::Utilities::MPI::sum(volume, comm);
    }
    CellErrors e;
    for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
      for (unsigned int k = 0; k < n_components; ++k)
      {
        const double error = value(c, k) - offset - exact_value(c, k);
        e.max = std::max(e.max, std::abs(error));
        e.l2 += fv->cell_volume[c] * error * error;
      }
    const std::vector<std::string> bad = dealii::Utilities::MPI::all_gather(comm, bad_value);
    for (const auto& message : bad)
      if (!message.empty())
        throw std::runtime_error(message);
    e.max = dealii::Utilities::MPI::max(e.max, comm);
    e.l2 = std::sqrt(dealii::Utilities::MPI::sum(e.l2, comm));
    return e;
  }
} // namespace fvfsi
