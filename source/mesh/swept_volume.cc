// Volumes swept by moving faces (FVGeometry::swept_volumes), the mesh fluxes of the ALE fluid.
//
// The region a face sweeps is closed by its old and new surfaces and by the surfaces its edges
// trace (3D: ruled bilinear patches; 2D: the straight paths of its two end points). Its volume is
// (1/dim) times the outward flux of the position vector x through that closed surface (divergence
// theorem, div x = dim). The old and new surfaces are integrated over the same pieces as the
// cell volumes in fv_geometry.cc, and each edge surface appears in the two faces of a cell that
// share the edge with opposite orientations. Summed over the faces of a cell, the edge terms then
// cancel and what is left is (1/dim) (flux through the new cell surface - flux through the old),
// i.e. V_P(new) - V_P(old) exactly as FVGeometry computes them.

#include <fvfsi/mesh/fv_geometry.h>

#include "face_pieces.h"

#include <array>
#include <cmath>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    /// Flux of x through the face pieces: sum_t S_t . r_t (exact, x is linear on a piece).
    template <int dim, typename Polygon>
    double position_flux(const Polygon& polygon, const std::vector<Point<dim>>& x)
    {
      const auto pieces = internal::decompose<dim>(polygon, x);
      double flux = 0;
      for (unsigned int t = 0; t < pieces.n; ++t)
        flux += pieces.S[t] * pieces.r[t];
      return flux;
    }

    /// 2D: flux of x through the path of end point a (a -> a'), with the normal of the edge's
    /// tangent rotated by +90 degrees; added for the face's end vertex, subtracted for its start.
    double path_flux(const Point<2>& a, const Point<2>& a_new)
    {
      const Tensor<1, 2> t = a_new - a;
      return Tensor<1, 2>({-t[1], t[0]}) * (a + a_new) / 2;
    }

    /// 3D: flux of x through the bilinear patch x(s, t) = (1-t)((1-s) a + s b) + t((1-s) a' + s b')
    /// traced by the edge a -> b, normal x_s x x_t. The integrand is of degree 2 in s and in t, so
    /// 2 x 2 Gauss points integrate it exactly; swapping a and b flips the sign.
    double patch_flux(const Point<3>& a, const Point<3>& b, const Point<3>& a_new,
                      const Point<3>& b_new)
    {
      const double g = 0.5 / std::sqrt(3.0);
      const std::array<double, 2> q = {{0.5 - g, 0.5 + g}};
      double flux = 0;
      for (const double s : q)
        for (const double t : q)
        {
          const Tensor<1, 3> x =
            (1 - t) * ((1 - s) * a + s * b) + t * ((1 - s) * a_new + s * b_new);
          const Tensor<1, 3> x_s = (1 - t) * (b - a) + t * (b_new - a_new);
          const Tensor<1, 3> x_t = (1 - s) * (a_new - a) + s * (b_new - b);
          flux += 0.25 * (x * cross_product_3d(x_s, x_t));
        }
      return flux;
    }
  } // namespace

  template <int dim>
  std::vector<double> FVGeometry<dim>::swept_volumes(const std::vector<Point<dim>>& old_x,
                                                     const std::vector<Point<dim>>& new_x) const
  {
    // Positions relative to the face's first old vertex: the swept volume does not depend on the
    // origin (its surface is closed), and a local one keeps the round-off relative to the face.
    constexpr unsigned int nv = FaceGeometry<dim>::max_vertices;
    std::array<unsigned int, nv> polygon;
    for (unsigned int i = 0; i < nv; ++i)
      polygon[i] = i;
    std::vector<Point<dim>> x(nv), y(nv); // old, new
    std::vector<double> dV(faces.size(), 0.0);
    for (unsigned int f = 0; f < faces.size(); ++f)
    {
      const auto& v = faces[f].vertices;
      const Point<dim> origin = old_x[v[0]];
      for (unsigned int i = 0; i < nv; ++i)
      {
        x[i] = Point<dim>(old_x[v[i]] - origin);
        y[i] = Point<dim>(new_x[v[i]] - origin);
      }
      double flux = position_flux<dim>(polygon, y) - position_flux<dim>(polygon, x);
      if constexpr (dim == 2)
        flux += path_flux(x[1], y[1]) - path_flux(x[0], y[0]);
      else
        for (unsigned int i = 0; i < nv; ++i)
        {
          const unsigned int j = (i + 1) % nv;
          flux += patch_flux(x[i], x[j], y[i], y[j]);
        }
      dV[f] = flux / dim;
    }
    return dV;
  }

  template std::vector<double> FVGeometry<2>::swept_volumes(const std::vector<Point<2>>&,
                                                            const std::vector<Point<2>>&) const;
  template std::vector<double> FVGeometry<3>::swept_volumes(const std::vector<Point<3>>&,
                                                            const std::vector<Point<3>>&) const;
} // namespace fvfsi
