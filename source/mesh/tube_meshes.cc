// The meshes of the paper's pressure wave in an elastic tube (section 4.4): the fluid cylinder
// (fvfsi_tube_fluid) and the tube wall around it (fvfsi_tube_wall), both from deal.II's
// generators, turned and coloured for fvfsi.
//
// Both lie along the x axis, x in [0, L]. The fluid's cross-section is deal.II's 2D hyper_ball
// (a square and four cells around it) whose four hull vertices sit at 45, 135, 225 and 315
// degrees; cylinder_shell's four cells round start at 0 degrees, so the wall is turned by 45
// degrees about the axis to put its inner vertices on the fluid's. Both keep a CylindricalManifold
// on their curved surfaces, so every global refinement puts the new interface vertices on the same
// circle: fluid and wall meet conformingly on every level (the FSI transfer does not need it, but
// then the two faceted interfaces are the same surface and no gap enters the coupling).

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <fvfsi/mesh/benchmark_meshes.h>

#include "generator_arguments.h"

#include <algorithm>
#include <cmath>

namespace fvfsi
{
  using namespace dealii;
  using namespace internal;

  namespace
  {
    /// The cylindrical manifold about the x axis.
    CylindricalManifold<3> x_axis_manifold()
    {
      return CylindricalManifold<3>(Tensor<1, 3>({1., 0., 0.}), Point<3>());
    }
  } // namespace

  void make_tube_fluid(const std::string& arguments, Triangulation<3>& tria)
  {
    const std::string name = "fvfsi_tube_fluid";
    const auto x = numbers_of(name, arguments, 3, 3);
    const double R = length_of(name, x, 0), L = length_of(name, x, 1);
    GridGenerator::subdivided_cylinder(tria, count_of(name, x, 2), R, L / 2);
    GridTools::shift(Point<3>(L / 2, 0, 0), tria);
    // subdivided_cylinder colours the hull 0 and the ends 1 (x = 0 after the shift) and 2: the
    // patch ids of the header. Its hull manifold is about the x axis through the origin, which the
    // shift along x keeps; the cells get a transfinite interpolation of it, as hyper_ball's do.
    tria.set_all_manifold_ids(1);
    tria.set_all_manifold_ids_on_boundary(0, 0);
    tria.set_manifold(0, x_axis_manifold());
    TransfiniteInterpolationManifold<3> cells;
    cells.initialize(tria);
    tria.set_manifold(1, cells);
  }

  void make_tube_wall(const std::string& arguments, Triangulation<3>& tria)
  {
    const std::string name = "fvfsi_tube_wall";
    const auto x = numbers_of(name, arguments, 4, 4);
    const double R = length_of(name, x, 0), t = length_of(name, x, 1), L = length_of(name, x, 2);
    GridGenerator::cylinder_shell(tria, L, R, R + t, 4, count_of(name, x, 3));
    // cylinder_shell is built about the z axis from z = 0 to L: (x, y, z) -> (z, x, y) puts it
    // about the x axis (a cyclic permutation, so the cells keep their orientation), then a turn by
    // 45 degrees about x puts its vertices at the angles of fvfsi_tube_fluid's.
    const double c = std::cos(numbers::PI / 4), s = std::sin(numbers::PI / 4);
    GridTools::transform([c, s](const Point<3>& p)
                         { return Point<3>(p[2], c * p[0] - s * p[1], s * p[0] + c * p[1]); },
                         tria);
    // Every cell, face and line keeps manifold id 0: the shell is a box in (r, phi, x), and
    // its end faces are annulus sectors in the planes x = 0 and L, which the manifold keeps.
    // The coarse faces are chords of the circles (four round): a face is told by its vertices.
    const double tolerance = 1e-6 * t;
    for (const auto& face : tria.active_face_iterators())
      if (face->at_boundary())
      {
        double x_min = L, x_max = 0, r_max = 0;
        for (const unsigned int v : face->vertex_indices())
        {
          const Point<3>& p = face->vertex(v);
          x_min = std::min(x_min, p[0]);
          x_max = std::max(x_max, p[0]);
          r_max = std::max(r_max, std::hypot(p[1], p[2]));
        }
        face->set_boundary_id(x_max - x_min < tolerance ? 2 : r_max < R + t / 2 ? 0 : 1);
      }
    tria.set_manifold(0, x_axis_manifold());
  }
} // namespace fvfsi
