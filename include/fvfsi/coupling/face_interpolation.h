#pragma once
// Face interpolation between two sides of the interface (paper section 3.5.1, Eqs 32-33; the
// GGI of Beaudoin and Jasak): a target face j takes
//
//   phi_j = sum_k w_jk phi_k,    w_jk = |S_j  intersected with  S_k| / |S_j|,          (32-33)
//
// summed over the source faces k that overlap j. The overlap is measured in the plane of face j
// (2D: the overlap of two segments along the line of j; 3D: the area of the intersection of the
// two projected convex polygons, by Sutherland-Hodgman clipping as in the paper; Boost.Geometry's
// polygon intersection was tried and loses ~1e-7 of the area to its integer rescaling). Candidates come from an R-tree of the source
// faces' bounding boxes (the paper's axis-aligned bounding-box rejection test).
//
// Conservative for forces: where the source faces are covered by the target faces, the target
// force sum_j S_j t_j equals the source force sum_k S_k t_k (sum_j |S_j cap S_k| = S_k).
// coverage(j) = sum_k w_jk is 1 for a target face that the source side covers.

#include <deal.II/base/tensor.h>

#include <fvfsi/coupling/interface_zone.h>

#include <utility>
#include <vector>

namespace fvfsi
{
  template <int dim>
  class FaceInterpolation
  {
  public:
    /// Weights from the zones' geometry (collective only in that every rank does the same).
    /// A source face counts for a target face if it faces it (outward normals against each
    /// other: n_j . n_k < -0.5, as the fluid's and the solid's are at their common surface) and
    /// its centre lies within half the target face's size of the target plane. Throws if a
    /// target face has no source face, naming both zones.
    FaceInterpolation(const InterfaceZone<dim>& source, const InterfaceZone<dim>& target);

    /// Eq. 32 for every target face.
    std::vector<dealii::Tensor<1, dim>>
    interpolate(const std::vector<dealii::Tensor<1, dim>>& source_values) const;

    /// sum_k w_jk of target face j (1: fully covered by the source side).
    double coverage(unsigned int j) const;
    /// The least and the largest coverage(j) over the target faces (1 and 1 where the two sides
    /// match; a curved surface faceted differently on the two sides: within a few per cent).
    std::pair<double, double> coverage_range() const;
    /// (source face k, w_jk) of target face j.
    const std::vector<std::pair<unsigned int, double>>& weights(const unsigned int j) const
    {
      return weight[j];
    }

  private:
    std::vector<std::vector<std::pair<unsigned int, double>>> weight;
  };
} // namespace fvfsi
