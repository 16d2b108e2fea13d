// The meshes of the paper's "channel over a cavity with a flexible bottom" benchmark (section 4.2,
// geometry as solids4foam's cavityFlexibleBottom tutorial): the fluid domain (fvfsi_cavity_channel)
// and the elastic plate below the cavity (fvfsi_cavity_plate), both for a target cell size h.
//
// Fluid block layout (not to scale; h = 0.1 gives a = 0.2). The cavity's top corners (2, 0) and
// (6, 0) are rounded with radius r = 0.25 about C_L = (1.75, -0.25) and C_R = (6.25, -0.25); each
// rounded corner sits in an O-grid quadrant [1.75, 2 + a] x [-0.25, a] (mirrored on the right) of
// two ring blocks, A (arc from 90 to 45 degrees) and B (45 to 0 degrees), which meet on the
// diagonal from the arc's midpoint M to the quadrant's corner K = (2 + a, a):
//
//     1 +--------+-----+---------------------------+-----+-------------------------+
//       |  I1    | T_L |            T              | T_R |           O1            |
//     a +--------+-----K---------------------------K-----+-------------------------+
//       |  I0    | A  /|                           |\  A |           O0            |
//     0 +--------+-.M  |            Z              |  M.-+-------------------------+
//                    \B|                           |B/                             0 .. 14
// -0.25              +-+---------------------------+-+
//                    | |                           | |
//                    |W|            Q              |W|
//    -1              +-+---------------------------+-+
//                    2 2+a                       6-a 6
//
// I0, I1: inlet blocks; O0, O1: outlet blocks; T_L, T, T_R: above the quadrants and the middle
// block Z; W, Q: the cavity below y = -0.25. Every block is a Coons patch of its four edges (the
// arcs exact circle arcs, parametrised by angle), subdivided uniformly; blocks that share an edge
// share its subdivision, so merge_triangulations joins them conformingly. The cavity floor y = -1
// (the FSI interface) has n_a + n_mid + n_a = 4 / h cells of length exactly h, so its vertices are
// x = 2 + k h, those of the plate's top. The arc boundary faces carry manifold ids 1 (left corner)
// and 2 (right corner) with PolarManifolds about C_L and C_R, so that global refinement puts the
// new boundary vertices on the arcs.

#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <fvfsi/mesh/benchmark_meshes.h>

