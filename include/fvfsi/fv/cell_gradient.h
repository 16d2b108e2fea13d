#pragma once
// A cell-centred vector field: one Tensor<1,dim> per locally owned and ghost cell, stored as dim
// cell vectors (e.g. the displacement u, or the gradient of a scalar, for which the alias
// CellGradient names the role).

#include <fvfsi/mesh/fv_geometry.h>

#include <array>

namespace fvfsi
{
  template <int dim>
  class CellVectorField
  {
  public:
    CellVectorField() = default;
    explicit CellVectorField(const FVGeometry<dim>& geometry)
    {
      for (auto& c : components)
      {
        c = geometry.make_cell_vector();
        c.update_ghost_values(); // a new field is readable everywhere, ghosts included
      }
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

  /// The gradient of a cell scalar field.
  template <int dim>
  using CellGradient = CellVectorField<dim>;

  /// Values on faces, indexed like FVGeometry::faces (e.g. boundary-face values phi_b).
  using FaceVector = std::vector<double>;
} // namespace fvfsi
