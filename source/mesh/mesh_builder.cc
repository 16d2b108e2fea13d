#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <fvfsi/base/exceptions.h>
#include <fvfsi/mesh/benchmark_meshes.h>
#include <fvfsi/mesh/mesh_builder.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    std::string resolve(const std::string& name, const std::string& directory)
    {
      if (name.empty() || name[0] == '/' || directory.empty())
        return name;
      return directory + "/" + name;
    }

    template <int dim>
    void read_mesh_file(const std::string& file, Triangulation<dim>& tria,
                        const std::string& section)
    {
      std::ifstream in(file);
      if (!in)
        throw std::runtime_error(section + "/File name: cannot open mesh file `" + file + "`");
      GridIn<dim> grid_in;
      grid_in.attach_triangulation(tria);
      const std::string ext = file.substr(file.find_last_of('.') + 1);
      try
      {
        if (ext == "msh")
          grid_in.read_msh(in);
        else if (ext == "inp" || ext == "ucd")
          grid_in.read_ucd(in);
        else if (ext == "vtk")
          grid_in.read_vtk(in);
        else
          throw std::runtime_error("unknown mesh format `." + ext + "` (use .msh, .inp or .vtk)");
      }
      catch (const std::exception& e)
      {
        throw std::runtime_error(section + "/File name: cannot read `" + file +
                                 "`: " + concise_message(e));
      }
    }

    /// splitmix64: a well-mixed 64-bit hash, used as a counter-based random number generator.
    std::uint64_t mix(std::uint64_t z)
    {
      z += 0x9e3779b97f4a7c15ULL;
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      return z ^ (z >> 31);
    }

    /// A unit vector in a random direction that depends only on the point and the seed.
    template <int dim>
    Tensor<1, dim> hashed_direction(const Point<dim>& p, const unsigned int seed)
    {
      std::uint64_t h = mix(seed);
      for (unsigned int d = 0; d < dim; ++d)
      {
        std::uint64_t bits;
        const double x = p[d] + 0.0; // +0.0 turns -0.0 into 0.0
        std::memcpy(&bits, &x, sizeof bits);
        h = mix(h ^ bits);
      }
      const auto uniform = [&h]()
      {
        h = mix(h);
        return (h >> 11) * (1.0 / 9007199254740992.0);
      };
      Tensor<1, dim> dir;
      const double phi = 2 * M_PI * uniform();
      if (dim == 2)
      {
        dir[0] = std::cos(phi);
        dir[1] = std::sin(phi);
      }
      else
      {
        const double cos_theta = 2 * uniform() - 1,
                     sin_theta = std::sqrt(1 - cos_theta * cos_theta);
        dir[0] = sin_theta * std::cos(phi);
        dir[1] = sin_theta * std::sin(phi);
        dir[dim - 1] = cos_theta;
      }
      return dir;
    }

    /// deal.II's generators read their counts (subdivisions, shells, slices) as unsigned ints:
    /// `-20` wraps to 4 294 967 276 and the generator allocates until memory runs out, and deal.II
    /// checks zero only in Debug builds. The count arguments (`:`-separated, numbered from 0) of
    /// each generator of GridGenerator::generate_from_name_and_arguments, and their least value.
    void check_generator_counts(const MeshParameters& params)
    {
      struct Count
      {
        unsigned int argument, least;
      };
      static const std::map<std::string, std::vector<Count>> counts = {
        {"subdivided_hyper_cube", {{0, 1}}},
        {"subdivided_hyper_rectangle", {{0, 1}}},
        {"cheese", {{0, 0}}},
        {"hyper_cross", {{0, 0}}},
        {"plate_with_a_hole", {{7, 0}, {8, 0}, {10, 1}}},
        {"channel_with_cylinder", {{1, 1}}},
        {"hyper_shell", {{3, 0}}},
        {"half_hyper_shell", {{3, 0}}},
        {"quarter_hyper_shell", {{3, 0}}},
        {"cylinder_shell", {{3, 0}, {4, 0}}},
        {"hyper_cube_with_cylindrical_hole", {{3, 1}}},
        {"concentric_hyper_shells", {{3, 0}, {5, 1}}},
        {"moebius", {{0, 1}, {1, 0}}},
        {"torus", {{2, 1}}}};
      const auto it = counts.find(params.generator);
      if (it == counts.end())
        return;
      const std::vector<std::string> arguments =
        Utilities::split_string_list(params.generator_arguments, ':');
      constexpr unsigned int most = 100000;
      for (const auto& [argument, least] : it->second)
        if (argument < arguments.size() &&
            // subdivided_hyper_rectangle also takes step sizes (reals) in place of counts
            !(params.generator == "subdivided_hyper_rectangle" &&
              arguments[argument].find('.') != std::string::npos))
          for (const auto& entry : Utilities::split_string_list(arguments[argument], ','))
            if (!Patterns::Integer(least, most).match(entry))
              throw std::runtime_error(
                "argument " + std::to_string(argument + 1) + " of " + params.generator +
                " is a count (of cells, shells or slices): a whole "
                "number from " +
                std::to_string(least) + " to " + std::to_string(most) + ", not `" + entry + "`");
    }
  } // namespace

  template <int dim>
  void distort_interior_vertices(parallel::distributed::Triangulation<dim>& tria,
                                 const double factor, const unsigned int seed)
  {
    const unsigned int n = tria.n_vertices();
    std::vector<double> min_edge(n, std::numeric_limits<double>::max());
    std::vector<bool> on_boundary(n, false), of_owned_cell(n, false);
    for (const auto& cell : tria.active_cell_iterators())
    {
      if (cell->is_artificial())
        continue;
      for (unsigned int l = 0; l < GeometryInfo<dim>::lines_per_cell; ++l)
      {
        const auto line = cell->line(l);
        const double length = line->vertex(0).distance(line->vertex(1));
        for (unsigned int v = 0; v < 2; ++v)
          min_edge[line->vertex_index(v)] = std::min(min_edge[line->vertex_index(v)], length);
      }
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          for (const unsigned int v : cell->face(f)->vertex_indices())
            on_boundary[cell->face(f)->vertex_index(v)] = true;
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          of_owned_cell[cell->vertex_index(v)] = true;
    }
    // Only vertices of owned cells see all their edges (the ghost layer holds every cell that
    // shares a vertex with an owned cell); their new positions are then copied to the ghost copies
    // of the cells by their owners (communicate_locally_moved_vertices would need vertex owners).
    std::vector<bool> moved(n, false);
    for (const auto& cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
        {
          const unsigned int i = cell->vertex_index(v);
          if (moved[i] || on_boundary[i] || !of_owned_cell[i])
            continue;
          cell->vertex(v) += factor * min_edge[i] * hashed_direction(cell->vertex(v), seed);
          moved[i] = true;
        }
    using Corners = std::array<Point<dim>, GeometryInfo<dim>::vertices_per_cell>;
    using Cell = typename parallel::distributed::Triangulation<dim>::active_cell_iterator;
    GridTools::exchange_cell_data_to_ghosts<Corners, parallel::distributed::Triangulation<dim>>(
      tria,
      [](const Cell& cell)
      {
        Corners x;
        for (const unsigned int v : cell->vertex_indices())
          x[v] = cell->vertex(v);
        return std_cxx17::optional<Corners>(x);
      },
      [](const Cell& cell, const Corners& x)
      {
        for (const unsigned int v : cell->vertex_indices())
          cell->vertex(v) = x[v];
      });
  }

  /// Transfinite-interpolation manifolds (deal.II's generators attach them, e.g.
  /// channel_with_cylinder and plate_with_a_hole) initialised anew on `tria`. copy_triangulation
  /// copies the manifold objects, but a TransfiniteInterpolationManifold keeps the coarse cells of
  /// the triangulation it was initialised with, and a parallel::distributed::Triangulation
  /// renumbers its coarse cells (p4est's order): refining would then look up the wrong cells
  /// ("Computing the mapping between a real space point and a point in reference space failed").
  /// The id is reset to a flat manifold first, so that the initialisation does not call the stale
  /// object on the lines that carry the id themselves.
  template <int dim>
  void reinitialize_transfinite_manifolds(parallel::distributed::Triangulation<dim>& tria)
  {
    for (const types::manifold_id id : tria.get_manifold_ids())
      if (id != numbers::flat_manifold_id &&
          dynamic_cast<const TransfiniteInterpolationManifold<dim>*>(&tria.get_manifold(id)))
      {
        tria.reset_manifold(id);
        TransfiniteInterpolationManifold<dim> manifold;
        manifold.initialize(tria);
        tria.set_manifold(id, manifold);
      }
  }

  template <int dim>
  void make_coarse_mesh(const MeshParameters& params,
                        parallel::distributed::Triangulation<dim>& tria,
                        const std::string& prm_directory)
  {
    // The coarse mesh is built in a serial triangulation (identical on every rank), so that
    // GridTools::distort_random gives the same coarse mesh for any number of ranks.
    Triangulation<dim> coarse;
    if (params.generator == "file")
    {
      if (params.file_name.empty())
        throw std::runtime_error(params.section + "/Generator = file, but " + params.section +
                                 "/File name is empty");
      read_mesh_file(resolve(params.file_name, prm_directory), coarse, params.section);
    }
    else
    {
      const std::string generator = params.section + "/Generator = `" + params.generator +
                                    "` with " + params.section + "/Generator arguments = `" +
                                    params.generator_arguments + "`";
      try
      {
        if (is_benchmark_mesh(params.generator))
          make_benchmark_mesh(params.generator, params.generator_arguments, coarse);
        else
        {
          check_generator_counts(params);
          GridGenerator::generate_from_name_and_arguments(coarse, params.generator,
                                                          params.generator_arguments);
        }
      }
      catch (const std::exception& e)
      {
        throw std::runtime_error(generator + " failed: " + concise_message(e));
      }
      // deal.II checks its generators' arguments only in Debug builds: a zero, negative or
      // non-finite size gives cells without volume, which would make NaN of every field.
      if (coarse.n_active_cells() == 0)
        throw std::runtime_error(generator + " gives no cells");
      for (const auto& cell : coarse.active_cell_iterators())
        if (!(cell->measure() > 0) || !std::isfinite(cell->measure()))
          throw std::runtime_error(generator + " gives a cell of volume " +
                                   Utilities::to_string(cell->measure()) +
                                   ": the arguments must describe a mesh of positive size");
    }
    if (params.distortion > 0 && params.distort_coarse_mesh)
      GridTools::distort_random(params.distortion, coarse, true, params.distortion_seed);
    tria.copy_triangulation(coarse);
    reinitialize_transfinite_manifolds(tria);
  }

  template <int dim>
  void make_mesh(const MeshParameters& params, parallel::distributed::Triangulation<dim>& tria,
                 const std::string& prm_directory)
  {
    make_coarse_mesh(params, tria, prm_directory);
    tria.refine_global(params.n_global_refinements);
    for (const auto& cell : tria.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (!cell->at_boundary(f) &&
              (cell->face(f)->has_children() || cell->neighbor_is_coarser(f)))
            throw std::runtime_error("the mesh has hanging faces; fvfsi needs a conforming mesh");
    if (params.distortion > 0 && !params.distort_coarse_mesh)
      distort_interior_vertices(tria, params.distortion, params.distortion_seed);
  }

  template void make_mesh(const MeshParameters&, parallel::distributed::Triangulation<2>&,
                          const std::string&);
  template void make_coarse_mesh(const MeshParameters&, parallel::distributed::Triangulation<2>&,
                                 const std::string&);
  template void make_coarse_mesh(const MeshParameters&, parallel::distributed::Triangulation<3>&,
                                 const std::string&);
  template void make_mesh(const MeshParameters&, parallel::distributed::Triangulation<3>&,
                          const std::string&);
  template void distort_interior_vertices(parallel::distributed::Triangulation<2>&, double,
                                          unsigned int);
  template void distort_interior_vertices(parallel::distributed::Triangulation<3>&, double,
                                          unsigned int);
} // namespace fvfsi
