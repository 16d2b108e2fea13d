#pragma once
// The fluid-structure interaction scene: the partitioned, strongly coupled Dirichlet-Neumann
// procedure of the paper's Algorithm 1. Per time step:
//
//   1. the clock advances; both solvers move to the new time level; the interface displacement d
//      is predicted (linear extrapolation);
//   2. iterate: move the fluid mesh (Laplace mesh motion with the interface vertices at d), solve
//      the fluid, transfer its wall tractions to the solid faces (Eqs 32-33), solve the solid,
//      transfer its vertex displacements to the fluid interface vertices (3.5.2), and update d
//      from the residual r = d~ - d (Eq. 30) by fixed relaxation, Aitken, IQN-ILS or IQN-IMVJ,
//      until |r| <= tolerance |d~| (or, optionally, |r| <= reduction x the step's largest |r|);
//   3. both solvers accept the step.
// Steady (Fluid/Transient = Solid/Transient = false): step 2 alone converges the steady coupled
// state, each iteration solving the steady fluid and the static solid (solve_steady()).
// solve_time_step() in fsi_scene.cc is this list, line by line.
//
// The fluid and the solid have their own meshes (`Mesh` and `Solid mesh`), decomposed
// independently over the same ranks; the coupling sees only the two interfaces, gathered whole on
// every rank (InterfaceZone). Neither solver knows about the other; all three read one clock.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>

#include <fvfsi/ale/mesh_motion.h>
#include <fvfsi/base/time_control.h>
#include <fvfsi/coupling/fsi_interface.h>
#include <fvfsi/coupling/partitioned_coupling.h>
#include <fvfsi/fluid/fluid_solver.h>
#include <fvfsi/fv/point_probes.h>
#include <fvfsi/io/checkpoint.h>
#include <fvfsi/io/history_file.h>
#include <fvfsi/io/summary.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/scenes/fluid_scene.h>
#include <fvfsi/scenes/solid_scene.h>
#include <fvfsi/solid/solid_solver.h>

