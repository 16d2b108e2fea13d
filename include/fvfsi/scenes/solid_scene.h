#pragma once
// The solid scene: a SolidSolver on a mesh from the .prm, run to its end time (or one steady
// solve), with probes, patch forces, time-history tables, VTU output, and errors against an exact
// solution when the .prm gives one (e.g. the plate with a hole).

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <fvfsi/base/time_control.h>
#include <fvfsi/fv/point_probes.h>
#include <fvfsi/io/history_file.h>
#include <fvfsi/io/summary.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_parameters.h>
#include <fvfsi/solid/solid_parameters.h>
#include <fvfsi/solid/solid_solver.h>

#include <memory>
#include <string>
#include <vector>

namespace fvfsi
{
  struct SolidSceneParameters
  {
    /// Named probe points, `A: 0.6, 0.2 | B: 0.2, 0.21`.
    std::string probes = "";
    /// Patches whose total force is recorded, comma separated.
    std::vector<std::string> force_patches;
    /// Exact displacement (dim expressions) for the error norms; empty: none.
    std::string exact_displacement = "";
    /// Exact Cauchy stress, 2D: `sxx; syy; sxy`, 3D: `sxx; syy; szz; sxy; syz; sxz`; empty: none.
    std::string exact_stress = "";
    /// Patches on whose faces the stress error is measured, comma separated.
    std::vector<std::string> stress_error_patches;
    /// Write VTU every this many time steps (0: only at the end).
    unsigned int output_interval = 0;

    void declare(dealii::ParameterHandler& prm);
  };

  /// What a solid run found.
  struct SolidResults
  {
    double max_displacement_error = -1; ///< max over cells of |u_P - u(r_P)|_inf [m]
    /// max over the faces of each stress-error patch of max_ij |sigma_f - sigma(r_f)| [Pa]
    std::vector<std::pair<std::string, double>> max_stress_error;
    std::vector<std::pair<std::string, dealii::Tensor<1, 3>>> probe_displacement; ///< final values
    unsigned int total_outer_iterations = 0;
    unsigned int n_time_steps = 0;
  };

  template <int dim>
  class SolidScene
  {
  public:
    SolidScene(const MeshParameters& mesh_parameters, const SolidParameters& solid_parameters,
               const SolidSceneParameters& scene_parameters, const TimeParameters& time,
               MPI_Comm comm, const std::string& prm_directory, const std::string& output_directory);

    void run();
    void write_summary(Summary& summary) const;
    const SolidResults& results() const { return result; }
    const FVGeometry<dim>& geometry() const { return *fv; }
    const SolidSolver<dim>& solver() const { return *solid; }
    const TimeControl& time() const { return clock; }

  private:
    void make_grid();
    void compute_errors();
    void record_time_history();
    /// The displacement at probe i [m] (collective).
    dealii::Tensor<1, dim> probe_displacement(unsigned int i) const;
    void output_results() const;

    MPI_Comm comm;
    MeshParameters mesh_parameters;
    SolidParameters solid_parameters;
    SolidSceneParameters scene_parameters;
    std::string prm_directory, output_directory;
    dealii::ConditionalOStream pcout;
    TimeControl clock;
    dealii::parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<FVGeometry<dim>> fv;
    std::unique_ptr<SolidSolver<dim>> solid;
    PointProbes<dim> probes;
    std::unique_ptr<VtuOutput<dim>> vtu_output;
    std::unique_ptr<HistoryFile> history;
    SolidResults result;
  };
} // namespace fvfsi
