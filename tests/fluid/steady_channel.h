#pragma once
// Shared by the steady-fluid tests (fluid_steady_range, fluid_simplec): prm/turek_hron_cfd2.prm
// on a coarse channel (n = 12, 1921 cells), mean inflow U, steady tolerance 1e-9, run to its end
// or its error.
#include <fvfsi/scenes/fluid_scene.h>

#include "../test_utilities.h"

#include <filesystem>
#include <string>
#include <vector>

namespace fvfsi_test
{
  struct Result
  {
    double drag = 0, relaxation = 0;
    unsigned int pseudo_steps = 0;
    std::string error;
  };

  inline Result run_steady_channel(const double U, const std::vector<std::string>& extra)
  {
    // SIMPLE unless `extra` says otherwise: these tests are about its relaxation (a steady run
    // takes SIMPLEC where its file does not choose, app/steady_settings.h).
    std::vector<std::string> overrides = {
      "Mesh/Generator arguments=12", "Fluid/Steady tolerance=1e-9", "Output directory=out",
      "Fluid/Consistent pressure coupling=false",
      format("Fluid/Velocity inlet=inlet: %g*1.5*4*y*(0.41-y)/0.41^2; 0", U)};
    overrides.insert(overrides.end(), extra.begin(), extra.end());
    const auto p = shipped_case("turek_hron_cfd2", overrides);
    std::filesystem::create_directories("out");
    fvfsi::FluidScene<2> scene(p->mesh, p->fluid, p->fluid_scene, p->time, MPI_COMM_WORLD, ".",
                               "out");
    Result r;
    try
    {
      scene.run();
    }
    catch (const std::exception& e)
    {
      r.error = e.what();
    }
    r.drag = scene.body_force()[0];
    r.relaxation = scene.solver().momentum_relaxation();
    r.pseudo_steps = scene.solver().pseudo_steps();
    return r;
  }
} // namespace fvfsi_test
