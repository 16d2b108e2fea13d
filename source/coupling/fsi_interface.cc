#include <fvfsi/coupling/fsi_interface.h>

namespace fvfsi
{
  template <int dim>
  FsiInterface<dim>::FsiInterface(const FVGeometry<dim>& fluid,
                                  const std::vector<unsigned int>& fluid_patches,
                                  const std::string& fluid_name, const FVGeometry<dim>& solid,
                                  const std::vector<unsigned int>& solid_patches,
                                  const std::string& solid_name)
      : n_fluid_faces(fluid.faces.size()), n_solid_faces(solid.faces.size()),
        fluid_zone(fluid, fluid_patches, fluid_name), solid_zone(solid, solid_patches, solid_name),
        traction_map(fluid_zone, solid_zone), displacement_map(solid_zone, fluid_zone)
  {
  }

  template <int dim>
  InterfaceVector FsiInterface<dim>::displacements_to_fluid(
    const std::vector<dealii::Tensor<1, dim>>& solid_vertex_u) const
  {
    return displacement_map.interpolate(solid_zone.gather_point_field(solid_vertex_u));
  }

  template class FsiInterface<2>;
  template class FsiInterface<3>;
} // namespace fvfsi
