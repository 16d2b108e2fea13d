// The coupled solid algorithm on slender, bending-dominated structures, where the segregated one
// converges slowly or not at all (doc/results/solid_coupled.md):
//  - 2D: prm/cantilever.prm (2 m x 0.1 m, end shear load, exact Timoshenko displacement imposed
//    at x = 0) on 40 x 2 and 80 x 4 cells: linear elastic in one Newton iteration, St. Venant-
//    Kirchhoff in at most 10; the tip deflection u_y(2, 0) against the exact -1.60275e-2 m;
//  - 3D: a block cantilever 1 m x 0.1 m x 0.1 m, 20 x 2 x 2 cells, clamped (u = 0) at x = 0, a
//    uniform shear traction of 1e6 Pa (1e4 N) at x = 1: linear elastic in one Newton iteration,
//    St. Venant-Kirchhoff in at most 10, the tip deflection (at the centre of a tip face,
//    (1, 0.025, 0.025)) against Timoshenko beam theory,
//    P L^3 / (3 E I) + P L / (kappa G A) = 2.016e-3 m (the clamp u = 0 stiffens the coarse beam).
// Deflections are printed with 3 significant digits.
#include <fvfsi/scenes/solid_scene.h>

#include "../test_utilities.h"

#include <filesystem>

using namespace fvfsi_test;

template <int dim>
std::pair<double, unsigned int> tip_deflection(const fvfsi::MeshParameters& mesh,
                                               const fvfsi::SolidParameters& solid,
                                               const fvfsi::SolidSceneParameters& scene_parameters)
{
  std::filesystem::create_directories("out");
  fvfsi::TimeParameters time;
  fvfsi::SolidScene<dim> scene(mesh, solid, scene_parameters, time, MPI_COMM_WORLD, ".", "out");
  scene.run();
  return {scene.results().probe_displacement[0].second[1], scene.results().total_outer_iterations};
}

void cantilever_2d(std::ofstream& out)
{
  for (const std::string model : {"linear elastic", "St. Venant-Kirchhoff"})
    for (const unsigned int refinements : {0u, 1u})
    {
      const auto p =
        shipped_case("cantilever", {"Mesh/Global refinements=" + std::to_string(refinements),
                                    "Solid/Model=" + model});
      const auto [u_y, iterations] = tip_deflection<2>(p->mesh, p->solid, p->solid_scene);
      const unsigned int limit = model == "linear elastic" ? 1 : 10;
      out << "2D cantilever, " << model << ", " << (40 << refinements) << " x "
          << (2 << refinements) << ": tip u_y = " << format("%.3e", u_y) << " m ("
          << format("%+.2f", 100 * (u_y / -1.60275e-2 - 1)) << "%), Newton iterations <= " << limit
          << ": " << yes_no(iterations <= limit) << "\n";
    }
}

void cantilever_3d(std::ofstream& out)
{
  fvfsi::MeshParameters mesh;
  mesh.generator = "subdivided_hyper_rectangle";
  mesh.generator_arguments = "20, 2, 2 : 0, -0.05, -0.05 : 1, 0.05, 0.05 : true";
  mesh.n_global_refinements = 0;
  mesh.patch_names = {{0, "left"}, {1, "right"}, {2, "bottom"},
                      {3, "top"},  {4, "back"},  {5, "front"}};
  fvfsi::SolidParameters solid;
  solid.E = 2e11;
  solid.nu = 0.3;
  solid.rho = 7800;
  solid.body_force = "0; 0; 0";
  solid.algorithm = fvfsi::SolidParameters::Algorithm::coupled;
  solid.outer_tolerance = 1e-10;
  solid.fixed_displacement = "left: 0; 0; 0";
  solid.traction = "right: 0; -1e6; 0 | bottom: 0; 0; 0 | top: 0; 0; 0 | back: 0; 0; 0 | "
                   "front: 0; 0; 0";
  fvfsi::SolidSceneParameters scene_parameters;
  scene_parameters.probes = "tip: 1, 0.025, 0.025"; // the centre of a tip face
  for (const auto model : {fvfsi::SolidParameters::Model::linear_elastic,
                           fvfsi::SolidParameters::Model::st_venant_kirchhoff})
  {
    solid.model = model;
    const auto [u_y, iterations] = tip_deflection<3>(mesh, solid, scene_parameters);
    const bool linear = model == fvfsi::SolidParameters::Model::linear_elastic;
    out << "3D block cantilever, " << (linear ? "linear elastic" : "St. Venant-Kirchhoff")
        << ", 20 x 2 x 2: tip u_y = " << format("%.3e", u_y) << " m ("
        << format("%+.1f", 100 * (u_y / -2.016e-3 - 1))
        << "% of beam theory), Newton iterations <= " << (linear ? 1 : 10) << ": "
        << yes_no(iterations <= (linear ? 1u : 10u)) << "\n";
  }
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  cantilever_2d(out);
  cantilever_3d(out);
}
