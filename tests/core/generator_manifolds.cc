// Meshes from deal.II's generators keep their manifolds through fvfsi::make_mesh (which builds the
// coarse mesh in a serial triangulation and copies it into the parallel::distributed one) and
// through global refinement, serial and parallel (issue 15, item 1). The generators, with the
// manifolds deal.II attaches: channel_with_cylinder and plate_with_a_hole (transfinite
// interpolation around a polar manifold: before the fix in make_mesh their refinement stopped with
// "Computing the mapping between a real space point and a point in reference space failed"),
// hyper_shell and hyper_ball in 2D, cylinder and hyper_shell in 3D.
//
// Asserts, per generator:
//  - the mesh volume (sum of FVGeometry's V_P) converges to the exact domain volume at order >= 1.8
//    between 2 and 3 global refinements (straight cell edges on curved boundaries: an O(h^2) error;
//    refinement without the manifolds would leave the coarse polygon's error, order 0);
//  - 3 BDF2 time steps of the segregated linear-elastic solid (gravity-like body force, every
//    boundary clamped) on the mesh refined 3 times converge; the displacement at an interior probe
//    is printed to 4 digits, the same for 1 and 2 ranks (the two outputs are compared by numdiff
//    like every test: the solid converges to max |du| / max |u| < 1e-10, far below the 4 digits).
#include <deal.II/base/numbers.h>

#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_builder.h>
#include <fvfsi/scenes/solid_scene.h>

#include "../test_utilities.h"

#include <cmath>
#include <filesystem>
#include <set>

using namespace dealii;
using namespace fvfsi_test;

namespace
{
  struct Generator
  {
    std::string name, arguments;
    double exact_volume;
    std::string probe; // an interior point, `x, y[, z]`
  };

  /// The mesh's volume (sum of V_P) and number of cells; adds its boundary ids to `ids`.
  template <int dim>
  std::pair<double, unsigned int> mesh_volume(const fvfsi::MeshParameters& mesh,
                                              std::set<unsigned int>& ids)
  {
    parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
    fvfsi::make_mesh(mesh, tria);
    for (const auto& cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f))
          ids.insert(cell->face(f)->boundary_id());
    const fvfsi::FVGeometry<dim> fv(tria);
    double V = 0;
    for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
      V += fv.cell_volume[c];
    return {Utilities::MPI::sum(V, MPI_COMM_WORLD), fv.n_global_cells()};
  }

  template <int dim>
  void check(const Generator& g, std::ofstream& out)
  {
    std::vector<std::string> set = {"Dimension=" + std::to_string(dim), "Mesh/Generator=" + g.name,
                                    "Mesh/Generator arguments=" + g.arguments, "Mesh/Patch names="};

    // The volume on 1, 2 and 3 refinements: errors and the order of the last pair.
    std::set<unsigned int> ids;
    std::vector<double> error;
    unsigned int n_cells = 0;
    for (const unsigned int r : {1u, 2u, 3u})
    {
      auto p = shipped_case("cantilever", set);
      p->mesh.n_global_refinements = r;
      const auto [V, n] = mesh_volume<dim>(p->mesh, ids);
      error.push_back(std::abs(V - g.exact_volume) / g.exact_volume);
      n_cells = n;
    }
    const double order = std::log2(error[1] / error[2]);
    out << dim << "D " << g.name << ": volume error " << format("%.2e", error[1]) << " -> "
        << format("%.2e", error[2]) << ", order >= 1.8: " << yes_no(order >= 1.8) << std::endl;

    // A few solid time steps on the finest mesh, every boundary id clamped.
    const std::string zero = dim == 2 ? "0; 0" : "0; 0; 0";
    std::string clamped;
    for (const unsigned int id : ids)
      clamped += (clamped.empty() ? "" : " | ") + ("patch_" + std::to_string(id)) + ": " + zero;
    for (const std::string s :
         {"Mesh/Global refinements=3", "Solid/Model=linear elastic", "Solid/Algorithm=segregated",
          "Solid/Transient=true", "Solid/Young's modulus=1e6", "Solid/Density=1000",
          "Solid/Traction=", "Solid/Outer tolerance=1e-10", "Time/Time step=0.01",
          "Time/End time=0.03", "Solid scene/Exact displacement=", "Solid scene/Exact stress=",
          "Solid scene/Output interval=0"})
      set.push_back(s);
    set.push_back("Solid/Body force=" + std::string(dim == 2 ? "0; -10" : "0; -10; 0"));
    set.push_back("Solid/Fixed displacement=" + clamped);
    set.push_back("Solid scene/Probes=A: " + g.probe);
    const auto p = shipped_case("cantilever", set);
    std::filesystem::create_directories("out");
    fvfsi::SolidScene<dim> scene(p->mesh, p->solid, p->solid_scene, p->time, MPI_COMM_WORLD, ".",
                                 "out");
    scene.run();
    const auto& u = scene.results().probe_displacement[0].second;
    out << "   3 solid time steps on " << n_cells << " cells: u(A) = (" << format("%.4e", u[0]);
    for (unsigned int d = 1; d < dim; ++d)
      out << ", " << format("%.4e", u[d]);
    out << ") m" << std::endl;
  }
} // namespace

int main(int argc, char** argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const double pi = numbers::PI;
  // channel_with_cylinder: [0, 2.2] x [0, 0.41] without the circle r = 0.05 about (0.2, 0.2);
  // plate_with_a_hole: [-2, 2]^2 without the circle r = 0.4; hyper_shell: radii 0.5 and 1;
  // hyper_ball: radius 1; cylinder: radius 1 about the x axis, x in [-1, 1].
  for (const Generator& g :
       {Generator{"channel_with_cylinder", "0.03: 2: 2.0: true", 2.2 * 0.41 - pi * 0.05 * 0.05,
                  "1.0, 0.2"},
        Generator{"plate_with_a_hole", "0.4: 1: 1: 1: 1: 1: 0, 0: 0: 1: 1: 2: true", 16 - pi * 0.16,
                  "1.0, 1.0"},
        Generator{"hyper_shell", "0, 0: 0.5: 1: 0: true", 0.75 * pi, "0.75, 0"},
        Generator{"hyper_ball", "0, 0: 1: true", pi, "0.3, 0.2"}})
    check<2>(g, out);
  for (const Generator& g :
       {Generator{"cylinder", "1: 1", 2 * pi, "0, 0.3, 0.2"},
        Generator{"hyper_shell", "0, 0, 0: 0.5: 1: 0: true", 4 * pi / 3 * 0.875, "0.75, 0, 0"}})
    check<3>(g, out);
}