#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fvfsi
{
  class Progress;

  /// The FSI scene's own parameters: the coupling (`subsection Coupling`: interface patches and
  /// iteration).
  struct FsiSceneParameters
  {
    CouplingParameters coupling;
    void declare(dealii::ParameterHandler& prm) { coupling.declare(prm); }
  };

  struct FsiResults
  {
    unsigned int n_time_steps = 0;
    unsigned int n_coupled_steps = 0; ///< from Coupling/Start time on
    unsigned int total_coupling_iterations = 0, max_coupling_iterations = 0;
    unsigned long solid_outer_iterations = 0; ///< over all coupling iterations
    double mean_coupling_iterations() const
    {
      return n_coupled_steps == 0 ? 0 : double(total_coupling_iterations) / n_coupled_steps;
    }
    double min_volume_ratio = 1;     ///< min over cells and steps of V_P / V_P(reference), fluid
    double coupled_wall_seconds = 0; ///< wall time of the coupled time steps [s]
    template <class Archive>
    void serialize(Archive& ar, const unsigned int /*version*/)
    {
      ar& n_time_steps& n_coupled_steps& total_coupling_iterations& max_coupling_iterations&
        solid_outer_iterations& min_volume_ratio& coupled_wall_seconds;
    }
  };

  /// The parameters an FSI scene reads.
  struct FsiSceneInput
  {
    const MeshParameters &fluid_mesh, &solid_mesh;
    const FluidParameters& fluid;
    const FluidSceneParameters& fluid_scene;
    const SolidParameters& solid;
    const SolidSceneParameters& solid_scene;
    const FsiSceneParameters& fsi;
    const TimeParameters& time;
  };

  template <int dim>
  class FsiScene
  {
  public:
    FsiScene(const FsiSceneInput& input, MPI_Comm comm, const std::string& prm_directory,
             const std::string& output_directory);

    /// Write a checkpoint every `interval` time steps; continue from `restart_from`'s checkpoint.
    void set_checkpoints(const CheckpointParameters& parameters) { checkpoints = parameters; }
    void run();
    void write_summary(Summary& summary) const;
    const FsiResults& results() const { return result; }
    const SolidSolver<dim>& solid_solver() const { return *solid; }
    const FluidSolver<dim>& fluid_solver() const { return *fluid; }
    const TimeControl& time() const { return clock; }
    /// The interface displacement at the fluid interface vertices (zone numbering) [m].
    const InterfaceVector& interface_displacement() const { return coupling->displacement(); }
    /// The displacement at solid probe i [m] (collective).
    dealii::Tensor<1, dim> solid_probe(unsigned int i) const;
    /// Print the probes' displacements, the forces and the coupling iterations of the run.
    void print_result() const;
    const PointProbes<dim>& solid_probes() const { return probes; }

  private:
    /// The meshes (from the checkpoint when restarting), their geometry and the solvers.
    void make_grids();
    void make_interface();
    void make_output();
    /// The meshes' sizes, the interface and the coupling method, for the log.
    void print_set_up() const;
    /// Steady: the coupled steady state, its output and state files (fsi_scene_steady.cc).
    void run_steady();
    /// Transient: the time loop (fsi_scene_time_loop.cc).
    void run_transient();
    /// A failed time step: back to its start, then true with the time step halved (Time/Time
    /// step control), or, the halvings spent, false with the last converged state written.
    bool halve_time_step(unsigned int step, unsigned int& halvings, const std::exception& failure);
    /// Count a converged time step and its coupling iterations in the results.
    void count_time_step(unsigned int step, unsigned int iterations, double wall_seconds,
                         Progress& progress);
    /// The step that reaches Coupling/Start time if dt stays what it is now (at most `total`).
    unsigned int last_fluid_alone_step(unsigned int total) const;
    /// The progress line of a time step (every Fluid scene/Progress interval steps).
    void print_progress(unsigned int step, unsigned int total, unsigned int iterations,
                        unsigned int last_fluid_alone_step, const Progress& progress) const;
    /// Checkpoints (io/checkpoint.h): the fluid mesh with its reference and current vertex
    /// positions, the fluid, mesh-motion and solid states, and the clock, the interface
    /// displacements, the coupling's columns, the results so far and the output records.
    void write_checkpoint();
    /// Restarting: the states of the solvers, after make_grids() and make_interface().
    void restore_checkpoint();
    /// The fluid's and the mesh motion's part of a checkpoint.
    void fluid_state(MeshArchive<dim>& archive);
    /// The state at the start of a time step, kept in memory (the checkpoint's content), and the
    /// return to it after a failed step.
    void capture_step_start();
    void return_to_step_start();
    /// Steady: write the state a run on another mesh can start from (fluid_state.txt,
    /// interface_state.txt in the output directory; fsi_scene_steady.cc).
    void write_state() const;
    /// Start from the state an earlier steady run wrote into `directory` (mesh sequencing).
    void start_from_state(const std::string& directory);
    /// The part of a checkpoint every rank holds alike.
    template <class Archive>
    void global_state(Archive& archive);
    /// One time step of Algorithm 1; returns the coupling iterations.
    unsigned int solve_time_step();
    /// Step 2 of Algorithm 1 (PartitionedCoupling::converge with coupling_iteration()):
    /// coupling iterations from d until the interface residual is below the tolerance; returns
    /// their number (d is then the accepted displacement).
    unsigned int converge_interface();
    /// Steady FSI (Fluid/Transient = Solid/Transient = false): the coupling iterations converge
    /// the steady coupled state, steady fluid and static solid in each; returns their number.
    unsigned int solve_steady();
    /// "time step N (t = ...)" or "the steady coupled solve", for messages.
    std::string step_name() const;
    /// Steps 2a-2e of Algorithm 1 for the displacement d; returns the solid's answer d~.
    InterfaceVector coupling_iteration(const InterfaceVector& d);
    /// Move the fluid mesh so that its interface vertices sit at reference + d.
    void move_fluid_mesh(const InterfaceVector& displacement);
    /// Fluid wall tractions -> solid external tractions.
    void transfer_tractions();
    /// Solid vertex displacements -> fluid interface vertices (zone numbering).
    InterfaceVector solid_interface_displacement() const;
    void record_time_history(unsigned int iterations, double residual);
    /// Append the velocity and pressure at every fluid probe to `line`, the probes found on the
    /// fluid mesh as it is now.
    void append_fluid_probes(std::vector<double>& line);
    /// Steady: one line of fsi_steady_history.txt and a progress line per coupling iteration.
    void record_steady_iteration(unsigned int k, double residual);
    /// The fluid's force on the Fluid scene/Force patches [N] (per unit depth in 2D).
    dealii::Tensor<1, dim> fluid_force() const;
    void output_results() const;

    MPI_Comm comm;
    MeshParameters fluid_mesh_parameters, solid_mesh_parameters;
    FluidParameters fluid_parameters;
    FluidSceneParameters fluid_scene_parameters;
    SolidParameters solid_parameters;
    SolidSceneParameters solid_scene_parameters;
    FsiSceneParameters prm;
    std::string prm_directory, output_directory;
    const bool steady; ///< steady FSI: Fluid/Transient = false
    dealii::ConditionalOStream pcout;
    /// Wall time per part of Algorithm 1 (printed at the end, summary.json `timing`).
    mutable dealii::TimerOutput timer;
    TimeControl clock;
    const unsigned int max_halvings; ///< Time/Time step control

    dealii::parallel::distributed::Triangulation<dim> fluid_tria, solid_tria;
    std::unique_ptr<FVGeometry<dim>> fluid_fv, fluid_reference_fv, solid_fv;
    std::unique_ptr<FluidSolver<dim>> fluid;
    std::unique_ptr<MeshMotion<dim>> motion;
    std::unique_ptr<SolidSolver<dim>> solid;
    /// The interface's two sides and the transfers across it.
    std::unique_ptr<FsiInterface<dim>> interface;
    /// Algorithm 1's iteration, the coupling method and the interface displacements.
    std::unique_ptr<PartitionedCoupling> coupling;
    PointProbes<dim> probes;       ///< Solid scene/Probes: displacement
    PointProbes<dim> fluid_probes; ///< Fluid scene/Probes: velocity and pressure
    std::unique_ptr<VtuOutput<dim>> fluid_output, solid_output;
    std::unique_ptr<HistoryFile> history;

    std::vector<dealii::Point<dim>> vertices_old; ///< fluid vertex positions at t^n
    CheckpointParameters checkpoints;
    /// Restarting: the checkpoint's meshes and records between make_grids() and
    /// restore_checkpoint(), and the fluid vertex positions saved.
    std::unique_ptr<MeshArchive<dim>> fluid_restart, solid_restart;
    std::vector<dealii::Point<dim>> restart_vertices;
    std::unique_ptr<MeshArchive<dim>> step_start_fluid, step_start_solid;
    std::stringstream step_start_global;

    std::optional<dealii::Tensor<1, dim>> last_force; ///< fluid_force() of the last record
    double volume_ratio = 1; ///< min over the fluid cells of V_P / V_P(reference), now
    FsiResults result;
  };
} // namespace fvfsi
