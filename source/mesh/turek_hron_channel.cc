// The fluid domain of the Turek-Hron benchmarks (CFD, FSI): the channel [0, 2.5] x [0, 0.41]
// without the cylinder (centre (0.2, 0.2), radius 0.05) and the flag (y in [0.19, 0.21], from the
// cylinder to x = 0.6), as a block-structured quadrilateral mesh built at full resolution.
//
// Block layout (not to scale); R = the cylinder, F = the flag (not meshed):
//
//   0.41 +-----+-------+----------------+-----------------------------------+
//        | L3  |  A    |      U3        |                D3                 |
//   0.30 +-----+-------+----------------+-----------------------------------+
//        |     | ring  |      U2        |                D2                 |
//   0.21 | L2  |  /R\  |FFFFFFFFFFFFFFFF+-----------------------------------+ D1 (behind
//   0.19 |     |  \_/  |FFFFFFFFFFFFFFFF+-----------------------------------+    the flag)
//        |     | ring  |      U1        |                D0                 |
//   0.10 +-----+-------+----------------+-----------------------------------+
//        | L1  |  B    |      U0        |             (D-1)                 |
//   0.00 +-----+-------+----------------+-----------------------------------+
//        0    0.1     0.3              0.6                                  2.5
//
// The square [0.1, 0.3]^2 around the cylinder is an O-grid of six blocks between the circle and
// the square's sides: top, left, bottom (90 degrees of arc each) and, on the right, one block above
// and one below the flag (from the flag's corner on the circle to 45 degrees). Every block is a
// Coons patch of its four edges (arcs are exact circle arcs), subdivided n_s x n_t times, with
// geometric grading towards the cylinder (ring blocks) and downstream (D blocks); blocks that share
// an edge share its subdivision, so merge_triangulations joins them conformingly.

