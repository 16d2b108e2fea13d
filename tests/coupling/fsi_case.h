#pragma once
// Running a shipped FSI case in a coupling test (fsi3_coarse, tube_coarse, thick_plate_coarse),
// and the overrides that converge its solves for a comparison of partitions (also
// checkpoint_restart).

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

  /// The runs of a test that compares partitions: prm/NAME.prm with `base` on `comm` as shipped
  /// (into out_shipped; its error message is returned) and with `tight` (out_np); on rank 0, with
  /// `tight` on one rank (out_1) and, if `comm` has several ranks, as shipped on one rank
  /// (out_shipped_1).
  template <int dim>
  std::string run_shipped_and_one_rank(const std::string& name,
                                       const std::vector<std::string>& base,
                                       const std::vector<std::string>& tight, MPI_Comm comm)
  {
    const std::string error = run_fsi_case<dim>(name, base, {}, comm, "out_shipped");
    run_fsi_case<dim>(name, base, tight, comm, "out_np");
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    {
      run_fsi_case<dim>(name, base, tight, MPI_COMM_SELF, "out_1");
      if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
        run_fsi_case<dim>(name, base, {}, MPI_COMM_SELF, "out_shipped_1");
    }
    return error;
  }

  /// The overrides that converge every solve of a transient FSI run far below what a comparison
  /// of partitions asks: each linear solve, the pressure's first correctors too, by the relative
  /// `reduction`, the solid's outer iterations to 1e-13, the coupling to `coupling_tolerance`.
  /// The partition changes the preconditioners, so runs on different numbers of ranks agree to
  /// 1e-8 only where every solve stops well below it.
  inline std::vector<std::string> converged_solves(const std::string& reduction,
                                                   const std::string& coupling_tolerance)
  {
    return {"Fluid momentum solver/Residual reduction=" + reduction,
            "Fluid pressure solver/Residual reduction=" + reduction,
            "Fluid pressure solver/Corrector residual reduction=0",
            "Mesh motion solver/Residual reduction=" + reduction,
            "Solid linear solver/Residual reduction=" + reduction,
            "Solid/Outer tolerance=1e-13",
            "Coupling/Tolerance=" + coupling_tolerance};
  }
} // namespace fvfsi_test