#include "block_mesh.h"

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    using namespace internal;

    /// The cell size h of `name`'s single argument; 4 / h (the cells along the cavity floor and
    /// the plate) must be an integer, and h <= 0.2.
    double cell_size(const std::string& name, const std::string& arguments)
    {
      const auto fail = [&]()
      {
        throw std::runtime_error(
          name +
          " needs one argument `h`, the target cell size [m] with "
          "4/h an integer and h <= 0.2 (e.g. 0.1, 0.05, 0.025, 0.0125), got `" +
          arguments + "`");
      };
      const auto items = Utilities::split_string_list(arguments, ':');
      if (items.size() != 1)
        fail();
      double h = 0;
      try
      {
        h = Utilities::string_to_double(items[0]);
      }
      catch (...)
      {
        fail();
      }
      const double n = 4 / h;
      if (!(h > 0 && h <= 0.2 + 1e-12) || std::abs(n - std::round(n)) > 1e-9 * n)
        fail();
      return h;
    }
  } // namespace

  void make_cavity_channel(const std::string& arguments, Triangulation<2>& tria)
  {
    const double h = cell_size("fvfsi_cavity_channel", arguments);
    // The function is one list of blocks (the drawing in the header comment, block by block):
    // longer than a screen, but it reads as the mesh's drawing.

    // Geometry [m].
    const double L = 14, H = 1, x_0 = 2, x_1 = 6, depth = 1, r = 0.25;
    const Point<2> C_L(x_0 - r, -r), C_R(x_1 + r, -r);
    const double q = numbers::PI / 4;

    // Subdivisions. The floor has n_floor cells of length h (exactly); the O-grid quadrants reach
    // a = n_a h (about 0.2) beyond the cavity walls and above the channel floor.
    const unsigned int n_floor = static_cast<unsigned int>(std::round(4 / h));
    const unsigned int n_a = std::max(1u, static_cast<unsigned int>(std::round(0.2 / h)));
    const double a = n_a * h;
    const unsigned int n_mid = n_floor - 2 * n_a;
    // Other edges: the fewest cells not longer than h. The quadrant sides (length r + a) and the
    // half arcs (length r pi / 4) share a subdivision: it is set by their mean length.
    const auto cells = [h](const double length)
    { return std::max(1u, static_cast<unsigned int>(std::ceil(length / h - 1e-6))); };
    const unsigned int n_arc = cells(((r + a) + r * q) / 2), n_up = cells(H - a),
                       n_cavity = cells(depth - r), n_in = cells(x_0 - r),
                       n_out = cells(L - x_1 - r);

    std::vector<std::unique_ptr<Triangulation<2>>> blocks;
    const auto add = [&](const Curve& b, const Curve& t, const Curve& l, const Curve& rt,
                         unsigned int n_s, unsigned int n_t)
    {
      blocks.push_back(std::make_unique<Triangulation<2>>());
      make_block(*blocks.back(), b, t, l, rt, n_s, n_t);
    };
    const auto rectangle =
      [&](double x0, double x1, double y0, double y1, unsigned int n_x, unsigned int n_y)
    {
      add(line({x0, y0}, {x1, y0}), line({x0, y1}, {x1, y1}), line({x0, y0}, {x0, y1}),
          line({x1, y0}, {x1, y1}), n_x, n_y);
    };

    // Left corner: ring blocks A (90 -> 45 degrees) and B (45 -> 0 degrees).
    {
      const Point<2> P1(x_0 - r, 0), P2(x_0, -r), M = arc(C_L, r, q, q)(0), K(x_0 + a, a);
      add(arc(C_L, r, 2 * q, q), line({x_0 - r, a}, K), line(P1, {x_0 - r, a}), line(M, K), n_arc,
          n_a);
      add(arc(C_L, r, q, 0), line(K, {x_0 + a, -r}), line(M, K), line(P2, {x_0 + a, -r}), n_arc,
          n_a);
    }
    // Right corner (mirrored): A (90 -> 135 degrees) and B (135 -> 180 degrees).
    {
      const Point<2> P1(x_1 + r, 0), P2(x_1, -r), M = arc(C_R, r, 3 * q, 3 * q)(0), K(x_1 - a, a);
      add(arc(C_R, r, 2 * q, 3 * q), line({x_1 + r, a}, K), line(P1, {x_1 + r, a}), line(M, K),
          n_arc, n_a);
      add(arc(C_R, r, 3 * q, 4 * q), line(K, {x_1 - a, -r}), line(M, K), line(P2, {x_1 - a, -r}),
          n_arc, n_a);
    }
    // Inlet and outlet blocks.
    rectangle(0, x_0 - r, 0, a, n_in, n_a);
    rectangle(0, x_0 - r, a, H, n_in, n_up);
    rectangle(x_1 + r, L, 0, a, n_out, n_a);
    rectangle(x_1 + r, L, a, H, n_out, n_up);
    // Above the quadrants and the middle block.
    rectangle(x_0 - r, x_0 + a, a, H, n_arc, n_up);
    rectangle(x_0 + a, x_1 - a, a, H, n_mid, n_up);
    rectangle(x_1 - a, x_1 + r, a, H, n_arc, n_up);
    rectangle(x_0 + a, x_1 - a, -r, a, n_mid, n_arc);
    // The cavity below y = -r.
    rectangle(x_0, x_0 + a, -depth, -r, n_a, n_cavity);
    rectangle(x_0 + a, x_1 - a, -depth, -r, n_mid, n_cavity);
    rectangle(x_1 - a, x_1, -depth, -r, n_a, n_cavity);

    std::vector<const Triangulation<2>*> pointers;
    for (const auto& b : blocks)
      pointers.push_back(b.get());
    GridGenerator::merge_triangulations(pointers, tria, 1e-9);

    // Patches: 0 inlet, 1 outlet, 2 walls, 3 interface (cavity floor). Arc faces: manifolds 1, 2.
    const double tol = 1e-9;
    const auto on_circle = [&](const Point<2>& p, const Point<2>& c)
    { return std::abs(p.distance(c) - r) < tol; };
    for (const auto& face : tria.active_face_iterators())
      if (face->at_boundary())
      {
        const Point<2> c = face->center();
        face->set_boundary_id(std::abs(c[0]) < tol           ? 0
                              : std::abs(c[0] - L) < tol     ? 1
                              : std::abs(c[1] + depth) < tol ? 3
                                                             : 2);
        for (const unsigned int k : {1u, 2u})
        {
          const Point<2>& centre = k == 1 ? C_L : C_R;
          if (on_circle(face->vertex(0), centre) && on_circle(face->vertex(1), centre))
            face->set_manifold_id(k);
        }
      }
    tria.set_manifold(1, PolarManifold<2>(C_L));
    tria.set_manifold(2, PolarManifold<2>(C_R));
  }

  void make_cavity_plate(const std::string& arguments, Triangulation<2>& tria)
  {
    // "h" (uniform) or "h: beta" (graded): the cells keep their count, (4/h) x max(2, 0.4/h), and
    // with beta > 1 shrink towards the clamped ends and both surfaces. The map
    // s -> sign(s) (1 - (1 - |s|)^beta) of s in [-1, 1] (across the length and the thickness)
    // makes the end cells Delta_s^beta of the half-length (half-thickness) long, Delta_s the
    // uniform step in s: a grading for the stress singularities at the four corners where the
    // clamped ends meet the surfaces (cavity.md).
    const auto items = Utilities::split_string_list(arguments, ':');
    double beta = 1;
    if (items.size() == 2)
    {
      try
      {
        beta = Utilities::string_to_double(items[1]);
      }
      catch (...)
      {
        beta = 0;
      }
    }
    if (items.size() > 2 || !(beta >= 1 && beta <= 3))
      throw std::runtime_error("fvfsi_cavity_plate needs `h` or `h: beta` with the grading "
                               "exponent 1 <= beta <= 3 (1: uniform), got `" +
                               arguments + "`");
    const double h = cell_size("fvfsi_cavity_plate", items.empty() ? "" : items[0]);
    const unsigned int n_x = static_cast<unsigned int>(std::round(4 / h));
    const unsigned int n_y = std::max(2u, static_cast<unsigned int>(std::round(0.4 / h)));
    GridGenerator::subdivided_hyper_rectangle(tria, {n_x, n_y}, Point<2>(2, -1.4), Point<2>(6, -1),
                                              true);
    if (beta != 1)
    {
      const auto graded = [beta](const double s)
      { return (s < 0 ? -1 : 1) * (1 - std::pow(1 - std::abs(s), beta)); };
      GridTools::transform(
        [&](const Point<2>& p) {
          return Point<2>(4 + 2 * graded((p[0] - 4) / 2), -1.2 + 0.2 * graded((p[1] + 1.2) / 0.2));
        },
        tria);
    }
    // colorize: 0 x = 2, 1 x = 6, 2 y = -1.4, 3 y = -1 -> 0 clamped, 1 bottom, 2 interface.
    for (const auto& face : tria.active_face_iterators())
      if (face->at_boundary())
        face->set_boundary_id(face->boundary_id() <= 1 ? 0 : face->boundary_id() - 1);
  }
} // namespace fvfsi
