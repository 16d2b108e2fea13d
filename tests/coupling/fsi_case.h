#pragma once
// Running a shipped FSI case in a coupling test (fsi3_coarse, tube_coarse).

#include <fvfsi/scenes/fsi_scene.h>

#include "../test_utilities.h"

#include <filesystem>
#include <string>
#include <vector>

namespace fvfsi_test
{
  /// Runs prm/NAME.prm with the overrides `base` and then `overrides` on `comm`, writing to
  /// `directory`; returns the error message ("" if it ran through).
  template <int dim>
  std::string run_fsi_case(const std::string& name, const std::vector<std::string>& base,
                           const std::vector<std::string>& overrides, MPI_Comm comm,
                           const std::string& directory)
  {
    std::filesystem::create_directories(directory);
    auto settings = base;
    settings.insert(settings.end(), overrides.begin(), overrides.end());
    settings.push_back("Output directory=" + directory);
    const auto p = shipped_case(name, settings);
    try
    {
      fvfsi::FsiScene<dim> scene(p->fsi_input(), comm, ".", directory);
      scene.run();
    }
    catch (const std::exception& e)
    {
      return e.what();
    }
    return "";
  }
} // namespace fvfsi_test
