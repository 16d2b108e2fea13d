#pragma once
// Checkpoints: the state a run needs to continue, written every `Checkpoint interval` time steps
// and read back by `Restart from` (scenes/*_scene.cc say what each scene keeps).
//
// Two parts:
//  - MeshArchive: the distributed mesh and everything that lives on it. The mesh is saved with
//    parallel::distributed::Triangulation::save (p4est's forest), and every field travels with
//    it as one record of numbers per cell (deal.II's CellDataTransfer), so a checkpoint written on
//    one number of ranks can be read on another: p4est repartitions the cells and each record goes
//    with its cell. What a record holds is decided by the order of the calls: a solver's
//    checkpoint(archive) calls cells(), faces() and vertices() in the same order when saving and
//    when loading. Face values are stored per cell and face, from that cell's side: a value that
//    changes sign with the face's orientation (a flux F_f, an area vector S_f: Parity::odd) is
//    stored as seen from each cell, so it does not matter which cell owns the face after a
//    repartition.
//  - GlobalArchive: the numbers every rank holds alike (the clock, the interface displacement
//    and the coupling's columns, counters, the history files' lengths), in a Boost binary archive
//    written by rank 0 and read by every rank.
//
// A checkpoint is a directory `<Output directory>/checkpoint`; it is written to a temporary
// directory first and renamed over the last one, so that a run killed while writing keeps the
// previous checkpoint.

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/distributed/tria.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_parameters.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace fvfsi
{
  /// `Checkpoint interval` and `Restart from` (top level of a .prm file).
  struct CheckpointParameters
  {
    /// Write a checkpoint every this many time steps (0: never) and at a failed step.
    unsigned int interval = 0;
    /// Output directory of an earlier run whose checkpoint the run continues from ("": none).
    std::string restart_from = "";
    /// Output directory of an earlier steady run (any mesh) whose final state the run starts from
    /// ("": none); see io/point_values.h.
    std::string initial_state_from = "";
  };

  /// Whether a face value keeps (even: a position, a face-centre value) or flips (odd: a flux, an
  /// area vector) its sign when the face's orientation is reversed.
  enum class Parity
  {
    even,
    odd
  };

  template <int dim>
  class MeshArchive
  {
  public:
    /// For saving the state on `tria`: each call appends to the owned cells' records.
    /// `in_memory`: a copy of the state for this mesh and partition alone (the start of a time
    /// step): the arrays as they are, owned and ghost entries, no records per cell; it cannot be
    /// saved, only rewound and read.
    explicit MeshArchive(const dealii::parallel::distributed::Triangulation<dim>& tria,
                         bool in_memory = false);
    /// For loading: `tria` holds the coarse mesh of the run (make_coarse_mesh()); it is refined
    /// and partitioned as saved in `file` and the records are read (collective).
    MeshArchive(dealii::parallel::distributed::Triangulation<dim>& tria, const std::string& file);

    bool loading() const { return is_loading; }
    /// Where cells() and faces() find the cells and faces (needed before their first call).
    void set_geometry(const FVGeometry<dim>& geometry);

    /// Vertex positions indexed like the triangulation's vertices (owned and ghost cells').
    void vertices(std::vector<dealii::Point<dim>>& x);
    /// Values per vertex, indexed like the triangulation's vertices.
    void vertices(std::vector<double>& v);
    /// A cell field (owned and ghost values).
    void cells(CellVector& v);
    /// A per-cell array over the owned and ghost cells (e.g. old cell volumes).
    void cells(std::vector<double>& v);
    /// Face values indexed like FVGeometry::faces.
    void faces(std::vector<double>& v, Parity parity);
    /// Tensor (or Point) values per face.
    template <typename TensorType>
    void faces(std::vector<TensorType>& v, Parity parity);

    /// Write the mesh and the records to `file` (collective).
    void save(const std::string& file) const;

    /// A saving archive becomes a loading one of the records it holds, on the same mesh and
    /// partition (collective): a run returns to the state at the start of a failed time step.
    void rewind();
    /// Saving anew into the same records, their memory kept (the start of every time step).
    void clear_for_saving();

  private:
    static constexpr unsigned int faces_per_cell = dealii::GeometryInfo<dim>::faces_per_cell;
    /// Per owned and ghost cell of the geometry and face number: the face index and its sign as
    /// seen from the cell (+1: the cell is the face's owner P), or (invalid_cell, 0).
    void map_faces();
    /// The record of geometry cell c, and `n` values of it from the read position (loading).
    std::vector<double>& record(unsigned int c);
    const double* read(unsigned int c) const;
    /// `n` values per vertex: the shared part of the vertices() calls.
    template <typename Get, typename Set>
    void vertex_values(unsigned int n, const Get& get, const Set& set);
    /// Values per face and component: the shared part of the faces() calls.
    template <typename Get, typename Set>
    void face_values(unsigned int n_components, Parity parity, const Get& get, const Set& set);
    void advance(unsigned int n) { offset += n; }
    /// Loading: every ghost cell gets its owner's record (collective).
    void records_to_ghosts();
    /// A face field has an entry per face (saving and loading alike: the solver sizes it).
    void check_size(std::size_t n) const;

    const dealii::parallel::distributed::Triangulation<dim>& tria;
    const FVGeometry<dim>* geometry = nullptr;
    bool is_loading;
    bool in_memory;
    /// In memory: the arrays one after another.
    std::vector<double> memory;
    /// In memory: save or load n values at `data`.
    void copy(double* data, std::size_t n);
    /// One record per active cell (active_cell_index); owned cells' when saving, owned and ghost
    /// cells' when loading.
    std::vector<std::vector<double>> records;
    std::size_t offset = 0; ///< loading: the position of the next value in every record
    std::vector<std::array<std::pair<unsigned int, int>, faces_per_cell>> face_of_cell;
  };

  /// Move the vertices of the owned and ghost cells of `tria` to `x` (indexed like its vertices).
  template <int dim>
  void place_vertices(dealii::parallel::distributed::Triangulation<dim>& tria,
                      const std::vector<dealii::Point<dim>>& x);

  /// The rank-independent part of a checkpoint: `archive & x` saves or loads x (Boost
  /// serialization).
  class GlobalArchive
  {
  public:
    /// Saving (rank 0 writes `file`; the other ranks' calls do nothing) or loading (every rank
    /// reads `file`).
    GlobalArchive(const std::string& file, bool loading, MPI_Comm comm);
    /// In memory, on every rank: saving into `buffer` (replacing what it held) or loading from
    /// its start.
    GlobalArchive(std::stringstream& buffer, bool loading);
    bool loading() const { return in != nullptr; }
    template <typename T>
    GlobalArchive& operator&(T& x)
    {
      if (in)
        *in >> x;
      else if (out)
        *out << x;
      return *this;
    }

  private:
    std::fstream stream;
    std::unique_ptr<boost::archive::binary_iarchive> in;
    std::unique_ptr<boost::archive::binary_oarchive> out;
  };

  /// The checkpoint directory of an output directory, and the files in it.
  struct CheckpointFiles
  {
    explicit CheckpointFiles(const std::string& output_directory);
    std::string directory;
    /// `<directory>/<name>` (the final directory, or the one being written).
    std::string path(const std::string& name, bool writing = false) const;
    /// Create the temporary directory (rank 0) before the files are written...
    void begin_writing(MPI_Comm comm) const;
    /// ...and move it over the last checkpoint once they are (collective), with a `manifest`
    /// written last: each file's size and CRC-32.
    void finish_writing(MPI_Comm comm) const;
    /// Throws a clear error if `Restart from` holds no checkpoint, or one whose files differ
    /// from its manifest (cut short, replaced, missing), naming the file (collective: rank 0
    /// reads the files, every rank throws the same).
    void check_readable(const std::string& parameter, MPI_Comm comm) const;
  };

  /// A mesh's reference and current vertex positions, then what `state` puts into the archive
  /// (the solvers' checkpoint()), in memory: save_mesh() writes it, the start of a time step
  /// keeps it (a failed step returns to it through rewind_mesh()).
  /// `archive` is made if empty (in memory or for a file), else cleared and filled anew (its
  /// memory reused).
  template <int dim>
  void capture_mesh(std::unique_ptr<MeshArchive<dim>>& archive, const FVGeometry<dim>& geometry,
                    std::vector<dealii::Point<dim>> reference,
                    const std::function<void(MeshArchive<dim>&)>& state, bool in_memory = true);

  /// An archive of capture_mesh() made ready to be read again on the same mesh; returns the
  /// current vertex positions it holds (the solvers' states follow).
  template <int dim>
  std::vector<dealii::Point<dim>> rewind_mesh(MeshArchive<dim>& archive,
                                              const FVGeometry<dim>& geometry);

  /// Save the mesh `name` of a scene: capture_mesh() into the checkpoint being written
  /// (collective).
  template <int dim>
  void save_mesh(const CheckpointFiles& files, const std::string& name,
                 const FVGeometry<dim>& geometry, std::vector<dealii::Point<dim>> reference,
                 const std::function<void(MeshArchive<dim>&)>& state);

  /// Restarting: the mesh `name` of `files` onto `tria` (built from `mesh`'s coarse mesh) at its
  /// reference positions; `current` gets the positions it had. The returned archive is handed to
  /// the solvers (set_geometry(), then the same calls as save_mesh()'s `state`).
  template <int dim>
  std::unique_ptr<MeshArchive<dim>>
  load_mesh(const CheckpointFiles& files, const std::string& name, const MeshParameters& mesh,
            dealii::parallel::distributed::Triangulation<dim>& tria,
            const std::string& prm_directory, std::vector<dealii::Point<dim>>& current);

  /// What a restarted run's output continues: the history file's length and the steps each VTU
  /// series (.pvd) listed.
  struct OutputState
  {
    std::uint64_t history_length = 0;
    std::vector<std::vector<std::pair<double, std::string>>> series;
    template <class Archive>
    void serialize(Archive& ar, const unsigned int /*version*/)
    {
      ar& history_length& series;
    }
  };
  void save_output_state(const CheckpointFiles& files, OutputState state, MPI_Comm comm);
  OutputState load_output_state(const CheckpointFiles& files, MPI_Comm comm);
} // namespace fvfsi
