#pragma once
// The fluid scene: a FluidSolver on a mesh from the .prm, run steady or to its end time, with the
// force on chosen patches (drag and lift) as a time history, VTU output, errors against an exact
// solution when the .prm gives one, and for periodic flows the mean, amplitude and frequency of
// the forces over the last periods.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <fvfsi/ale/mesh_motion.h>
#include <fvfsi/base/time_control.h>
#include <fvfsi/fluid/fluid_parameters.h>
#include <fvfsi/fluid/fluid_solver.h>
#include <fvfsi/fv/point_probes.h>
#include <fvfsi/io/summary.h>
#include <fvfsi/scenes/scene_base.h>

#include <memory>
#include <string>
#include <vector>

namespace fvfsi
{
  /// `subsection Fluid scene` (probes: velocity and pressure; force patches: drag = x, lift = y)
  /// and `subsection Mesh motion`.
  struct FluidSceneParameters : SceneOutputParameters
  {
    /// Exact velocity (dim expressions of x, y[, z], t) and pressure [Pa]; empty: no errors.
    std::string exact_velocity = "", exact_pressure = "";
    /// Periodic flows: the mean, amplitude and frequency of the forces are taken over the
    /// samples with t >= End time - this [s] (0: none).
    double analysis_window = 0;
    /// How the mesh moves (subsection `Mesh motion`; default: it does not).
    MeshMotionParameters mesh_motion;

    void declare(dealii::ParameterHandler& prm);
  };

  /// Mean = (max + min) / 2, amplitude = (max - min) / 2 and frequency (from the mean
  /// up-crossings) of a sampled periodic signal, as Turek and Hron define them. With fewer than
  /// two up-crossings the samples hold no full period: all three are NaN (null in summary.json).
  struct PeriodicStatistics
  {
    double mean = 0, amplitude = 0, frequency = 0;
    unsigned int n_periods = 0; ///< full periods between the first and last up-crossing
  };
  PeriodicStatistics periodic_statistics(const std::vector<double>& t,
                                         const std::vector<double>& q);

  /// What a fluid run found.
  struct FluidResults
  {
    double max_velocity_error = -1, max_pressure_error = -1; ///< max over cells [m/s], [Pa]
    double l2_velocity_error = -1, l2_pressure_error = -1;   ///< sqrt(sum_P V_P e_P^2)
    unsigned int n_time_steps = 0; ///< time steps, or pseudo time steps of a steady run
    /// Moving meshes: min over cells and time steps of V_P / V_P(reference).
    double min_volume_ratio = 1;
    template <class Archive>
    void serialize(Archive& ar, const unsigned int /*version*/)
    {
      ar& n_time_steps& min_volume_ratio;
    }
  };

  template <int dim>
  class FluidScene : public SingleMeshScene<dim>
  {
  public:
    FluidScene(const MeshParameters& mesh_parameters, const FluidParameters& fluid_parameters,
               const FluidSceneParameters& scene_parameters, const TimeParameters& time,
               MPI_Comm comm, const std::string& prm_directory,
               const std::string& output_directory);

    void run();
    void write_summary(Summary& summary) const;
    const FluidSolver<dim>& solver() const { return *fluid; }
    const FluidResults& results() const { return result; }
    /// Force of the fluid on the force patches [N] (per unit depth in 2D).
    dealii::Tensor<1, dim> body_force() const;
    /// The probes of `Fluid scene/Probes`, and the velocity [m/s] and pressure [Pa] at probe i
    /// now (collective).
    const PointProbes<dim>& point_probes() const { return probes; }
    std::pair<dealii::Tensor<1, dim>, double> probe_values(unsigned int i) const;

  private:
    using Base = SingleMeshScene<dim>;
    using Base::clock, Base::comm, Base::fv, Base::history, Base::mesh_parameters, Base::pcout,
      Base::probes, Base::triangulation, Base::vtu_output;

    void make_grid();
    /// Checkpoints: the fluid's and the mesh motion's states, the force histories so far.
    void checkpoint_state(MeshArchive<dim>& archive);
    void checkpoint_state(GlobalArchive& archive);
    /// Restarting: the mesh moves to where it was, then the states are read.
    void restore();
    void run_transient();
    /// Moves the mesh to its position at the clock's time: vertices (also those of the
    /// triangulation, so that the VTU output shows the moved mesh), geometry, mesh fluxes.
    void move_mesh();
    void record_time_history();
    void compute_errors();

    FluidParameters fluid_parameters;
    FluidSceneParameters scene_parameters;
    std::unique_ptr<FluidSolver<dim>> fluid;
    std::unique_ptr<FVGeometry<dim>> reference_fv; ///< the undeformed mesh (moving meshes only)
    std::unique_ptr<MeshMotion<dim>> motion;

    std::vector<double> history_t, history_drag, history_lift;
    std::vector<std::pair<dealii::Tensor<1, dim>, double>> final_probe_values;
    FluidResults result;
  };
} // namespace fvfsi
