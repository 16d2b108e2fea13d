#pragma once
// Cell-centred fields with more than one component: one value per locally owned and ghost cell,
// stored as one cell vector per independent component.
//  - CellVectorField: a Tensor<1,dim> per cell (the displacement u, the velocity u); its alias
//    CellGradient names the role of the gradient of a scalar;
//  - CellHessian: a SymmetricTensor<2,dim> per cell (the Hessian of a scalar), components in
//    SymmetricTensor's unrolled order ((0,0), (1,1), [(2,2),] (0,1), ...).
// FaceVector holds one value per face (indexed like FVGeometry::faces).

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <fvfsi/mesh/fv_geometry.h>

#include <array>
#include <vector>

namespace fvfsi
{
  template <int dim, typename Value>
  class CellField
  {
  public:
    static constexpr unsigned int n_components = Value::n_independent_components;

    CellField() = default;
    explicit CellField(const FVGeometry<dim>& geometry)
    {
      for (auto& c : components)
      {
        c = geometry.make_cell_vector();
        c.update_ghost_values(); // a new field is readable everywhere, ghosts included
      }
    }

    Value operator[](const unsigned int cell) const
    {
      Value v;
      for (unsigned int i = 0; i < n_components; ++i)
        v[Value::unrolled_to_component_indices(i)] = components[i].local_element(cell);
      return v;
    }
    void set(const unsigned int cell, const Value& v)
    {
      for (unsigned int i = 0; i < n_components; ++i)
        components[i].local_element(cell) = v[Value::unrolled_to_component_indices(i)];
    }
    /// Copy the owners' values into the ghost entries (collective). The components' messages
    /// are all sent before any is waited for (one communication channel per component), so
    /// that the waits of the components overlap instead of following each other.
    void update_ghost_values() const
    {
      for (unsigned int i = 0; i < n_components; ++i)
        components[i].update_ghost_values_start(i);
      for (const auto& c : components)
        c.update_ghost_values_finish();
    }

    std::array<CellVector, n_components> components;
  };

  template <int dim>
  using CellVectorField = CellField<dim, dealii::Tensor<1, dim>>;
  /// The gradient of a cell scalar field: components d phi / d x_d.
  template <int dim>
  using CellGradient = CellVectorField<dim>;
  /// The Hessian of a cell scalar field.
  template <int dim>
  using CellHessian = CellField<dim, dealii::SymmetricTensor<2, dim>>;

  /// Values on faces, indexed like FVGeometry::faces (e.g. boundary-face values phi_b).
  using FaceVector = std::vector<double>;
} // namespace fvfsi
