#pragma once
// Every parameter fvfsi knows, bound to one ParameterHandler, and how a .prm file and `--set`
// overrides are read into them.

#include <deal.II/base/parameter_handler.h>

#include <fvfsi/base/time_control.h>
#include <fvfsi/mesh/mesh_parameters.h>
#include <fvfsi/scenes/fluid_scene.h>
#include <fvfsi/scenes/fsi_scene.h>
#include <fvfsi/scenes/poisson.h>
#include <fvfsi/scenes/solid_scene.h>

#include <string>
#include <vector>

namespace fvfsi
{
  /// The top level of a .prm file: which scene, in which dimension, written where.
  struct RunParameters
  {
    enum class Scene
    {
      poisson, ///< the FV core verification problem
      solid,   ///< the solid solver alone
      fluid,   ///< the flow solver alone, on a fixed or moving mesh
      fsi      ///< fluid and solid coupled
    };
    static const SelectionNames<Scene> scene_names;

    unsigned int dim = 2;
    Scene scene = Scene::poisson;
    std::string output_directory = "output";
    bool plot_history = false; ///< plot the history tables as PNG at the end
    CheckpointParameters checkpoint;
    void declare(dealii::ParameterHandler& prm);
  };

  /// Every parameter fvfsi knows, bound to one ParameterHandler.
  struct AllParameters
  {
    AllParameters();
    RunParameters run;
    TimeParameters time;
    MeshParameters mesh;
    PoissonParameters poisson;
    SolidParameters solid;
    SolidSceneParameters solid_scene;
    FluidParameters fluid;
    FluidSceneParameters fluid_scene;
    MeshParameters solid_mesh; ///< FSI: the solid's mesh (subsection `Solid mesh`)
    FsiSceneParameters fsi;
    dealii::ParameterHandler prm;
    /// The steady settings read_parameters applied (app/steady_settings.h), one line each.
    std::vector<std::string> steady_settings;

    /// The parameters of an FSI scene.
    FsiSceneInput fsi_input() const
    {
      return {mesh, solid_mesh, fluid, fluid_scene, solid, solid_scene, fsi, time};
    }
  };

  /**
   * Read `file` (empty: the built-in default scene, prm/fsi_demo.prm), then apply the
   * `overrides` ("Section/Sub/Key=value"). Throws
   * std::runtime_error with a message that names the file and line, or the override, at fault.
   */
  void read_parameters(AllParameters& parameters, const std::string& file,
                       const std::vector<std::string>& overrides);

  /// Set one parameter from "Section/Sub/Key=value" (as `--set` does); the error names the
  /// assignment.
  void apply_override(dealii::ParameterHandler& prm, const std::string& assignment);
} // namespace fvfsi
