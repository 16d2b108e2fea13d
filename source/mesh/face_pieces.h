#pragma once
// The decomposition of a face into the pieces that FVGeometry integrates over (Eq. 38, Appendix A):
// the segment itself in 2D, four triangles about the vertex average in 3D. Shared by the geometry
// (fv_geometry.cc) and the swept volumes (swept_volume.cc), which must use the same pieces for the
// space conservation law to hold to round-off.

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <vector>

namespace fvfsi::internal
{
  using dealii::Point;
  using dealii::Tensor;

  constexpr double third = 1.0 / 3.0;

  /// The pieces of a face the geometry is built from: segments (2D) or triangles (c, p_i, p_i+1)
  /// about the vertex average c (3D, Appendix A). Each has an area vector and a centroid.
  template <int dim>
  struct FacePieces
  {
    static constexpr unsigned int n = dim == 2 ? 1 : 4;
    std::array<Tensor<1, dim>, n> S;
    std::array<Point<dim>, n> r;
  };

  template <int dim, typename Polygon>
  FacePieces<dim> decompose(const Polygon& polygon, const std::vector<Point<dim>>& x)
  {
    FacePieces<dim> pieces;
    if constexpr (dim == 2)
    {
      const Tensor<1, 2> t = x[polygon[1]] - x[polygon[0]];
      pieces.S[0] = Tensor<1, 2>({t[1], -t[0]});
      pieces.r[0] = Point<2>((x[polygon[0]] + x[polygon[1]]) / 2);
    }
    else
    {
      Point<dim> c;
      for (const unsigned int v : polygon)
        c += x[v] / double(polygon.size());
      for (unsigned int i = 0; i < 4; ++i)
      {
        const Point<dim>&a = x[polygon[i]], &b = x[polygon[(i + 1) % 4]];
        pieces.S[i] = 0.5 * dealii::cross_product_3d(a - c, b - c);
        pieces.r[i] = Point<dim>((c + a + b) * third);
      }
    }
    return pieces;
  }
} // namespace fvfsi::internal
