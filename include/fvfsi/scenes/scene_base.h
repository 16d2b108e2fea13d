#pragma once
// What the scenes share: the output entries of their `... scene` subsections, and the parts of a
// scene on one mesh (the solid and fluid scenes): where it runs and writes, its clock, its mesh and
// FV geometry, its probes, its VTU writer and its history file. A scene program (scenes/*_scene)
// adds its solver and says what to record.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <fvfsi/base/time_control.h>
#include <fvfsi/fv/point_probes.h>
#include <fvfsi/io/history_file.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_parameters.h>

#include <memory>
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

  template <int dim>
  class SingleMeshScene
  {
  public:
    const FVGeometry<dim>& geometry() const { return *fv; }
    const TimeControl& time() const { return clock; }

  protected:
    /// `probe_parameter` names the probes' .prm entry in messages.
    SingleMeshScene(const MeshParameters& mesh_parameters, const TimeParameters& time,
                    const SceneOutputParameters& output, const std::string& probe_parameter,
                    MPI_Comm comm, const std::string& prm_directory,
                    const std::string& output_directory);

    /// The mesh of `Mesh`, its FV geometry, and the VTU writer `<output_name>.pvd`.
    void make_mesh_and_writer(const std::string& output_name);
    /// Create `<output directory>/<file_name>` with the given columns.
    void open_history(const std::string& file_name, const std::vector<std::string>& columns);
    /// `<base>x<suffix>`, `<base>y<suffix>`[, `<base>z<suffix>`]: the names of a vector's
    /// columns (e.g. ux_A, uy_A).
    static std::vector<std::string> vector_columns(const std::string& base, const std::string& suffix);
    /// True if a progress line or VTU output is due after time step `step` of `n_steps`.
    bool progress_due(unsigned int step, unsigned int n_steps) const;
    bool output_due(unsigned int step) const;

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
  };
} // namespace fvfsi
