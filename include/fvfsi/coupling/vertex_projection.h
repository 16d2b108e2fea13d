#pragma once
// Vertex interpolation from one side of the interface to the points of the other (paper section
// 3.5.2): the source faces are split into triangles about an extra central point (whose value is
// the mean of the face's vertex values; in 2D the faces are segments already), every target point
// is projected to the nearest triangle, and its value is the linear interpolation of the
// triangle's values at the projection. Exact for linear fields wherever the target points lie on
// the source surface. The nearest triangle is found through an R-tree of the triangles' bounding
// boxes, searched in order of box distance until no nearer triangle can remain.

#include <deal.II/base/tensor.h>

#include <fvfsi/coupling/interface_zone.h>

#include <array>
#include <vector>

namespace fvfsi
{
  template <int dim>
  class VertexProjection
  {
  public:
    VertexProjection(const InterfaceZone<dim>& source, const InterfaceZone<dim>& target);

    /// The target point field (an interface vector of the target zone) from the source point
    /// field.
    InterfaceVector interpolate(const std::vector<dealii::Tensor<1, dim>>& source_values) const;

    /// The largest distance between a target point and its projection [m]: the geometric gap
    /// between the two discretised surfaces.
    double max_gap() const { return gap; }

  private:
    static constexpr unsigned int n_face_points = InterfaceZone<dim>::n_face_points;
    /// Per target point: the source face and the weights of that face's points.
    std::vector<unsigned int> face;
    std::vector<std::array<double, n_face_points>> weight;
    std::vector<std::array<unsigned int, n_face_points>> face_points;
    double gap = 0;
  };
} // namespace fvfsi
