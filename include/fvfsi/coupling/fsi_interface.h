#pragma once
// The fluid-solid interface of a partitioned run (paper sections 3.5-3.6): its two sides, each
// a global interface zone (InterfaceZone, whole on every rank), and the two transfers across it
// that a Dirichlet-Neumann coupling iteration makes (Algorithm 1, steps 2c and 2e):
//
//   tractions_to_solid       the fluid's wall tractions on its interface faces -> the solid's
//                            interface faces, by the conservative face interpolation of
//                            Eqs 32-33 (FaceInterpolation);
//   displacements_to_fluid   the solid's displacements at its interface vertices (or its
//                            boundary-face displacements averaged to the vertices) -> the fluid
//                            interface points, by projection onto the solid faces (section 3.5.2,
//                            VertexProjection): d~ of Eq. 30.
//
// It sees interface data alone: per-face and per-vertex values indexed like each side's mesh,
// not the solvers. The maps are computed once, on the undeformed meshes, where the two sides
// coincide. FsiScene and tutorial step-4 hold one.

#include <deal.II/base/tensor.h>

#include <fvfsi/coupling/face_interpolation.h>
#include <fvfsi/coupling/interface_zone.h>
#include <fvfsi/coupling/vertex_projection.h>
#include <fvfsi/mesh/fv_geometry.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace fvfsi
{
  template <int dim>
  class FsiInterface
  {
  public:
    /// The zones of the `fluid_patches` of the fluid mesh and the `solid_patches` of the solid
    /// mesh (boundary ids; `fluid_name`, `solid_name` for messages, e.g. the .prm parameter),
    /// and the maps between them (collective).
    FsiInterface(const FVGeometry<dim>& fluid, const std::vector<unsigned int>& fluid_patches,
                 const std::string& fluid_name, const FVGeometry<dim>& solid,
                 const std::vector<unsigned int>& solid_patches, const std::string& solid_name);
    FsiInterface(const FsiInterface&) = delete; // the maps refer to the zones
    FsiInterface& operator=(const FsiInterface&) = delete;

    const InterfaceZone<dim>& fluid_side() const { return fluid_zone; }
    const InterfaceZone<dim>& solid_side() const { return solid_zone; }
    /// The length of an interface vector: dim values per fluid interface point.
    unsigned int n_values() const { return dim * fluid_zone.n_points(); }

    /// Step 2c: the traction on the solid's interface faces [Pa] (indexed like the solid
    /// mesh's faces, zero elsewhere) from `fluid_traction(f)`, the traction on the fluid's
    /// interface face f (a face of the fluid mesh this rank owns). Collective.
    template <class FluidTraction>
    std::vector<dealii::Tensor<1, dim>> tractions_to_solid(FluidTraction fluid_traction) const
    {
      std::vector<dealii::Tensor<1, dim>> on_fluid(n_fluid_faces);
      for (const auto& [f, i] : fluid_zone.local_faces())
        on_fluid[f] = fluid_traction(f);
      const auto on_zone = traction_map.interpolate(fluid_zone.gather_face_field(on_fluid));
      std::vector<dealii::Tensor<1, dim>> on_solid(n_solid_faces);
      for (const auto& [f, j] : solid_zone.local_faces())
        on_solid[f] = on_zone[j];
      return on_solid;
    }

    /// Step 2e: d~ at the fluid interface points [m] from the solid's displacements at its
    /// vertices (indexed like the solid triangulation's vertices). Collective.
    InterfaceVector
    displacements_to_fluid(const std::vector<dealii::Tensor<1, dim>>& solid_vertex_u) const;
    /// The same from the solid's boundary-face displacements (`solid_face_u(f)` for the solid's
    /// interface face f this rank owns), averaged to the vertices
    /// (InterfaceZone::face_to_point_average); on the rim of the interface the vertex values.
    template <class SolidFaceDisplacement>
    InterfaceVector
    displacements_to_fluid(SolidFaceDisplacement solid_face_u,
                           const std::vector<dealii::Tensor<1, dim>>& solid_vertex_u) const
    {
      std::vector<dealii::Tensor<1, dim>> on_solid(n_solid_faces);
      for (const auto& [f, j] : solid_zone.local_faces())
        on_solid[f] = solid_face_u(f);
      return displacement_map.interpolate(solid_zone.face_to_point_average(
        solid_zone.gather_face_field(on_solid), solid_zone.gather_point_field(solid_vertex_u)));
    }

    /// The least and the largest share of a solid face the fluid faces cover (1 where the sides
    /// match), and the largest distance of a fluid point from the solid faces [m].
    std::pair<double, double> coverage_range() const { return traction_map.coverage_range(); }
    double max_gap() const { return displacement_map.max_gap(); }
    /// Bytes this rank has received in the zones' gathers so far.
    std::uint64_t received_bytes() const
    {
      return fluid_zone.received_bytes() + solid_zone.received_bytes();
    }

  private:
    unsigned int n_fluid_faces, n_solid_faces; ///< faces of the two meshes on this rank
    InterfaceZone<dim> fluid_zone, solid_zone;
    FaceInterpolation<dim> traction_map;
    VertexProjection<dim> displacement_map;
  };
} // namespace fvfsi
