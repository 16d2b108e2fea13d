#pragma once
// The fvfsi command line:  fvfsi [CASE.prm] [--set "Section/Key=value"]... | --help | --print-parameters

#include <deal.II/base/parameter_handler.h>

#include <fvfsi/apps/fluid_scene.h>
#include <fvfsi/apps/fsi_scene.h>
#include <fvfsi/apps/poisson.h>
#include <fvfsi/apps/solid_scene.h>
#include <fvfsi/mesh/mesh_parameters.h>

#include <ostream>
#include <string>
#include <vector>

namespace fvfsi
{
  /// The top level of a .prm file: which scene, in which dimension, written where.
  struct RunParameters
  {
    unsigned int dim = 2;
    std::string scene = "poisson";
    std::string output_directory = "output";
    void declare(dealii::ParameterHandler& prm);
  };

  /// Every parameter fvfsi knows, bound to one ParameterHandler.
  struct AllParameters
  {
    AllParameters();
    RunParameters run;
    MeshParameters mesh;
    PoissonParameters poisson;
    SolidParameters solid;
    SolidSceneParameters solid_scene;
    FluidParameters fluid;
    FluidSceneParameters fluid_scene;
    MeshParameters solid_mesh; ///< FSI: the solid's mesh (subsection `Solid mesh`)
    FsiSceneParameters fsi;
    dealii::ParameterHandler prm;
  };

  /**
   * Read `file` (if not empty), then apply the `overrides` ("Section/Sub/Key=value"). Throws
   * std::runtime_error with a message that names the file and line, or the override, at fault.
   */
  void read_parameters(AllParameters& parameters, const std::string& file,
                       const std::vector<std::string>& overrides);

  /// Run fvfsi as the executable does (MPI must be initialised). Messages go to `out`/`err` on
  /// rank 0. Returns the process exit code: 0 on success, 1 on any error.
  int run_application(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
} // namespace fvfsi
