#pragma once
// A cell-centred gradient field: one Tensor<1,dim> per locally owned and ghost cell.

#include <fvfsi/mesh/fv_geometry.h>

#include <array>

namespace fvfsi
{
  template <int dim>
  class CellGradient
  {
  public:
    CellGradient() = default;
    explicit CellGradient(const FVGeometry<dim>& geometry)
    {
      for (auto& c : components)
        c = geometry.make_cell_vector();
    }

    dealii::Tensor<1, dim> operator[](const unsigned int cell) const
    {
      dealii::Tensor<1, dim> g;
      for (unsigned int d = 0; d < dim; ++d)
        g[d] = components[d].local_element(cell);
      return g;
    }
    void set(const unsigned int cell, const dealii::Tensor<1, dim>& g)
    {
      for (unsigned int d = 0; d < dim; ++d)
        components[d].local_element(cell) = g[d];
    }
    /// Copy the owners' values into the ghost entries (collective).
    void update_ghost_values() const
    {
      for (const auto& c : components)
        c.update_ghost_values();
    }

    std::array<CellVector, dim> components; ///< d phi / d x_d
  };

  /// Values on faces, indexed like FVGeometry::faces (e.g. boundary-face values phi_b).
  using FaceVector = std::vector<double>;
} // namespace fvfsi
