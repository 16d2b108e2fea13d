// The steady settings (app/steady_settings.h, issue 56 item 5): a steady run takes steady solver
// settings for every one of them its file leaves unset, and keeps what the file gives.
//   (a) prm/turek_hron_cfd3.prm switched to Fluid/Transient = false (nothing else): SIMPLEC and
//       the rough linear solves (momentum 0.1, pressure 0.01), the file's own corrector reduction
//       (1e-2) kept; the transient file as shipped takes none;
//   (b) prm/turek_hron_cfd2.prm, which gives its linear solves: only SIMPLEC is taken, its own
//       reductions stay; a `--set` of Consistent pressure coupling = false is kept (SIMPLE);
//   (c) a steady FSI (prm/turek_hron_fsi3.prm with both sides steady): Fluid/Steady tolerance =
//       0.1 x Coupling/Tolerance (1e-6 for its 1e-5); prm/turek_hron_fsi1.prm gives all of them
//       and takes none;
//   (d) the steady cavity (prm/cavity_rigid_bottom.prm, 1808 cells, steady tolerance 1e-5) run
//       with the settings and with the transient defaults given explicitly: the same lift to
//       1e-4 relative (the two runs stop at a relative change of 1e-5 per pseudo step, each on
//       its own path to the same steady state; measured 1.1e-5), and fewer pseudo steps with the settings (measured 52
//       against 80). The pseudo steps go to stdout only (they depend on round-off).
#include <fvfsi/app/steady_settings.h>
#include <fvfsi/scenes/fluid_scene.h>

#include "../test_utilities.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace fvfsi_test;

namespace
{
  struct Cavity
  {
    double lift;
    unsigned int pseudo_steps;
  };

  Cavity run_cavity(std::vector<std::string> overrides)
  {
    std::filesystem::create_directories("out");
    overrides.push_back("Output directory=out");
    const auto p = shipped_case("cavity_rigid_bottom", overrides);
    fvfsi::FluidScene<2> scene(p->mesh, p->fluid, p->fluid_scene, p->time, MPI_COMM_WORLD, ".",
                               "out");
    scene.run();
    return {scene.body_force()[1], scene.solver().pseudo_steps()};
  }
} // namespace

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();

  const auto cfd3 = shipped_case("turek_hron_cfd3", {"Fluid/Transient=false"});
  out << "(a) CFD3 switched to steady: SIMPLEC " << yes_no(cfd3->fluid.consistent_coupling)
      << ", reductions 0.1 / 0.01, the file's corrector reduction 1e-2 kept "
      << yes_no(cfd3->fluid.momentum_solver.reduction == 0.1 &&
                cfd3->fluid.pressure_solver.reduction == 0.01 &&
                cfd3->fluid.pressure_corrector_reduction == 1e-2)
      << ", " << cfd3->steady_settings.size() << " settings taken\n";
  const auto cfd3_transient = shipped_case("turek_hron_cfd3", {});
  out << "(a) CFD3 as shipped (transient): settings taken "
      << cfd3_transient->steady_settings.size() << ", SIMPLE "
      << yes_no(!cfd3_transient->fluid.consistent_coupling) << "\n";

  const auto cfd2 = shipped_case("turek_hron_cfd2", {});
  out << "(b) CFD2: SIMPLEC " << yes_no(cfd2->fluid.consistent_coupling)
      << ", its own corrector reduction 1e-1 and momentum reduction 1e-1 kept "
      << yes_no(cfd2->fluid.pressure_corrector_reduction == 0.1 &&
                cfd2->fluid.momentum_solver.reduction == 0.1)
      << ", " << cfd2->steady_settings.size() << " setting taken\n";
  const auto cfd2_simple =
    shipped_case("turek_hron_cfd2", {"Fluid/Consistent pressure coupling=false"});
  out << "(b) CFD2 with --set SIMPLE: kept "
      << yes_no(!cfd2_simple->fluid.consistent_coupling &&
                fvfsi::given(cfd2_simple->prm, "Fluid/Consistent pressure coupling"))
      << "\n";

  const auto fsi3 =
    shipped_case("turek_hron_fsi3", {"Fluid/Transient=false", "Solid/Transient=false"});
  out << "(c) FSI3 switched to steady: Fluid/Steady tolerance = 0.1 x Coupling/Tolerance "
      << yes_no(std::abs(fsi3->fluid.steady_tolerance - 1e-6) < 1e-18) << "\n";
  const auto fsi1 = shipped_case("turek_hron_fsi1", {});
  out << "(c) FSI1 as shipped: settings taken " << fsi1->steady_settings.size() << "\n";

  const Cavity with = run_cavity({});
  const Cavity as_given = run_cavity({"Fluid/Consistent pressure coupling=false",
                                      "Fluid pressure solver/Corrector residual reduction=0"});
  std::printf("cavity: lift %.10g in %u pseudo steps (steady settings), %.10g in %u (as given)\n",
              with.lift, with.pseudo_steps, as_given.lift, as_given.pseudo_steps);
  out << "(d) cavity: the same lift to 1e-4 "
      << yes_no(std::abs(with.lift - as_given.lift) <= 1e-4 * std::abs(as_given.lift))
      << ", fewer pseudo steps with the steady settings "
      << yes_no(with.pseudo_steps < as_given.pseudo_steps) << "\n";
}