#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

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

    /// Patches: 0 inlet (x = 0), 1 outlet (x = L), 2 channel walls (y = 0, H), 3 cylinder (the
    /// circle of radius R about C), 4 flag.
    void set_channel_patches(Triangulation<2>& tria, const Point<2>& C, const double R,
                             const double L, const double H)
    {
      const double tol = 1e-9;
      const auto on_circle = [&](const Point<2>& p) { return std::abs(p.distance(C) - R) < tol; };
      for (const auto& face : tria.active_face_iterators())
        if (face->at_boundary())
        {
          const Point<2> c = face->center();
          face->set_boundary_id(std::abs(c[0]) < tol                                       ? 0
                                : std::abs(c[0] - L) < tol                                 ? 1
                                : std::abs(c[1]) < tol || std::abs(c[1] - H) < tol         ? 2
                                : on_circle(face->vertex(0)) && on_circle(face->vertex(1)) ? 3
                                                                                           : 4);
        }
    }
  } // namespace

  void make_turek_hron_channel(const std::string& arguments, Triangulation<2>& tria)
  {
    std::vector<double> x;
    for (const auto& s : Utilities::split_string_list(arguments, ':'))
      x.push_back(Utilities::string_to_double(s));
    if (x.empty() || x.size() > 2 || !(x[0] >= 4 && x[0] <= 2000))
      throw std::runtime_error("fvfsi_turek_hron_channel needs `n[: grading]` with 4 <= n <= 2000 "
                               "(cells on a quarter of the cylinder), got `" +
                               arguments + "`");
    const unsigned int n = static_cast<unsigned int>(x[0]);
    const double beta = x.size() > 1 ? x[1] : 1.5; // radial grading towards the cylinder
    // The function is one list of blocks (rings about the cylinder, rectangles around the flag
    // and downstream): longer than a screen, but it reads as the mesh's drawing.

    // Geometry [m].
    const Point<2> C(0.2, 0.2);
    const double R = 0.05, L = 2.5, H = 0.41, x_tip = 0.6, y_lo = 0.19, y_hi = 0.21;
    const double flag_angle = std::asin(0.01 / R), q = numbers::PI / 4;
    const double box_lo = 0.1, box_hi = 0.3;

    // Subdivisions: the cell size on the box sides, h = 0.2 / n, sets the rest.
    const double h = (box_hi - box_lo) / n;
    const auto cells = [h](const double length)
    { return std::max(1u, static_cast<unsigned int>(std::round(length / h))); };
    const unsigned int n_radial = std::max(2u, n / 2), n_side = cells(y_lo - box_lo),
                       n_flag = std::max(2u, cells(y_hi - y_lo)), n_left = cells(box_lo),
                       n_bottom = cells(box_lo), n_top = cells(H - box_hi),
                       n_along = cells(x_tip - box_hi);
    // Downstream: the first cell about h long, spacing growing geometrically (by e^2 in all)
    // towards the outlet.
    const double beta_down = 2.0, length_down = L - x_tip;
    unsigned int n_downstream = 4;
    while (length_down * graded(1.0 / n_downstream, beta_down) > h)
      ++n_downstream;

    std::vector<std::unique_ptr<Triangulation<2>>> blocks;
    const auto add = [&](const Curve& b, const Curve& t, const Curve& l, const Curve& r,
                         unsigned int n_s, unsigned int n_t, double beta_s, double beta_t)
    {
      blocks.push_back(std::make_unique<Triangulation<2>>());
      make_block(*blocks.back(), b, t, l, r, n_s, n_t, beta_s, beta_t);
    };
    // Ring blocks: s along the arc, t from the circle (t = 0) to the square (t = 1). The grading
    // in t makes the cells next to the cylinder thinner.
    const auto ring = [&](double a0, double a1, Point<2> p0, Point<2> p1, unsigned int n_s)
    {
      add(arc(C, R, a0, a1), line(p0, p1), line(arc(C, R, a0, a1)(0), p0),
          line(arc(C, R, a0, a1)(1), p1), n_s, n_radial, 0, beta);
    };
    const Point<2> b00(box_lo, box_lo), b10(box_hi, box_lo), b01(box_lo, box_hi),
      b11(box_hi, box_hi);
    ring(q, 3 * q, b11, b01, n);                                // top
    ring(3 * q, 5 * q, b01, b00, n);                            // left
    ring(5 * q, 7 * q, b00, b10, n);                            // bottom
    ring(flag_angle, q, Point<2>(box_hi, y_hi), b11, n_side);   // right, above the flag
    ring(-q, -flag_angle, b10, Point<2>(box_hi, y_lo), n_side); // right, below the flag

    // Straight blocks [x0, x1] x [y0, y1] with n_x x n_y cells.
    const auto rectangle = [&](double x0, double x1, double y0, double y1, unsigned int n_x,
                               unsigned int n_y, double beta_x)
    {
      add(line({x0, y0}, {x1, y0}), line({x0, y1}, {x1, y1}), line({x0, y0}, {x0, y1}),
          line({x1, y0}, {x1, y1}), n_x, n_y, beta_x, 0);
    };
    // Left of the square.
    rectangle(0, box_lo, 0, box_lo, n_left, n_bottom, 0);
    rectangle(0, box_lo, box_lo, box_hi, n_left, n, 0);
    rectangle(0, box_lo, box_hi, H, n_left, n_top, 0);
    // Below and above the square.
    rectangle(box_lo, box_hi, 0, box_lo, n, n_bottom, 0);
    rectangle(box_lo, box_hi, box_hi, H, n, n_top, 0);
    // Along the flag.
    rectangle(box_hi, x_tip, 0, box_lo, n_along, n_bottom, 0);
    rectangle(box_hi, x_tip, box_lo, y_lo, n_along, n_side, 0);
    rectangle(box_hi, x_tip, y_hi, box_hi, n_along, n_side, 0);
    rectangle(box_hi, x_tip, box_hi, H, n_along, n_top, 0);
    // Downstream, graded towards the outlet.
    const double ys[] = {0, box_lo, y_lo, y_hi, box_hi, H};
    const unsigned int ns[] = {n_bottom, n_side, n_flag, n_side, n_top};
    for (unsigned int k = 0; k < 5; ++k)
      rectangle(x_tip, L, ys[k], ys[k + 1], n_downstream, ns[k], beta_down);

    std::vector<const Triangulation<2>*> pointers;
    for (const auto& b : blocks)
      pointers.push_back(b.get());
    GridGenerator::merge_triangulations(pointers, tria, 1e-9);

    set_channel_patches(tria, C, R, L, H);
  }
} // namespace fvfsi
