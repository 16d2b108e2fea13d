#include <deal.II/base/bounding_box.h>
#include <deal.II/numerics/rtree.h>

#include <fvfsi/coupling/vertex_projection.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fvfsi
{
  using namespace dealii;
  namespace bgi = boost::geometry::index;

  namespace
  {
    /// Barycentric weights of the point of segment [a, b] nearest to x.
    std::array<double, 2> nearest_on_segment(const Point<2>& x, const Point<2>& a,
                                             const Point<2>& b)
    {
      const Tensor<1, 2> ab = b - a;
      const double t = std::clamp((x - a) * ab / ab.norm_square(), 0.0, 1.0);
      return {{1 - t, t}};
    }

    /// Barycentric weights of the point of triangle (a, b, c) nearest to x (Ericson, Real-Time
    /// Collision Detection, section 5.1.5: the Voronoi regions of vertices, edges and face).
    std::array<double, 3> nearest_on_triangle(const Point<3>& x, const Point<3>& a,
                                              const Point<3>& b, const Point<3>& c)
    {
      const Tensor<1, 3> ab = b - a, ac = c - a, ap = x - a;
      const double d1 = ab * ap, d2 = ac * ap;
      if (d1 <= 0 && d2 <= 0)
        return {{1, 0, 0}};
      const Tensor<1, 3> bp = x - b;
      const double d3 = ab * bp, d4 = ac * bp;
      if (d3 >= 0 && d4 <= d3)
        return {{0, 1, 0}};
      const double vc = d1 * d4 - d3 * d2;
      if (vc <= 0 && d1 >= 0 && d3 <= 0)
      {
        const double v = d1 / (d1 - d3);
        return {{1 - v, v, 0}};
      }
      const Tensor<1, 3> cp = x - c;
      const double d5 = ab * cp, d6 = ac * cp;
      if (d6 >= 0 && d5 <= d6)
        return {{0, 0, 1}};
      const double vb = d5 * d2 - d1 * d6;
      if (vb <= 0 && d2 >= 0 && d6 <= 0)
      {
        const double w = d2 / (d2 - d6);
        return {{1 - w, 0, w}};
      }
      const double va = d3 * d6 - d5 * d4;
      if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
      {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {{0, 1 - w, w}};
      }
      const double denominator = 1 / (va + vb + vc);
      const double v = vb * denominator, w = vc * denominator;
      return {{1 - v - w, v, w}};
    }

    template <int dim>
    double box_distance(const BoundingBox<dim>& box, const Point<dim>& x)
    {
      double d2 = 0;
      for (unsigned int d = 0; d < dim; ++d)
      {
        const double e = std::max({box.lower_bound(d) - x[d], 0.0, x[d] - box.upper_bound(d)});
        d2 += e * e;
      }
      return std::sqrt(d2);
    }

    /// The pieces of the source surface: 2D each face (a segment); 3D each quadrilateral split
    /// into four triangles about the mean of its vertices.
    template <int dim>
    struct Piece
    {
      unsigned int face;
      unsigned int first; ///< 3D: the triangle (p_first, p_first+1, centre); 2D: 0
    };

    /// The nearest point of piece p (a segment in 2D, a triangle of the face about its centre c
    /// in 3D) to x, as weights w of the face's points; returns the distance.
    template <int dim>
    double project(const Point<dim>& x, const InterfaceZone<dim>& source, const Point<dim>& c,
                   const Piece<dim>& p, std::array<double, InterfaceZone<dim>::n_face_points>& w)
    {
      constexpr unsigned int n_face_points = InterfaceZone<dim>::n_face_points;
      const auto& corners = source.face_points[p.face];
      w.fill(0);
      if constexpr (dim == 2)
        w = nearest_on_segment(x, source.points[corners[0]], source.points[corners[1]]);
      else
      {
        const unsigned int i0 = p.first, i1 = (p.first + 1) % n_face_points;
        const auto b =
          nearest_on_triangle(x, source.points[corners[i0]], source.points[corners[i1]], c);
        for (unsigned int i = 0; i < n_face_points; ++i)
          w[i] = b[2] / n_face_points; // the centre's value is the mean of the vertex values
        w[i0] += b[0];
        w[i1] += b[1];
      }
      Point<dim> y;
      for (unsigned int i = 0; i < n_face_points; ++i)
        y += w[i] * source.points[corners[i]];
      return (x - y).norm();
    }
  } // namespace

  template <int dim>
  VertexProjection<dim>::VertexProjection(const InterfaceZone<dim>& source,
                                          const InterfaceZone<dim>& target)
      : face(target.n_points()), weight(target.n_points()), face_points(source.face_points)
  {
    std::vector<Piece<dim>> pieces;
    std::vector<BoundingBox<dim>> boxes;
    std::vector<Point<dim>> centre(source.n_faces());
    for (unsigned int f = 0; f < source.n_faces(); ++f)
    {
      for (const unsigned int i : source.face_points[f])
        centre[f] += source.points[i] / double(n_face_points);
      for (unsigned int first = 0; first < (dim == 2 ? 1 : n_face_points); ++first)
      {
        pieces.push_back({f, first});
        std::vector<Point<dim>> corners = {
          source.points[source.face_points[f][first]],
          source.points[source.face_points[f][(first + 1) % n_face_points]]};
        if (dim == 3)
          corners.push_back(centre[f]);
        boxes.emplace_back(corners);
      }
    }
    const auto tree = pack_rtree_of_indices(boxes);

    for (unsigned int i = 0; i < target.n_points(); ++i)
    {
      const Point<dim>& x = target.points[i];
      double best = std::numeric_limits<double>::max();
      // The k nearest boxes; more while a box not yet looked at could hold a nearer piece.
      for (unsigned int k = std::min<unsigned int>(8, pieces.size());;
           k = std::min<unsigned int>(2 * k, pieces.size()))
      {
        std::vector<unsigned int> candidates;
        for (const auto p : tree | bgi::adaptors::queried(bgi::nearest(x, k)))
          candidates.push_back(p);
        std::sort(candidates.begin(), candidates.end()); // ties: the lowest piece, on every rank
        double farthest_box = 0;
        for (const unsigned int p : candidates)
        {
          farthest_box = std::max(farthest_box, box_distance(boxes[p], x));
          std::array<double, n_face_points> w;
          const double distance = project(x, source, centre[pieces[p].face], pieces[p], w);
          if (distance < best - 1e-14 * (1 + best))
          {
            best = distance;
            face[i] = pieces[p].face;
            weight[i] = w;
          }
        }
        if (k == pieces.size() || farthest_box >= best)
          break;
      }
      gap = std::max(gap, best);
    }
  }

  template <int dim>
  InterfaceVector
  VertexProjection<dim>::interpolate(const std::vector<Tensor<1, dim>>& source_values) const
  {
    InterfaceVector target(dim * face.size());
    for (unsigned int i = 0; i < face.size(); ++i)
      for (unsigned int j = 0; j < n_face_points; ++j)
        for (unsigned int d = 0; d < dim; ++d)
          target[i * dim + d] += weight[i][j] * source_values[face_points[face[i]][j]][d];
    return target;
  }

  template class VertexProjection<2>;
  template class VertexProjection<3>;
} // namespace fvfsi
