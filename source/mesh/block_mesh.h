#pragma once
// Block-structured 2D meshes, for fvfsi's own benchmark generators (turek_hron_channel.cc,
// cavity_meshes.cc): a block is the Coons patch of four edge curves, subdivided n_s x n_t times,
// optionally graded; blocks that share an edge share its subdivision, so
// GridGenerator::merge_triangulations joins them conformingly.

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <functional>

namespace fvfsi::internal
{
  using namespace dealii;

  using Curve = std::function<Point<2>(double)>; // s in [0, 1] -> point

  inline Curve line(const Point<2>& a, const Point<2>& b)
  {
    return [a, b](const double s) { return Point<2>(a + s * (b - a)); };
  }

  inline Curve arc(const Point<2>& centre, const double radius, const double angle_0,
                   const double angle_1)
  {
    return [=](const double s)
    {
      const double phi = angle_0 + s * (angle_1 - angle_0);
      return Point<2>(centre[0] + radius * std::cos(phi), centre[1] + radius * std::sin(phi));
    };
  }

  /// x in [0, 1] -> [0, 1], spacing growing by the factor exp(beta / n) from cell to cell.
  inline double graded(const double x, const double beta)
  {
    return std::abs(beta) < 1e-12 ? x : std::expm1(beta * x) / std::expm1(beta);
  }

  /// A block with edges bottom(s), top(s) (t = 0, 1) and left(t), right(t) (s = 0, 1), n_s x n_t
  /// cells, grading beta_s, beta_t. Orientation is fixed so that cells are not inverted.
  inline void make_block(Triangulation<2>& block, const Curve& bottom, const Curve& top,
                         const Curve& left, const Curve& right, const unsigned int n_s,
                         const unsigned int n_t, const double beta_s = 0, const double beta_t = 0)
  {
    const auto coons = [&](const double s, const double t)
    {
      return Point<2>((1 - t) * bottom(s) + t * top(s) + (1 - s) * left(t) + s * right(t) -
                      ((1 - s) * (1 - t) * bottom(0) + s * (1 - t) * bottom(1) +
                       (1 - s) * t * top(0) + s * t * top(1)));
    };
    const Tensor<1, 2> d_s = coons(0.51, 0.5) - coons(0.49, 0.5);
    const Tensor<1, 2> d_t = coons(0.5, 0.51) - coons(0.5, 0.49);
    const bool flip = d_s[0] * d_t[1] - d_s[1] * d_t[0] < 0;
    GridGenerator::subdivided_hyper_rectangle(block, {n_s, n_t}, Point<2>(0, 0), Point<2>(1, 1));
    GridTools::transform(
      [&](const Point<2>& p)
      {
        const double s = graded(flip ? 1 - p[0] : p[0], beta_s), t = graded(p[1], beta_t);
        return coons(s, t);
      },
      block);
  }
} // namespace fvfsi::internal
