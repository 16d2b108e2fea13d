#include <deal.II/base/mpi.h>
#include <deal.II/distributed/cell_data_transfer.h>
// CellDataTransfer is instantiated in deal.II for Vector<double> only: records of variable size
// need its templates.
#include <deal.II/distributed/cell_data_transfer.templates.h>
#include <deal.II/grid/grid_tools.h>

#include <fvfsi/io/checkpoint.h>
#include <fvfsi/mesh/mesh_builder.h>

#include <boost/crc.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    /// One record of numbers per active cell.
    using Records = std::vector<std::vector<double>>;
  } // namespace

  template <int dim>
  MeshArchive<dim>::MeshArchive(const parallel::distributed::Triangulation<dim>& tria,
                                const bool in_memory)
      : tria(tria), is_loading(false), in_memory(in_memory),
        records(in_memory ? 0 : tria.n_active_cells())
  {
  }

  template <int dim>
  void MeshArchive<dim>::copy(double* const data, const std::size_t n)
  {
    if (is_loading)
      std::copy(memory.begin() + offset, memory.begin() + offset + n, data);
    else
      memory.insert(memory.end(), data, data + n);
    advance(n);
  }

  template <int dim>
  MeshArchive<dim>::MeshArchive(parallel::distributed::Triangulation<dim>& mesh,
                                const std::string& file)
      : tria(mesh), is_loading(true), in_memory(false)
  {
    if (mesh.n_levels() != 1)
      throw std::logic_error("MeshArchive: load onto a coarse mesh");
    try
    {
      mesh.load(file);
    }
    catch (const std::exception& e)
    {
      throw std::runtime_error(
        "cannot read the checkpoint mesh `" + file +
        "` (was it written with this .prm file's Mesh settings?): " + e.what());
    }
    records.resize(mesh.n_active_cells());
    parallel::distributed::CellDataTransfer<dim, dim, Records> transfer(mesh, true);
    transfer.deserialize(records);
    records_to_ghosts();
  }

  template <int dim>
  void MeshArchive<dim>::records_to_ghosts()
  {
    // The ghost cells' records from their owners: faces of ghost cells (boundary faces) and the
    // vertices of ghost cells are read from them.
    using Cell = typename parallel::distributed::Triangulation<dim>::active_cell_iterator;
    GridTools::exchange_cell_data_to_ghosts<std::vector<double>,
                                            parallel::distributed::Triangulation<dim>>(
      tria,
      [this](const Cell& cell)
      { return std_cxx17::optional<std::vector<double>>(records[cell->active_cell_index()]); },
      [this](const Cell& cell, const std::vector<double>& r)
      { records[cell->active_cell_index()] = r; });
  }

  template <int dim>
  void MeshArchive<dim>::clear_for_saving()
  {
    is_loading = false;
    offset = 0;
    memory.clear();
    for (auto& r : records)
      r.clear();
  }

  template <int dim>
  void MeshArchive<dim>::rewind()
  {
    if (!is_loading && !in_memory)
      records_to_ghosts();
    is_loading = true;
    offset = 0;
  }

  template <int dim>
  void MeshArchive<dim>::set_geometry(const FVGeometry<dim>& g)
  {
    geometry = &g;
    if (!is_loading && !in_memory)
      map_faces();
  }

  template <int dim>
  void MeshArchive<dim>::map_faces()
  {
    face_of_cell.assign(geometry->n_relevant_cells(), {});
    for (auto& cell : face_of_cell)
      cell.fill({invalid_cell, 0});
    for (unsigned int f = 0; f < geometry->faces.size(); ++f)
    {
      const auto& face = geometry->faces[f];
      face_of_cell[face.P][face.face_no] = {f, +1};
      if (face.kind == FaceKind::interior)
        face_of_cell[face.N][geometry->cell(face.P)->neighbor_of_neighbor(face.face_no)] = {f, -1};
    }
  }

  template <int dim>
  std::vector<double>& MeshArchive<dim>::record(const unsigned int c)
  {
    return records[geometry->cell(c)->active_cell_index()];
  }

  template <int dim>
  const double* MeshArchive<dim>::read(const unsigned int c) const
  {
    const auto& r = records[geometry->cell(c)->active_cell_index()];
    if (r.size() <= offset)
      throw std::runtime_error("the checkpoint holds less data per cell than this run reads "
                               "(written by another version of fvfsi or another kind of scene?)");
    return r.data() + offset;
  }

  template <int dim>
  template <typename Get, typename Set>
  void MeshArchive<dim>::vertex_values(const unsigned int n, const Get& get, const Set& set)
  {
    // Every cell stores the values at its vertices; loading, every owned and ghost cell sets them
    // (a vertex shared by cells gets the same value from each).
    constexpr unsigned int per_cell = GeometryInfo<dim>::vertices_per_cell;
    for (const auto& cell : tria.active_cell_iterators())
    {
      auto& r = records[cell->active_cell_index()];
      if (!is_loading && cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int k = 0; k < n; ++k)
            r.push_back(get(cell->vertex_index(v), k));
      if (is_loading && (cell->is_locally_owned() || cell->is_ghost()))
      {
        if (r.size() < offset + per_cell * n)
          throw std::runtime_error("the checkpoint holds less data per cell than this run reads");
        for (const unsigned int v : cell->vertex_indices())
          set(cell->vertex_index(v), &r[offset + v * n]);
      }
    }
    advance(per_cell * n);
  }

  template <int dim>
  void MeshArchive<dim>::vertices(std::vector<Point<dim>>& x)
  {
    static_assert(sizeof(Point<dim>) == dim * sizeof(double), "a Point is dim doubles");
    if (in_memory)
      return copy(reinterpret_cast<double*>(x.data()), x.size() * dim);
    if (is_loading)
      x.resize(tria.n_vertices());
    vertex_values(
      dim, [&](const unsigned int v, const unsigned int k) { return x[v][k]; },
      [&](const unsigned int v, const double* values)
      {
        for (unsigned int k = 0; k < dim; ++k)
          x[v][k] = values[k];
      });
  }

  template <int dim>
  void MeshArchive<dim>::vertices(std::vector<double>& x)
  {
    if (x.size() != tria.n_vertices())
      throw std::logic_error("MeshArchive: a vertex field of " + std::to_string(x.size()) +
                             " entries for " + std::to_string(tria.n_vertices()) + " vertices");
    if (in_memory)
      return copy(x.data(), x.size());
    vertex_values(
      1, [&](const unsigned int v, unsigned int) { return x[v]; },
      [&](const unsigned int v, const double* values) { x[v] = values[0]; });
  }

  template <int dim>
  void MeshArchive<dim>::cells(CellVector& v)
  {
    if (v.locally_owned_size() + v.get_partitioner()->n_ghost_indices() !=
        geometry->n_relevant_cells())
      throw std::logic_error("MeshArchive: a cell vector that is not of the mesh's size");
    if (in_memory) // owned and ghost values: they follow each other in v's memory
      return copy(v.begin(), geometry->n_relevant_cells());
    if (is_loading)
    {
      for (unsigned int c = 0; c < geometry->n_relevant_cells(); ++c)
        v.local_element(c) = read(c)[0];
    }
    else
      for (unsigned int c = 0; c < geometry->n_owned_cells(); ++c)
        record(c).push_back(v.local_element(c));
    advance(1);
  }

  template <int dim>
  void MeshArchive<dim>::cells(std::vector<double>& v)
  {
    if (in_memory)
      return copy(v.data(), v.size());
    if (is_loading)
    {
      v.resize(geometry->n_relevant_cells());
      for (unsigned int c = 0; c < geometry->n_relevant_cells(); ++c)
        v[c] = read(c)[0];
    }
    else
      for (unsigned int c = 0; c < geometry->n_owned_cells(); ++c)
        record(c).push_back(v[c]);
    advance(1);
  }

  template <int dim>
  template <typename Get, typename Set>
  void MeshArchive<dim>::face_values(const unsigned int n_components, const Parity parity,
                                     const Get& get, const Set& set)
  {
    // Saving: every owned cell stores all its faces as seen from itself. Loading: every face
    // reads its owner P's record (P sees the face as its own: sign +1).
    if (is_loading)
      for (unsigned int f = 0; f < geometry->faces.size(); ++f)
      {
        const auto& face = geometry->faces[f];
        set(f, read(face.P) + face.face_no * n_components);
      }
    else
      for (unsigned int c = 0; c < geometry->n_owned_cells(); ++c)
        for (const auto& [f, sign] : face_of_cell[c])
          for (unsigned int k = 0; k < n_components; ++k)
            record(c).push_back(f == invalid_cell ? 0.
                                                  : (parity == Parity::odd ? sign : 1) * get(f, k));
    advance(faces_per_cell * n_components);
  }

  template <int dim>
  void MeshArchive<dim>::check_size(const std::size_t n) const
  {
    if (n != geometry->faces.size())
      throw std::logic_error("MeshArchive: a face field of " + std::to_string(n) + " entries for " +
                             std::to_string(geometry->faces.size()) + " faces");
  }

  template <int dim>
  void MeshArchive<dim>::faces(std::vector<double>& v, const Parity parity)
  {
    check_size(v.size());
    if (in_memory)
      return copy(v.data(), v.size());
    face_values(
      1, parity, [&](const unsigned int f, unsigned int) { return v[f]; },
      [&](const unsigned int f, const double* x) { v[f] = x[0]; });
  }

  template <int dim>
  template <typename TensorType>
  void MeshArchive<dim>::faces(std::vector<TensorType>& v, const Parity parity)
  {
    constexpr unsigned int n = TensorType::n_independent_components;
    check_size(v.size());
    static_assert(sizeof(TensorType) == n * sizeof(double), "a tensor is its components");
    if (in_memory)
      return copy(reinterpret_cast<double*>(v.data()), v.size() * n);
    face_values(
      n, parity,
      [&](const unsigned int f, const unsigned int k)
      { return v[f][TensorType::unrolled_to_component_indices(k)]; },
      [&](const unsigned int f, const double* x)
      {
        for (unsigned int k = 0; k < n; ++k)
          v[f][TensorType::unrolled_to_component_indices(k)] = x[k];
      });
  }

  template <int dim>
  void MeshArchive<dim>::save(const std::string& file) const
  {
    if (in_memory)
      throw std::logic_error("MeshArchive: an in-memory copy cannot be saved");
    parallel::distributed::CellDataTransfer<dim, dim, Records> transfer(tria, true);
    transfer.prepare_for_serialization(records);
    tria.save(file);
  }

  template <int dim>
  void place_vertices(parallel::distributed::Triangulation<dim>& tria,
                      const std::vector<Point<dim>>& x)
  {
    for (const auto& cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for (const unsigned int v : cell->vertex_indices())
          cell->vertex(v) = x[cell->vertex_index(v)];
  }

  GlobalArchive::GlobalArchive(std::stringstream& buffer, const bool loading)
  {
    buffer.clear(); // the flags of the last read (end of file)
    if (loading)
    {
      buffer.seekg(0);
      in = std::make_unique<boost::archive::binary_iarchive>(buffer);
    }
    else
    {
      buffer.str(""); // a new save replaces the last
      out = std::make_unique<boost::archive::binary_oarchive>(buffer);
    }
  }

  GlobalArchive::GlobalArchive(const std::string& file, const bool loading, const MPI_Comm comm)
  {
    if (loading)
    {
      stream.open(file, std::ios::in | std::ios::binary);
      if (!stream)
        throw std::runtime_error("cannot read the checkpoint file `" + file + "`");
      in = std::make_unique<boost::archive::binary_iarchive>(stream);
    }
    else if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      stream.open(file, std::ios::out | std::ios::binary | std::ios::trunc);
      if (!stream)
        throw std::runtime_error("cannot write the checkpoint file `" + file + "`");
      out = std::make_unique<boost::archive::binary_oarchive>(stream);
    }
  }

  CheckpointFiles::CheckpointFiles(const std::string& output_directory)
      : directory(output_directory + "/checkpoint")
  {
  }

  std::string CheckpointFiles::path(const std::string& name, const bool writing) const
  {
    return directory + (writing ? ".new/" : "/") + name;
  }

  void CheckpointFiles::begin_writing(const MPI_Comm comm) const
  {
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::filesystem::remove_all(directory + ".new");
      std::filesystem::create_directories(directory + ".new");
    }
    MPI_Barrier(comm);
  }

  namespace
  {
    /// The size [bytes] and CRC-32 of a file.
    std::pair<std::uintmax_t, std::uint32_t> size_and_crc(const std::filesystem::path& file)
    {
      boost::crc_32_type crc;
      std::ifstream in(file, std::ios::binary);
      std::vector<char> buffer(1 << 20);
      while (in)
      {
        in.read(buffer.data(), buffer.size());
        crc.process_bytes(buffer.data(), in.gcount());
      }
      return {std::filesystem::file_size(file), crc.checksum()};
    }

    /// `<directory>/manifest`: a line "SIZE CRC NAME" per file of the directory (NAME relative).
    void write_manifest(const std::string& directory)
    {
      std::ostringstream lines;
      for (const auto& entry : std::filesystem::recursive_directory_iterator(directory))
        if (entry.is_regular_file())
        {
          const auto [size, crc] = size_and_crc(entry.path());
          lines << size << ' ' << crc << ' '
                << std::filesystem::relative(entry.path(), directory).string() << '\n';
        }
      std::ofstream(directory + "/manifest") << lines.str();
    }

    /// What differs between the files of `directory` and its manifest ("" if nothing, or if
    /// there is no manifest: a checkpoint written before manifests).
    std::string manifest_difference(const std::string& directory)
    {
      std::ifstream manifest(directory + "/manifest");
      std::uintmax_t size;
      std::uint32_t crc;
      std::string name;
      while (manifest >> size >> crc && std::getline(manifest >> std::ws, name))
      {
        const std::filesystem::path file = std::filesystem::path(directory) / name;
        if (!std::filesystem::exists(file))
          return "its file `" + name + "` is missing";
        const auto [actual_size, actual_crc] = size_and_crc(file);
        if (actual_size != size)
          return "its file `" + name + "` has " + std::to_string(actual_size) + " bytes where " +
                 std::to_string(size) + " were written (cut short or replaced)";
        if (actual_crc != crc)
          return "its file `" + name +
                 "` has the size it was written with but other contents "
                 "(CRC-32 differs)";
      }
      return "";
    }
  } // namespace

  void CheckpointFiles::finish_writing(const MPI_Comm comm) const
  {
    MPI_Barrier(comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      write_manifest(directory + ".new");
      // The old checkpoint is removed only once the new one is complete.
      std::filesystem::remove_all(directory + ".old");
      if (std::filesystem::exists(directory))
        std::filesystem::rename(directory, directory + ".old");
      std::filesystem::rename(directory + ".new", directory);
      std::filesystem::remove_all(directory + ".old");
    }
    MPI_Barrier(comm);
  }

  void CheckpointFiles::check_readable(const std::string& parameter, const MPI_Comm comm) const
  {
    if (!std::filesystem::exists(path("state")))
      throw std::runtime_error(parameter + ": no checkpoint in `" + directory +
                               "` (a run writes one every `Checkpoint interval` time steps)");
    // A damaged file would stop the restart inside p4est or Boost's archive with a message
    // that names neither the file nor the parameter.
    std::string difference;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      difference = manifest_difference(directory);
    difference = Utilities::MPI::broadcast(comm, difference, 0);
    if (!difference.empty())
      throw std::runtime_error(parameter + ": the checkpoint in `" + directory +
                               "` is damaged: " + difference +
                               "; restart from another checkpoint or run from the start");
  }

  template <int dim>
  void capture_mesh(std::unique_ptr<MeshArchive<dim>>& archive, const FVGeometry<dim>& geometry,
                    std::vector<Point<dim>> reference,
                    const std::function<void(MeshArchive<dim>&)>& state, const bool in_memory)
  {
    if (archive)
      archive->clear_for_saving();
    else
      archive = std::make_unique<MeshArchive<dim>>(geometry.triangulation(), in_memory);
    std::vector<Point<dim>> current = geometry.vertices();
    archive->vertices(reference);
    archive->vertices(current);
    archive->set_geometry(geometry);
    state(*archive);
  }

  template <int dim>
  void save_mesh(const CheckpointFiles& files, const std::string& name,
                 const FVGeometry<dim>& geometry, std::vector<Point<dim>> reference,
                 const std::function<void(MeshArchive<dim>&)>& state)
  {
    std::unique_ptr<MeshArchive<dim>> archive;
    capture_mesh(archive, geometry, std::move(reference), state, false);
    archive->save(files.path(name, true));
  }

  template <int dim>
  std::vector<Point<dim>> rewind_mesh(MeshArchive<dim>& archive, const FVGeometry<dim>& geometry)
  {
    archive.rewind();
    std::vector<Point<dim>> reference = geometry.vertices(), current = reference;
    archive.vertices(reference);
    archive.vertices(current);
    return current;
  }

  template <int dim>
  std::unique_ptr<MeshArchive<dim>>
  load_mesh(const CheckpointFiles& files, const std::string& name, const MeshParameters& mesh,
            parallel::distributed::Triangulation<dim>& tria, const std::string& prm_directory,
            std::vector<Point<dim>>& current)
  {
    make_coarse_mesh(mesh, tria, prm_directory);
    auto archive = std::make_unique<MeshArchive<dim>>(tria, files.path(name));
    // Vertices of no owned or ghost cell keep the positions the refinement gave them.
    std::vector<Point<dim>> reference = tria.get_vertices();
    current = reference;
    archive->vertices(reference);
    archive->vertices(current);
    place_vertices(tria, reference);
    return archive;
  }

  void save_output_state(const CheckpointFiles& files, OutputState state, const MPI_Comm comm)
  {
    GlobalArchive archive(files.path("output", true), false, comm);
    archive& state;
  }

  OutputState load_output_state(const CheckpointFiles& files, const MPI_Comm comm)
  {
    OutputState state;
    GlobalArchive archive(files.path("output"), true, comm);
    archive& state;
    return state;
  }

  template void capture_mesh(std::unique_ptr<MeshArchive<2>>&, const FVGeometry<2>&,
                             std::vector<Point<2>>, const std::function<void(MeshArchive<2>&)>&,
                             bool);
  template void capture_mesh(std::unique_ptr<MeshArchive<3>>&, const FVGeometry<3>&,
                             std::vector<Point<3>>, const std::function<void(MeshArchive<3>&)>&,
                             bool);
  template std::vector<Point<2>> rewind_mesh(MeshArchive<2>&, const FVGeometry<2>&);
  template std::vector<Point<3>> rewind_mesh(MeshArchive<3>&, const FVGeometry<3>&);
  template void save_mesh(const CheckpointFiles&, const std::string&, const FVGeometry<2>&,
                          std::vector<Point<2>>, const std::function<void(MeshArchive<2>&)>&);
  template void save_mesh(const CheckpointFiles&, const std::string&, const FVGeometry<3>&,
                          std::vector<Point<3>>, const std::function<void(MeshArchive<3>&)>&);
  template std::unique_ptr<MeshArchive<2>> load_mesh(const CheckpointFiles&, const std::string&,
                                                     const MeshParameters&,
                                                     parallel::distributed::Triangulation<2>&,
                                                     const std::string&, std::vector<Point<2>>&);
  template std::unique_ptr<MeshArchive<3>> load_mesh(const CheckpointFiles&, const std::string&,
                                                     const MeshParameters&,
                                                     parallel::distributed::Triangulation<3>&,
                                                     const std::string&, std::vector<Point<3>>&);
  template void place_vertices(parallel::distributed::Triangulation<2>&,
                               const std::vector<Point<2>>&);
  template void place_vertices(parallel::distributed::Triangulation<3>&,
                               const std::vector<Point<3>>&);
  template class MeshArchive<2>;
  template class MeshArchive<3>;
  template void MeshArchive<2>::faces(std::vector<Tensor<1, 2>>&, Parity);
  template void MeshArchive<3>::faces(std::vector<Tensor<1, 3>>&, Parity);
  template void MeshArchive<2>::faces(std::vector<Tensor<2, 2>>&, Parity);
  template void MeshArchive<3>::faces(std::vector<Tensor<2, 3>>&, Parity);
  template void MeshArchive<2>::faces(std::vector<Point<2>>&, Parity);
  template void MeshArchive<3>::faces(std::vector<Point<3>>&, Parity);
} // namespace fvfsi
