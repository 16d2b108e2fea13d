#include <deal.II/base/mpi.h>

#include <fvfsi/coupling/interface_zone.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    /// One face of the interface as every rank sees it.
    template <int dim>
    struct GatheredFace
    {
      Point<dim> centre;
      Tensor<1, dim> normal;
      double area;
      std::array<Point<dim>, GeometryInfo<dim>::vertices_per_face> vertices;
    };

    /// The boundary faces of owned cells for which `on_interface` is true, of all ranks
    /// (flattened for all_gather).
    template <int dim, typename Predicate>
    std::vector<GatheredFace<dim>> gather_faces(const FVGeometry<dim>& geometry,
                                                const Predicate& on_interface)
    {
      constexpr unsigned int n_points = GeometryInfo<dim>::vertices_per_face;
      constexpr unsigned int stride = 2 * dim + 1 + n_points * dim;
      std::vector<double> mine;
      for (const unsigned int f : geometry.boundary_faces())
        if (const auto& face = geometry.faces[f]; on_interface(face))
        {
          mine.insert(mine.end(), &face.centre[0], &face.centre[0] + dim);
          mine.insert(mine.end(), &face.n[0], &face.n[0] + dim);
          mine.push_back(face.area);
          for (const unsigned int v : face.vertices)
            mine.insert(mine.end(), &geometry.vertices()[v][0], &geometry.vertices()[v][0] + dim);
        }
      std::vector<GatheredFace<dim>> faces;
      for (const auto& part : Utilities::MPI::all_gather(geometry.comm(), mine))
        for (unsigned int i = 0; i + stride <= part.size(); i += stride)
        {
          GatheredFace<dim> face;
          for (unsigned int d = 0; d < dim; ++d)
          {
            face.centre[d] = part[i + d];
            face.normal[d] = part[i + dim + d];
            for (unsigned int j = 0; j < n_points; ++j)
              face.vertices[j][d] = part[i + 2 * dim + 1 + j * dim + d];
          }
          face.area = part[i + 2 * dim];
          faces.push_back(face);
        }
      return faces;
    }
  } // namespace

  template <int dim>
  InterfaceZone<dim>::InterfaceZone(const FVGeometry<dim>& geometry,
                                    const std::vector<unsigned int>& patches,
                                    const std::string& name)
      : name(name), comm(geometry.comm())
  {
    const auto on_interface = [&](const FaceGeometry<dim>& face) // a boundary face
    { return std::find(patches.begin(), patches.end(), face.patch) != patches.end(); };
    std::vector<GatheredFace<dim>> faces = gather_faces(geometry, on_interface);
    if (faces.empty())
      throw std::runtime_error("Interface " + name + ": its patches have no boundary face");
    // Faces ordered by their centres, points by their coordinates: independent of the ranks.
    std::sort(faces.begin(), faces.end(),
              [](const auto& a, const auto& b)
              { return point_key(a.centre) < point_key(b.centre); });
    for (const auto& face : faces)
      for (const auto& x : face.vertices)
        point_lookup.emplace(point_key(x), 0);
    for (auto& [x, index] : point_lookup)
    {
      index = points.size();
      points.push_back(Point<dim>());
      for (unsigned int d = 0; d < dim; ++d)
        points.back()[d] = x[d];
    }
    std::map<std::array<double, dim>, unsigned int> face_index;
    for (const auto& face : faces)
    {
      face_index[point_key(face.centre)] = face_centre.size();
      face_centre.push_back(face.centre);
      face_normal.push_back(face.normal);
      face_area.push_back(face.area);
      std::array<unsigned int, n_face_points> corners;
      for (unsigned int j = 0; j < n_face_points; ++j)
        corners[j] = point_lookup.at(point_key(face.vertices[j]));
      face_points.push_back(corners);
    }

    // The rim of the interface surface, where it meets the rest of the boundary: in 2D the points
    // of one face, in 3D the points of the edges of one face.
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> edge_faces;
    for (const auto& corners : face_points)
      for (unsigned int j = 0; j < (dim == 2 ? 2u : n_face_points); ++j)
      {
        const unsigned int a = corners[j], b = dim == 2 ? a : corners[(j + 1) % n_face_points];
        ++edge_faces[std::minmax(a, b)];
      }
    on_rim.assign(points.size(), false);
    for (const auto& [edge, count] : edge_faces)
      if (count == 1)
        on_rim[edge.first] = on_rim[edge.second] = true;

    // The way back to the local mesh.
    std::map<unsigned int, unsigned int> local_point;
    for (const unsigned int f : geometry.boundary_faces())
      if (on_interface(geometry.faces[f]))
      {
        local_face_list.emplace_back(f, face_index.at(point_key(geometry.faces[f].centre)));
        for (const unsigned int v : geometry.faces[f].vertices)
          local_point[v] = point_lookup.at(point_key(geometry.vertices()[v]));
      }
    local_point_list.assign(local_point.begin(), local_point.end());
  }

  template <int dim>
  unsigned int InterfaceZone<dim>::point_index(const Point<dim>& x) const
  {
    const auto it = point_lookup.find(point_key(x));
    if (it == point_lookup.end())
      throw std::runtime_error("Interface " + name + ": no interface point at " +
                               Utilities::to_string(x[0]) + ", " + Utilities::to_string(x[1]));
    return it->second;
  }

  namespace
  {
    /// The zone field of n entries from the local values of the (local index, zone index) pairs
    /// of every rank; an entry several ranks hold (a point on a processor boundary) takes the
    /// lowest rank's value.
    template <int dim>
    std::vector<Tensor<1, dim>>
    gather(const std::vector<std::pair<unsigned int, unsigned int>>& pairs,
           const std::vector<Tensor<1, dim>>& local_values, const unsigned int n,
           const MPI_Comm comm, std::uint64_t& bytes_received)
    {
      std::vector<double> mine;
      for (const auto& [local, i] : pairs)
      {
        mine.push_back(i);
        mine.insert(mine.end(), &local_values[local][0], &local_values[local][0] + dim);
      }
      std::vector<Tensor<1, dim>> field(n);
      std::vector<bool> set(n, false);
      const auto parts = Utilities::MPI::all_gather(comm, mine);
      for (unsigned int rank = 0; rank < parts.size(); ++rank)
        if (rank != Utilities::MPI::this_mpi_process(comm))
          bytes_received += sizeof(double) * parts[rank].size();
      for (const auto& part : parts)
        for (unsigned int k = 0; k < part.size(); k += dim + 1)
        {
          const unsigned int i = static_cast<unsigned int>(part[k]);
          if (set[i])
            continue;
          set[i] = true;
          for (unsigned int d = 0; d < dim; ++d)
            field[i][d] = part[k + 1 + d];
        }
      return field;
    }
  } // namespace

  template <int dim>
  std::vector<Tensor<1, dim>>
  InterfaceZone<dim>::gather_face_field(const std::vector<Tensor<1, dim>>& local_values) const
  {
    return gather(local_face_list, local_values, n_faces(), comm, bytes_received);
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  InterfaceZone<dim>::gather_point_field(const std::vector<Tensor<1, dim>>& local_values) const
  {
    return gather(local_point_list, local_values, n_points(), comm, bytes_received);
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  InterfaceZone<dim>::face_to_point_average(const std::vector<Tensor<1, dim>>& face_values,
                                            const std::vector<Tensor<1, dim>>& rim_values) const
  {
    AssertDimension(face_values.size(), n_faces());
    AssertDimension(rim_values.size(), n_points());
    std::vector<Tensor<1, dim>> sum(n_points());
    std::vector<double> weight(n_points(), 0.0);
    for (unsigned int f = 0; f < n_faces(); ++f)
      for (const unsigned int i : face_points[f])
      {
        const double w = 1 / (points[i] - face_centre[f]).norm();
        sum[i] += w * face_values[f];
        weight[i] += w;
      }
    for (unsigned int i = 0; i < n_points(); ++i)
      sum[i] = on_rim[i] ? rim_values[i] : sum[i] / weight[i]; // every point belongs to a face
    return sum;
  }

  template class InterfaceZone<2>;
  template class InterfaceZone<3>;
} // namespace fvfsi
