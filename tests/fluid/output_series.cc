// The VTU time series of a transient run: with `Fluid scene/Output interval = 1`, the .pvd record
// of a scene lists every time step it wrote, each with its time and an existing .pvtu file (one
// writer per mesh for the whole run; a writer made anew for each output would leave only the last
// step in the .pvd). Checked on the fluid scene (prm/taylor_green.prm, 5 steps) and on the FSI
// scene (prm/fsi_pressure_column.prm, 4 steps: fluid.pvd and solid.pvd), serial and mpirun=2.
#include <fvfsi/scenes/fluid_scene.h>
#include <fvfsi/scenes/fsi_scene.h>

#include "../test_utilities.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

using namespace fvfsi_test;

/// The (time, file) entries of a .pvd record.
std::vector<std::pair<double, std::string>> read_pvd(const std::string& name)
{
  std::ifstream in(name);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::regex entry("<DataSet timestep=\"([^\"]+)\"[^>]*file=\"([^\"]+)\"");
  std::vector<std::pair<double, std::string>> entries;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry);
       it != std::sregex_iterator(); ++it)
    entries.emplace_back(std::stod((*it)[1]), (*it)[2]);
  return entries;
}

/// True if `name` lists n steps at t = dt, 2 dt, ..., n dt whose files exist.
bool lists_every_step(const std::string& directory, const std::string& name, const unsigned int n,
                      const double dt)
{
  const auto entries = read_pvd(directory + "/" + name);
  bool ok = entries.size() == n;
  for (unsigned int i = 0; ok && i < n; ++i)
    ok = std::abs(entries[i].first - (i + 1) * dt) < 1e-9 * dt &&
         std::filesystem::exists(directory + "/" + entries[i].second);
  return ok;
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  {
    std::filesystem::create_directories("fluid_out");
    const auto p =
      shipped_case("taylor_green", {"Time/End time=0.125", "Fluid scene/Output interval=1",
                                    "Mesh/Global refinements=3", "Output directory=fluid_out"});
    fvfsi::FluidScene<2> scene(p->mesh, p->fluid, p->fluid_scene, p->time, MPI_COMM_WORLD, ".",
                               "fluid_out");
    scene.run();
    if (root)
      out << "fluid scene: fluid.pvd lists the 5 steps written, with their times and files: "
          << yes_no(lists_every_step("fluid_out", "fluid.pvd", 5, 0.025)) << "\n";
  }
  {
    std::filesystem::create_directories("fsi_out");
    const auto p =
      shipped_case("fsi_pressure_column", {"Time/End time=0.02", "Fluid scene/Output interval=1",
                                           "Output directory=fsi_out"});
    fvfsi::FsiScene<2> scene(p->fsi_input(), MPI_COMM_WORLD, ".", "fsi_out");
    scene.run();
    if (root)
      out << "FSI scene: fluid.pvd and solid.pvd list the 4 steps written: "
          << yes_no(lists_every_step("fsi_out", "fluid.pvd", 4, 0.005) &&
                    lists_every_step("fsi_out", "solid.pvd", 4, 0.005))
          << "\n";
  }
}
