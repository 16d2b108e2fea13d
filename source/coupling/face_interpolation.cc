#include <deal.II/base/bounding_box.h>
#include <deal.II/numerics/rtree.h>

#include <fvfsi/coupling/face_interpolation.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;
  namespace bgi = boost::geometry::index;

  namespace
  {
    template <int dim>
    BoundingBox<dim> face_box(const InterfaceZone<dim>& zone, const unsigned int f)
    {
      std::vector<Point<dim>> corners;
      for (const unsigned int i : zone.face_points[f])
        corners.push_back(zone.points[i]);
      return BoundingBox<dim>(corners);
    }

    /// Overlap length of source segment k with target segment j, along the line of j.
    double overlap(const InterfaceZone<2>& target, const unsigned int j,
                   const InterfaceZone<2>& source, const unsigned int k)
    {
      const Point<2>& a = target.points[target.face_points[j][0]];
      const Tensor<1, 2> t = (target.points[target.face_points[j][1]] - a) / target.face_area[j];
      const double s0 = (source.points[source.face_points[k][0]] - a) * t,
                   s1 = (source.points[source.face_points[k][1]] - a) * t;
      return std::max(0.0, std::min(target.face_area[j], std::max(s0, s1)) -
                             std::max(0.0, std::min(s0, s1)));
    }

    using Polygon = std::vector<std::array<double, 2>>;

    double signed_area(const Polygon& p)
    {
      double a = 0;
      for (unsigned int i = 0; i < p.size(); ++i)
      {
        const auto &u = p[i], &v = p[(i + 1) % p.size()];
        a += u[0] * v[1] - v[0] * u[1];
      }
      return a / 2;
    }

    /// Sutherland-Hodgman: the part of `subject` inside the convex, counter-clockwise `clip`.
    Polygon clip_polygon(Polygon subject, const Polygon& clip)
    {
      for (unsigned int e = 0; e < clip.size() && !subject.empty(); ++e)
      {
        const auto &a = clip[e], &b = clip[(e + 1) % clip.size()];
        // Signed distance-like measure: > 0 left of a->b (inside).
        const auto side = [&](const std::array<double, 2>& x)
        { return (b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0]); };
        Polygon result;
        for (unsigned int i = 0; i < subject.size(); ++i)
        {
          const auto &p = subject[i], &q = subject[(i + 1) % subject.size()];
          const double sp = side(p), sq = side(q);
          if (sp >= 0)
            result.push_back(p);
          if ((sp >= 0) != (sq >= 0))
          {
            const double t = sp / (sp - sq);
            result.push_back({{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}});
          }
        }
        subject = std::move(result);
      }
      return subject;
    }

    /// Area of the intersection of source face k with target face j, both projected on the
    /// plane of j (Sutherland-Hodgman clipping of convex polygons, as in the paper).
    double overlap(const InterfaceZone<3>& target, const unsigned int j,
                   const InterfaceZone<3>& source, const unsigned int k)
    {
      // An orthonormal basis (e1, e2) of the plane of j, counter-clockwise about n_j.
      const Tensor<1, 3>& n = target.face_normal[j];
      Tensor<1, 3> e1 =
        target.points[target.face_points[j][1]] - target.points[target.face_points[j][0]];
      e1 -= (e1 * n) * n;
      e1 /= e1.norm();
      const Tensor<1, 3> e2 = cross_product_3d(n, e1);
      const Point<3>& origin = target.face_centre[j];
      const auto polygon = [&](const InterfaceZone<3>& zone, const unsigned int f)
      {
        Polygon p;
        for (const unsigned int i : zone.face_points[f])
          p.push_back({{(zone.points[i] - origin) * e1, (zone.points[i] - origin) * e2}});
        if (signed_area(p) < 0) // a face of the other side: its normal points the other way
          std::reverse(p.begin(), p.end());
        return p;
      };
      const Polygon piece = clip_polygon(polygon(source, k), polygon(target, j));
      return piece.size() < 3 ? 0.0 : std::abs(signed_area(piece));
    }
  } // namespace

  template <int dim>
  FaceInterpolation<dim>::FaceInterpolation(const InterfaceZone<dim>& source,
                                            const InterfaceZone<dim>& target)
      : weight(target.n_faces())
  {
    std::vector<BoundingBox<dim>> boxes;
    for (unsigned int k = 0; k < source.n_faces(); ++k)
      boxes.push_back(face_box(source, k));
    const auto tree = pack_rtree_of_indices(boxes);

    for (unsigned int j = 0; j < target.n_faces(); ++j)
    {
      // Size of face j: its longest extent; candidates within half of it.
      BoundingBox<dim> box = face_box(target, j);
      double size = 0;
      for (unsigned int d = 0; d < dim; ++d)
        size = std::max(size, box.side_length(d));
      box.extend(0.5 * size);
      std::vector<unsigned int> candidates;
      for (const auto k : tree | bgi::adaptors::queried(bgi::intersects(box)))
        candidates.push_back(k);
      std::sort(candidates.begin(), candidates.end()); // a fixed summation order
      for (const unsigned int k : candidates)
      {
        // The two sides face each other: out of the solid is into the fluid, so their outward
        // normals point against each other. A surface parallel to the interface faces the same
        // way (the far side of a thin flag or wall, within half a face size on a coarse mesh)
        // and is never taken for it.
        if (target.face_normal[j] * source.face_normal[k] > -0.5 ||
            std::abs((source.face_centre[k] - target.face_centre[j]) * target.face_normal[j]) >
              0.5 * size)
          continue;
        const double w = overlap(target, j, source, k) / target.face_area[j];
        if (w > 1e-12)
          weight[j].emplace_back(k, w);
      }
      if (weight[j].empty())
        throw std::runtime_error(
          "Interface " + target.name + ": the face at centre (" +
          Utilities::to_string(target.face_centre[j][0]) + ", " +
          Utilities::to_string(target.face_centre[j][1]) +
          (dim == 3 ? ", " + Utilities::to_string(target.face_centre[j][2]) : std::string()) +
          ") m overlaps no face of " + source.name +
          " that faces it (outward normals against each other): do the two interface patches "
          "describe the same surface, seen from its two sides?");
    }
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  FaceInterpolation<dim>::interpolate(const std::vector<Tensor<1, dim>>& source_values) const
  {
    std::vector<Tensor<1, dim>> target(weight.size());
    for (unsigned int j = 0; j < weight.size(); ++j)
      for (const auto& [k, w] : weight[j])
        target[j] += w * source_values[k];
    return target;
  }

  template <int dim>
  double FaceInterpolation<dim>::coverage(const unsigned int j) const
  {
    double sum = 0;
    for (const auto& [k, w] : weight[j])
      sum += w;
    return sum;
  }

  template <int dim>
  std::pair<double, double> FaceInterpolation<dim>::coverage_range() const
  {
    std::pair<double, double> range(1e300, 0);
    for (unsigned int j = 0; j < weight.size(); ++j)
      range = {std::min(range.first, coverage(j)), std::max(range.second, coverage(j))};
    return range;
  }

  template class FaceInterpolation<2>;
  template class FaceInterpolation<3>;
} // namespace fvfsi
