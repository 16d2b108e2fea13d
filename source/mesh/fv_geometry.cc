#include <deal.II/dofs/dof_tools.h>

#include <fvfsi/mesh/fv_geometry.h>

#include "face_pieces.h"

#include <algorithm>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    using internal::decompose;
    constexpr double third = internal::third;

    /// Vertex indices of face f of a cell in cyclic order (deal.II numbers face vertices
    /// lexicographically; (0, 1, 3, 2) walks a quad's boundary).
    template <int dim, typename Array>
    std::array<unsigned int, GeometryInfo<dim>::vertices_per_face>
    face_polygon(const Array& cell_vertices, const unsigned int f)
    {
      constexpr unsigned int nv = GeometryInfo<dim>::vertices_per_face;
      constexpr std::array<unsigned int, 4> cyclic = {{0, 1, 3, 2}};
      std::array<unsigned int, nv> polygon;
      for (unsigned int i = 0; i < nv; ++i)
        polygon[i] =
          cell_vertices[GeometryInfo<dim>::face_to_cell_vertices(f, dim == 2 ? i : cyclic[i])];
      return polygon;
    }

    /// Reverse `polygon` if its area vector points into the cell whose vertex average is `apex`,
    /// so that the stored order is counter-clockwise about the outward normal.
    template <int dim, typename Polygon>
    void orient_outward(Polygon& polygon, const Point<dim>& apex, const std::vector<Point<dim>>& x)
    {
      const auto pieces = decompose<dim>(polygon, x);
      double outward = 0;
      for (unsigned int t = 0; t < pieces.n; ++t)
        outward += pieces.S[t] * (pieces.r[t] - apex);
      if (outward < 0)
        std::reverse(polygon.begin(), polygon.end());
    }
  } // namespace

  template <int dim>
  FVGeometry<dim>::FVGeometry(const parallel::distributed::Triangulation<dim>& tria)
      : tria(tria), fe(0), dofs(tria)
  {
    number_cells();
    reinit(tria.get_vertices());
  }

  template <int dim>
  void FVGeometry<dim>::number_cells()
  {
    dofs.distribute_dofs(fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    cell_partitioner = std::make_shared<Utilities::MPI::Partitioner>(
      dofs.locally_owned_dofs(), relevant, tria.get_communicator());
    n_owned = cell_partitioner->locally_owned_size();
    const unsigned int n_relevant = n_owned + cell_partitioner->n_ghost_indices();
    cells.resize(n_relevant);
    cell_vertex_indices.resize(n_relevant);
    std::vector<types::global_dof_index> dof(1);
    for (const auto& cell : dofs.active_cell_iterators())
      if (!cell->is_artificial())
      {
        cell->get_dof_indices(dof);
        const unsigned int c = cell_partitioner->global_to_local(dof[0]);
        cells[c] = cell;
        for (const unsigned int v : cell->vertex_indices())
          cell_vertex_indices[c][v] = cell->vertex_index(v);
      }
    // Face polygons, oriented once in the reference configuration (where every cell is valid).
    const auto& x = tria.get_vertices();
    cell_polygons.resize(n_relevant);
    for (unsigned int c = 0; c < n_relevant; ++c)
    {
      Point<dim> apex;
      for (const unsigned int v : cell_vertex_indices[c])
        apex += x[v] / double(GeometryInfo<dim>::vertices_per_cell);
      for (unsigned int f = 0; f < GeometryInfo<dim>::faces_per_cell; ++f)
      {
        cell_polygons[c][f] = face_polygon<dim>(cell_vertex_indices[c], f);
        orient_outward<dim>(cell_polygons[c][f], apex, x);
      }
    }
    collect_faces();
  }

  template <int dim>
  void FVGeometry<dim>::collect_faces()
  {
    const auto local = [this](const auto& cell)
    {
      std::vector<types::global_dof_index> dof(1);
      cell->get_dof_indices(dof);
      return cell_partitioner->global_to_local(dof[0]);
    };
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm());
    faces.clear();
    boundary_face_list.clear();
    all_boundary_face_list.clear();
    faces_of_cell.assign(cells.size(), {});
    for (unsigned int c = 0; c < cells.size(); ++c)
      for (const unsigned int f : cells[c]->face_indices())
      {
        FaceGeometry<dim> face;
        face.P = c;
        face.face_no = f;
        if (cells[c]->at_boundary(f))
        {
          face.kind = c < n_owned ? FaceKind::boundary : FaceKind::ghost_boundary;
          face.patch = cells[c]->face(f)->boundary_id();
          face.counted_here = c < n_owned;
        }
        else if (c >= n_owned)
          continue; // a ghost cell's interior faces belong to its owner
        else
        {
          const auto neighbor = cells[c]->neighbor(f);
          face.N = local(neighbor);
          if (neighbor->is_locally_owned())
          {
            if (face.N < c)
              continue; // the interior face was already added from the other side
            face.kind = FaceKind::interior;
          }
          else
          {
            face.kind = FaceKind::processor;
            face.counted_here = my_rank < neighbor->subdomain_id();
          }
        }
        face.vertices = cell_polygons[c][f];
        faces_of_cell[c].push_back(faces.size());
        if (face.kind == FaceKind::interior)
          faces_of_cell[face.N].push_back(faces.size());
        if (face.kind == FaceKind::boundary)
          boundary_face_list.push_back(faces.size());
        if (face.N == invalid_cell)
          all_boundary_face_list.push_back(faces.size());
        faces.push_back(face);
        if (c < n_owned) // owned cells (local numbers below n_owned) first: a prefix of faces
          n_faces_of_owned_cells = faces.size();
      }
    std::vector<std::vector<std::pair<unsigned int, unsigned int>>> cell_boundary_faces(
      cells.size());
    for (const unsigned int f : all_boundary_face_list)
      cell_boundary_faces[faces[f].P].emplace_back(faces[f].face_no, f);
    boundary_exchange.reinit(*cell_partitioner, GeometryInfo<dim>::faces_per_cell,
                             cell_boundary_faces);
  }

  template <int dim>
  void FVGeometry<dim>::reinit(const std::vector<Point<dim>>& new_vertex_positions)
  {
    vertex_positions = new_vertex_positions;
    compute_cell_geometry();
    for (auto& face : faces)
      compute_face_geometry(face);
  }

  template <int dim>
  void FVGeometry<dim>::compute_cell_geometry()
  {
    // Volume and centroid by decomposing the cell into pyramids with apex at the vertex average
    // and the face pieces as bases (Eq. 38); the pyramid centroid is apex + dim/(dim+1) (r - apex).
    centroid.resize(cells.size());
    cell_volume.resize(cells.size());
    const auto& x = vertex_positions;
    for (unsigned int c = 0; c < cells.size(); ++c)
    {
      Point<dim> apex;
      for (const unsigned int v : cell_vertex_indices[c])
        apex += x[v] / double(GeometryInfo<dim>::vertices_per_cell);
      double volume = 0;
      Tensor<1, dim> moment;
      for (unsigned int f = 0; f < GeometryInfo<dim>::faces_per_cell; ++f)
      {
        const auto pieces = decompose<dim>(cell_polygons[c][f], x);
        for (unsigned int t = 0; t < pieces.n; ++t)
        {
          const double v = pieces.S[t] * (pieces.r[t] - apex) / dim;
          volume += v;
          moment += v * (double(dim) / (dim + 1)) * (pieces.r[t] - apex);
        }
      }
      cell_volume[c] = volume;
      centroid[c] = apex + moment / volume;
    }
  }

  template <int dim>
  void FVGeometry<dim>::set_tangential_weights(FaceGeometry<dim>& face) const
  {
    // Eq. 39: (1/S_f) sum_e m_e L_e phi_e with m_e L_e = (p_e1 - p_e0) x n_f and phi_e the edge
    // average; in 2D the "edges" are the two end points and m_e = -+ t.
    const auto& x = vertex_positions;
    constexpr unsigned int nv = FaceGeometry<dim>::max_vertices;
    for (auto& w : face.tangential_weight)
      w = Tensor<1, dim>();
    if constexpr (dim == 2)
    {
      const Tensor<1, dim> t = x[face.vertices[1]] - x[face.vertices[0]];
      face.tangential_weight[0] = -t / t.norm_square();
      face.tangential_weight[1] = t / t.norm_square();
    }
    else
    {
      // Edge midpoints of a (possibly non-planar) quad lie on the plane through its vertex average
      // normal to S_f, so this is exact for linear fields on any hexahedral face.
      for (unsigned int i = 0; i < nv; ++i)
      {
        const unsigned int j = (i + 1) % nv;
        const Tensor<1, dim> m_L =
          cross_product_3d(x[face.vertices[j]] - x[face.vertices[i]], face.n);
        face.tangential_weight[i] += m_L / (2 * face.area);
        face.tangential_weight[j] += m_L / (2 * face.area);
      }
    }
  }

  template <int dim>
  void FVGeometry<dim>::compute_face_geometry(FaceGeometry<dim>& face) const
  {
    const auto& x = vertex_positions;
    const auto pieces = decompose<dim>(face.vertices, x);
    constexpr unsigned int nv = FaceGeometry<dim>::max_vertices;

    face.S = Tensor<1, dim>();
    double sum_area = 0;
    Tensor<1, dim> weighted_centre;
    for (unsigned int t = 0; t < pieces.n; ++t)
    {
      face.S += pieces.S[t];
      sum_area += pieces.S[t].norm();
      weighted_centre += pieces.S[t].norm() * pieces.r[t];
    }
    face.centre = Point<dim>(weighted_centre / sum_area);
    face.area = face.S.norm();
    face.n = face.S / face.area;

    // Eq. 37 summed over this face's pieces, written as weights of the vertex values.
    for (unsigned int i = 0; i < nv; ++i)
      face.gauss_green_weight[i] =
        dim == 2 ? 0.5 * face.S
                 : face.S / (3.0 * nv) +
                     (pieces.S[i % pieces.n] + pieces.S[(i + nv - 1) % pieces.n]) * third;

    set_tangential_weights(face);

    const Point<dim>& r_P = centroid[face.P];
    const Tensor<1, dim> r_fP = face.centre - r_P;
    face.k_P = r_fP - (face.n * r_fP) * face.n;
    if (face.N == invalid_cell)
    {
      face.d = r_fP;
      face.k_N = Tensor<1, dim>();
      face.w = 1;
    }
    else
    {
      const Point<dim>& r_N = centroid[face.N];
      face.d = r_N - r_P;
      const Tensor<1, dim> r_Nf = r_N - face.centre;
      face.k_N = r_Nf - (face.n * r_Nf) * face.n;
      face.w = (face.n * r_Nf) / (face.n * face.d);
    }
    face.d_n = face.n * face.d;
  }

  template <int dim>
  std::vector<double> move_mesh(FVGeometry<dim>& geometry,
                                parallel::distributed::Triangulation<dim>& tria,
                                const std::vector<Point<dim>>& old_positions,
                                const std::vector<Point<dim>>& new_positions)
  {
    std::vector<double> swept = geometry.swept_volumes(old_positions, new_positions);
    geometry.reinit(new_positions);
    for (const auto& cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          cell->vertex(v) = new_positions[cell->vertex_index(v)];
    return swept;
  }

  template class FVGeometry<2>;
  template class FVGeometry<3>;
  template std::vector<double> move_mesh(FVGeometry<2>&, parallel::distributed::Triangulation<2>&,
                                         const std::vector<Point<2>>&,
                                         const std::vector<Point<2>>&);
  template std::vector<double> move_mesh(FVGeometry<3>&, parallel::distributed::Triangulation<3>&,
                                         const std::vector<Point<3>>&,
                                         const std::vector<Point<3>>&);
} // namespace fvfsi
