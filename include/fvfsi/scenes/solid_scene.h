#pragma once
// The solid scene: a SolidSolver on a mesh from the .prm, run to its end time (or one steady
// solve), with probes, patch forces, time-history tables, VTU output, and errors against an exact
// solution when the .prm gives one (e.g. the plate with a hole).

#include <fvfsi/io/summary.h>
#include <fvfsi/scenes/scene_base.h>
#include <fvfsi/solid/solid_parameters.h>
#include <fvfsi/solid/solid_solver.h>

#include <memory>
#include <string>
#include <vector>

namespace fvfsi
{
  /// `subsection Solid scene`: probes (displacement), force patches, output, and the exact
  /// solution of a verification case.
  struct SolidSceneParameters : SceneOutputParameters
  {
    /// Exact displacement (dim expressions) for the error norms; empty: none.
    std::string exact_displacement = "";
    /// Exact Cauchy stress, 2D: `sxx; syy; sxy`, 3D: `sxx; syy; szz; sxy; syz; sxz`; empty: none.
    std::string exact_stress = "";
    /// Patches on whose faces the stress error is measured, comma separated.
    std::vector<std::string> stress_error_patches;

    SolidSceneParameters() { progress_interval = 10; }
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
    template <class Archive>
    void serialize(Archive& ar, const unsigned int /*version*/)
    {
      ar& total_outer_iterations& n_time_steps;
    }
  };

  template <int dim>
  class SolidScene : public SingleMeshScene<dim>
  {
  public:
    SolidScene(const MeshParameters& mesh_parameters, const SolidParameters& solid_parameters,
               const SolidSceneParameters& scene_parameters, const TimeParameters& time,
               MPI_Comm comm, const std::string& prm_directory,
               const std::string& output_directory);

    void run();
    void write_summary(Summary& summary) const;
    const SolidResults& results() const { return result; }
    const SolidSolver<dim>& solver() const { return *solid; }

  private:
    using Base = SingleMeshScene<dim>;
    using Base::clock, Base::comm, Base::fv, Base::history, Base::mesh_parameters, Base::pcout,
      Base::probes, Base::vtu_output;

    void make_grid();
    void compute_errors();
    void record_time_history();
    /// The displacement at probe i [m] (collective).
    dealii::Tensor<1, dim> probe_displacement(unsigned int i) const;

    SolidParameters solid_parameters;
    SolidSceneParameters scene_parameters;
    std::unique_ptr<SolidSolver<dim>> solid;
    SolidResults result;
  };
} // namespace fvfsi
