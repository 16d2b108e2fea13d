#pragma once
// Boundary conditions of a cell-centred scalar field, per patch (boundary id), with one value per
// boundary face.

#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/mesh/fv_geometry.h>

#include <map>
#include <stdexcept>
#include <string>

namespace fvfsi
{
  enum class BoundaryType
  {
    dirichlet, ///< phi_b given (Eq. 23)
    neumann    ///< n . grad phi given, n pointing out of the domain
  };

  template <int dim>
  struct ScalarBoundaryConditions
  {
    /// Type of every boundary patch of the mesh.
    std::map<unsigned int, BoundaryType> patch_type;
    /// Per face (indexed like FVGeometry::faces): phi_b on Dirichlet faces, n . grad phi on
    /// Neumann faces; unused on interior faces.
    FaceVector value;

    BoundaryType type(const FaceGeometry<dim>& face) const
    {
      const auto it = patch_type.find(face.patch);
      if (it == patch_type.end())
        throw std::runtime_error("no boundary condition for patch id " + std::to_string(face.patch));
      return it->second;
    }
  };
} // namespace fvfsi
