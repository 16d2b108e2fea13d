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
    /// Coordinates as a map key: exact bits, which every rank computes identically.
    template <int dim>
    std::array<double, dim> key(const Point<dim>& x)
    {
      std::array<double, dim> k;
      for (unsigned int d = 0; d < dim; ++d)
        k[d] = x[d];
      return k;
    }
  } // namespace

  template <int dim>
  InterfaceZone<dim>::InterfaceZone(const FVGeometry<dim>& geometry,
                                    const std::vector<unsigned int>& patches, const std::string& name)
    : name(name)
    , comm(geometry.comm())
  {
    const auto on_interface = [&](const FaceGeometry<dim>& face) {
      return face.kind == FaceKind::boundary &&
             std::find(patches.begin(), patches.end(), face.patch) != patches.end();
    };
    // Each owned face as centre, normal, area and vertex coordinates, flattened for all_gather.
    constexpr unsigned int stride = 2 * dim + 1 + n_face_points * dim;
    std::vector<double> mine;
    for (const auto& face : geometry.faces)
      if (on_interface(face))
      {
        for (unsigned int d = 0; d < dim; ++d)
          mine.push_back(face.centre[d]);
        for (unsigned int d = 0; d < dim; ++d)
          mine.push_back(face.n[d]);
        mine.push_back(face.area);
        for (const unsigned int v : face.vertices)
          for (unsigned int d = 0; d < dim; ++d)
            mine.push_back(geometry.vertices()[v][d]);
      }
    std::vector<double> all;
    for (const auto& part : Utilities::MPI::all_gather(comm, mine))
      all.insert(all.end(), part.begin(), part.end());
    const unsigned int n = all.size() / stride;
    if (n == 0)
      throw std::runtime_error("Interface " + name + ": its patches have no boundary face");

    const auto point_at = [&](const unsigned int i, const unsigned int offset) {
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = all[i * stride + offset + d];
      return x;
    };
    // Faces ordered by their centres, points by their coordinates: independent of the ranks.
    std::vector<unsigned int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return key(point_at(a, 0)) < key(point_at(b, 0));
    });
    std::map<std::array<double, dim>, unsigned int> point_index;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n_face_points; ++j)
        point_index.emplace(key(point_at(i, 2 * dim + 1 + j * dim)), 0);
    for (auto& [x, index] : point_index)
    {
      index = points.size();
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = x[d];
      points.push_back(p);
    }
    std::map<std::array<double, dim>, unsigned int> face_index;
    for (const unsigned int i : order)
    {
      face_index[key(point_at(i, 0))] = face_centre.size();
      face_centre.push_back(point_at(i, 0));
      face_normal.push_back(point_at(i, dim));
      face_area.push_back(all[i * stride + 2 * dim]);
      std::array<unsigned int, n_face_points> corners;
      for (unsigned int j = 0; j < n_face_points; ++j)
        corners[j] = point_index.at(key(point_at(i, 2 * dim + 1 + j * dim)));
      face_points.push_back(corners);
    }

    // The way back to the local mesh.
    std::map<unsigned int, unsigned int> local_point;
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
    {
      const auto& face = geometry.faces[f];
      if (!on_interface(face))
        continue;
      local_face_list.emplace_back(f, face_index.at(key(face.centre)));
      for (const unsigned int v : face.vertices)
        local_point[v] = point_index.at(key(geometry.vertices()[v]));
    }
    local_point_list.assign(local_point.begin(), local_point.end());
    point_lookup = std::move(point_index);
  }

  template <int dim>
  unsigned int InterfaceZone<dim>::point_index(const Point<dim>& x) const
  {
    const auto it = point_lookup.find(key(x));
    if (it == point_lookup.end())
      throw std::runtime_error("Interface " + name + ": no interface point at " +
                               Utilities::to_string(x[0]) + ", " + Utilities::to_string(x[1]));
    return it->second;
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  InterfaceZone<dim>::gather_face_field(const std::vector<Tensor<1, dim>>& local_values) const
  {
    std::vector<double> mine;
    for (const auto& [f, i] : local_face_list)
    {
      mine.push_back(i);
      for (unsigned int d = 0; d < dim; ++d)
        mine.push_back(local_values[f][d]);
    }
    std::vector<Tensor<1, dim>> field(n_faces());
    for (const auto& part : Utilities::MPI::all_gather(comm, mine))
      for (unsigned int k = 0; k < part.size(); k += dim + 1)
        for (unsigned int d = 0; d < dim; ++d)
          field[static_cast<unsigned int>(part[k])][d] = part[k + 1 + d];
    return field;
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  InterfaceZone<dim>::gather_point_field(const std::vector<Tensor<1, dim>>& local_values) const
  {
    std::vector<double> mine;
    for (const auto& [v, i] : local_point_list)
    {
      mine.push_back(i);
      for (unsigned int d = 0; d < dim; ++d)
        mine.push_back(local_values[v][d]);
    }
    std::vector<Tensor<1, dim>> field(n_points());
    std::vector<bool> set(n_points(), false);
    for (const auto& part : Utilities::MPI::all_gather(comm, mine))
      for (unsigned int k = 0; k < part.size(); k += dim + 1)
      {
        const unsigned int i = static_cast<unsigned int>(part[k]);
        if (set[i])
          continue; // the lowest rank's value
        set[i] = true;
        for (unsigned int d = 0; d < dim; ++d)
          field[i][d] = part[k + 1 + d];
      }
    return field;
  }

  template class InterfaceZone<2>;
  template class InterfaceZone<3>;
} // namespace fvfsi
