#pragma once
// One side of the fluid-solid interface, gathered whole on every rank: the paper's "global face
// zone" (section 3.6). The fluid and the solid meshes are decomposed independently, so the rank
// that owns a fluid interface face rarely owns the solid faces it touches; with the whole
// interface on every rank, each rank interpolates between the two sides on its own, and only the
// interface data (a few thousand faces) ever crosses ranks.
//
// A zone is built once from the locally owned boundary faces of some patches, gathered with
// Utilities::MPI::all_gather. Its faces are numbered by their centres (lexicographically) and its
// points (the faces' vertices, each once) by their coordinates, so the numbering is the same on
// every rank and for every number of ranks. Face and point fields of the zone are plain vectors
// in that numbering; gather_face_field() and gather_point_field() build them from each rank's
// local values, and local_faces() / local_points() lead back to the local mesh.
//
// The geometry is that of the mesh when the zone is built (for the solid, the reference
// configuration of its total-Lagrangian description): the interpolation weights between two
// zones (FaceInterpolation, VertexProjection) are computed once from it, when the two sides of
// the interface coincide.

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <fvfsi/mesh/fv_geometry.h>

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fvfsi
{
  /// A vector field on the points of an interface zone, whole on every rank: dim values per
  /// point, component d of point i at i dim + d (the interface displacement d of Algorithm 1, the
  /// vectors of the coupling acceleration).
  using InterfaceVector = dealii::Vector<double>;

  /// Point i of an interface vector.
  template <int dim>
  dealii::Tensor<1, dim> point_value(const InterfaceVector& v, const unsigned int i)
  {
    dealii::Tensor<1, dim> x;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] = v[i * dim + d];
    return x;
  }

  template <int dim>
  class InterfaceZone
  {
  public:
    /// Vertices per face: 2 in 2D (a segment), 4 in 3D (a quadrilateral).
    static constexpr unsigned int n_face_points = dealii::GeometryInfo<dim>::vertices_per_face;

    /// Gather the boundary faces of `patches` (boundary ids) of `geometry` (collective). Throws
    /// if they have no face.
    InterfaceZone(const FVGeometry<dim>& geometry, const std::vector<unsigned int>& patches,
                  const std::string& name);

    unsigned int n_faces() const { return face_centre.size(); }
    unsigned int n_points() const { return points.size(); }

    std::string name;                                                 ///< for messages
    std::vector<dealii::Point<dim>> points;                           ///< unique face vertices [m]
    std::vector<std::array<unsigned int, n_face_points>> face_points; ///< cyclic, into `points`
    std::vector<dealii::Point<dim>> face_centre;                      ///< r_f [m]
    std::vector<dealii::Tensor<1, dim>> face_normal; ///< unit normal out of the mesh
    std::vector<double> face_area;                   ///< S_f [m^(dim-1)]
    /// Whether each point is on the rim of the interface surface, where it meets the rest of the
    /// boundary (2D: the line's end points; 3D: the points of edges that only one face has).
    std::vector<bool> on_rim;

    /// (local face index in FVGeometry::faces, zone face index) of this rank's owned faces.
    const std::vector<std::pair<unsigned int, unsigned int>>& local_faces() const
    {
      return local_face_list;
    }
    /// (triangulation vertex index, zone point index) of the vertices of this rank's owned faces.
    const std::vector<std::pair<unsigned int, unsigned int>>& local_points() const
    {
      return local_point_list;
    }

    /// The zone point at exactly the coordinates x (as the mesh that built the zone had them);
    /// throws if there is none.
    unsigned int point_index(const dealii::Point<dim>& x) const;

    /// The zone face field whose entry for each zone face is `local_values[f]` of the rank that
    /// owns face f (local_values indexed like FVGeometry::faces). Collective.
    std::vector<dealii::Tensor<1, dim>>
    gather_face_field(const std::vector<dealii::Tensor<1, dim>>& local_values) const;

    /// The zone point field from each rank's values at its points (`local_values` indexed by
    /// triangulation vertex, like vertex fields of the mesh). A point seen by several ranks takes
    /// the value of the lowest rank. Collective.
    std::vector<dealii::Tensor<1, dim>>
    gather_point_field(const std::vector<dealii::Tensor<1, dim>>& local_values) const;

    /// The point field whose value at each point is the average of `face_values` (a zone face
    /// field) over the faces round the point, weighted by the inverse distance from the point to
    /// each face centre (in 2D: the linear interpolation between the two faces); on the rim,
    /// where a face average would reach past the interface, `rim_values` (a zone point field).
    std::vector<dealii::Tensor<1, dim>>
    face_to_point_average(const std::vector<dealii::Tensor<1, dim>>& face_values,
                          const std::vector<dealii::Tensor<1, dim>>& rim_values) const;

    /// Bytes this rank has received from the other ranks in gather_face_field() and
    /// gather_point_field() so far (the payload of the all-gathers: zone index and dim values per
    /// entry, 8 bytes each): the communication of the global interface zone.
    std::uint64_t received_bytes() const { return bytes_received; }

  private:
    MPI_Comm comm;
    mutable std::uint64_t bytes_received = 0;
    std::vector<std::pair<unsigned int, unsigned int>> local_face_list, local_point_list;
    std::map<std::array<double, dim>, unsigned int> point_lookup;
  };
} // namespace fvfsi
