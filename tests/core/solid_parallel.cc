// np = 2 equals np = 1 for the solid solver: the displacement field, gathered by cell centroid,
// of (a) the linear-elastic plate with a hole (968 cells, steady, symmetry + traction boundaries)
// and (b) five BDF2 steps of the St. Venant-Kirchhoff Turek-Hron flag under gravity (280 cells,
// clamped + traction boundaries), also with Solid/Hessian correction (which plate_hole.prm sets
// too), agrees with a run on rank 0 alone to 1e-8 relative
// (max |u_np - u_1| / max |u_1|). Outer iterations converge to 1e-12 in both runs, so what is
// left is round-off and partition-dependent AMG/Anderson differences.
#include <fvfsi/scenes/solid_scene.h>

#include "../test_utilities.h"

#include <filesystem>
#include <map>

using namespace fvfsi_test;

using Values = std::vector<std::pair<std::array<double, 2>, std::array<double, 2>>>;

Values run(const fvfsi::AllParameters& p, MPI_Comm comm)
{
  std::filesystem::create_directories("out");
  fvfsi::SolidScene<2> scene(p.mesh, p.solid, p.solid_scene, p.time, comm, ".", "out");
  scene.run();
  Values values;
  const auto& fv = scene.geometry();
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
    values.push_back({{fv.centroid[c][0], fv.centroid[c][1]},
                      {scene.solver().displacement()[c][0], scene.solver().displacement()[c][1]}});
  return values;
}

void compare(std::ofstream& out, const std::string& title, const fvfsi::AllParameters& p)
{
  const auto gathered = dealii::Utilities::MPI::gather(MPI_COMM_WORLD, run(p, MPI_COMM_WORLD));
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return;
  std::map<std::array<double, 2>, std::array<double, 2>> reference;
  double max_u = 0;
  for (const auto& [x, u] : run(p, MPI_COMM_SELF))
  {
    reference[x] = u;
    max_u = std::max({max_u, std::abs(u[0]), std::abs(u[1])});
  }
  double max_difference = 0;
  unsigned int matched = 0;
  for (const auto& part : gathered)
    for (const auto& [x, u] : part)
      if (const auto it = reference.find(x); it != reference.end())
      {
        ++matched;
        max_difference = std::max(
          {max_difference, std::abs(u[0] - it->second[0]), std::abs(u[1] - it->second[1])});
      }
  out << title << ": " << reference.size()
      << " cells, all matched: " << yes_no(matched == reference.size())
      << ", max |u_np - u_1| / max |u_1| < 1e-8: " << yes_no(max_difference / max_u < 1e-8) << "\n";
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  compare(out, "plate with a hole", *shipped_case("plate_hole", {"Solid/Outer tolerance=1e-12"}));
  compare(out, "Turek-Hron flag, 5 BDF2 steps",
          *shipped_case("turek_hron_csm1", {"Mesh/Generator arguments=70: 4",
                                            "Solid/Transient=true", "Time/Time step=0.01",
                                            "Time/End time=0.05", "Solid/Outer tolerance=1e-12"}));
  compare(out, "Turek-Hron flag, 5 BDF2 steps, Hessian correction",
          *shipped_case("turek_hron_csm1",
                        {"Mesh/Generator arguments=70: 4", "Solid/Transient=true",
                         "Time/Time step=0.01", "Time/End time=0.05", "Solid/Outer tolerance=1e-12",
                         "Solid/Hessian correction=true"}));
}
