// Solid/Algorithm = coupled (Newton's method) solves the discrete equations of the segregated
// algorithm: the displacement fields of the two, gathered by cell centroid over all ranks, agree
// to 1e-8 relative (max |u_coupled - u_segregated| / max |u_segregated|) for
//  - the plate with a hole (prm/plate_hole.prm, 968 cells, steady, symmetry + traction
//    boundaries), linear elastic with the three face-gradient variants (present with the
//    Hessian correction, as shipped; Demirdzic-Muzaferija; Jasak-Weller), and St. Venant-Kirchhoff;
//  - the Turek-Hron flag (prm/turek_hron_csm1.prm, 70 x 4 cells, St. Venant-Kirchhoff, clamped +
//    traction boundaries): five BDF2 steps of CSM3's start (released under gravity), present
//    variant, without and with the Hessian correction.
// The segregated outer iterations converge to 1e-12 (the steady flag is left out of this
// comparison: its segregated iteration contracts by 0.9997 per iteration and does not reach
// 1e-12 in 400 000). The steady CSM1 flag of the same mesh is solved by the coupled algorithm alone
// and its point A compared with the converged segregated value of doc/results/csm.md (70 x 4,
// (-6.637e-3, -63.49e-3) m). Asserted: Newton iterations per run (linear elastic: 1; St.
// Venant-Kirchhoff: at most 8 on the plate, 30 in the five flag steps, 20 for the steady flag).
#include <fvfsi/scenes/solid_scene.h>

#include "../test_utilities.h"
#include "solid_fields.h"

#include <filesystem>
#include <map>

using namespace fvfsi_test;

/// The displacement by centroid (rank 0: all cells) and the outer / Newton iterations.
std::pair<SolidField, unsigned int> run(const fvfsi::AllParameters& p)
{
  std::filesystem::create_directories("out");
  fvfsi::SolidScene<2> scene(p.mesh, p.solid, p.solid_scene, p.time, MPI_COMM_WORLD, ".", "out");
  scene.run();
  return {displacement_by_centroid(scene), scene.results().total_outer_iterations};
}

void compare(std::ofstream& out, const std::string& title, const std::string& name,
             const std::vector<std::string>& overrides, const unsigned int max_newton)
{
  auto segregated = overrides, coupled = overrides;
  segregated.insert(segregated.end(), {"Solid/Algorithm=segregated", "Solid/Outer tolerance=1e-12",
                                       "Solid/Max outer iterations=100000"});
  coupled.insert(coupled.end(), {"Solid/Algorithm=coupled", "Solid/Outer tolerance=1e-12"});
  const auto [u_s, k_s] = run(*shipped_case(name, segregated));
  const auto [u_c, k_c] = run(*shipped_case(name, coupled));
  bool matched = false;
  const double difference = max_relative_difference(u_c, u_s, matched);
  out << title << ": " << u_s.size() << " cells, all matched: " << yes_no(matched)
      << ", Newton iterations <= " << max_newton << ": " << yes_no(k_c <= max_newton)
      << ", max |u_coupled - u_segregated| / max |u| < 1e-8: " << yes_no(difference < 1e-8) << "\n";
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  for (const std::string variant : {"present", "Demirdzic-Muzaferija", "Jasak-Weller"})
    compare(out, "plate with a hole, linear elastic, " + variant, "plate_hole",
            {"Solid/Variant=" + variant}, 1);
  compare(out, "plate with a hole, St. Venant-Kirchhoff", "plate_hole",
          {"Solid/Model=St. Venant-Kirchhoff"}, 8);
  const std::vector<std::string> flag = {"Mesh/Generator arguments=70: 4", "Solid/Transient=true",
                                         "Time/Time step=0.01", "Time/End time=0.05"};
  compare(out, "Turek-Hron flag, 5 BDF2 steps", "turek_hron_csm1", flag, 30);
  auto hessian = flag;
  hessian.push_back("Solid/Hessian correction=true");
  compare(out, "Turek-Hron flag, 5 BDF2 steps, Hessian correction", "turek_hron_csm1", hessian, 30);

  const auto p =
    shipped_case("turek_hron_csm1", {"Mesh/Generator arguments=70: 4", "Solid/Algorithm=coupled"});
  std::filesystem::create_directories("out");
  fvfsi::SolidScene<2> scene(p->mesh, p->solid, p->solid_scene, p->time, MPI_COMM_WORLD, ".",
                             "out");
  scene.run();
  const auto& A = scene.results().probe_displacement[0].second;
  out << "steady CSM1 flag, 70 x 4, coupled: point A = " << format("(%.4e, %.4e)", A[0], A[1])
      << " m, Newton iterations <= 20: " << yes_no(scene.results().total_outer_iterations <= 20)
      << "\n";
}
