#pragma once
// Boundary-face values of a ghost cell, copied from the rank that owns the cell: what a rank
// computes on the boundary faces of its owned cells becomes visible on the ghost_boundary faces
// of its neighbours (needed where a boundary value depends on vertex data a neighbour lacks).

#include <fvfsi/mesh/fv_geometry.h>

#include <vector>

namespace fvfsi
{
  /// `values` is indexed like FVGeometry::faces; T is double or a dealii::Tensor of doubles.
  template <int dim, typename T>
  void update_ghost_boundary_faces(const FVGeometry<dim>& geometry, std::vector<T>& values)
  {
    geometry.boundary_face_exchange().update(values);
  }
} // namespace fvfsi
