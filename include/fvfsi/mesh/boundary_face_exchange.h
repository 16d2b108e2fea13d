#pragma once
// Copies values stored per face from the domain-boundary faces of owned cells to the same faces
// of the ghost cells on the neighbouring ranks (FaceKind::boundary -> FaceKind::ghost_boundary).
// The pattern - which faces go to which rank, in which order - is set up once per mesh from a
// deal.II Partitioner over the numbers (global cell index) * faces_per_cell + face_no; every
// update() is then one message per neighbouring rank, with no search over cells.

#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>

#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

namespace fvfsi
{
  class BoundaryFaceExchange
  {
  public:
    /// The pattern. `cell_faces[c]` lists (face number within the cell, local face index) of the
    /// domain-boundary faces of the locally relevant cell c (numbered like `cells`: the owned
    /// cells, then the ghost cells). Collective.
    void reinit(const dealii::Utilities::MPI::Partitioner& cells, unsigned int faces_per_cell,
                const std::vector<std::vector<std::pair<unsigned int, unsigned int>>>& cell_faces);

    /// values[f] of every ghost_boundary face f := the owner's values[f] of the same face.
    /// `values` is indexed like FVGeometry::faces; T is double or a dealii::Tensor of doubles.
    template <typename T>
    void update(std::vector<T>& values) const;

  private:
    /// Over cell * faces_per_cell + face_no; empty on one rank.
    std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partitioner;
    std::vector<unsigned int> send_faces; ///< local faces in the partitioner's import order
    std::vector<unsigned int> recv_faces; ///< local faces in the partitioner's ghost order
    /// Message buffers, kept between updates (the solid updates in every boundary sweep).
    mutable std::vector<double> send, receive;
  };

  template <typename T>
  void BoundaryFaceExchange::update(std::vector<T>& values) const
  {
    static_assert(std::is_trivially_copyable_v<T> && sizeof(T) % sizeof(double) == 0);
    if (!partitioner)
      return;
    constexpr unsigned int n = sizeof(T) / sizeof(double);
    constexpr int tag = 5113; // only these messages, each received before update() returns
    send.resize(send_faces.size() * n);
    receive.resize(recv_faces.size() * n);
    for (unsigned int k = 0; k < send_faces.size(); ++k)
      std::memcpy(&send[k * n], &values[send_faces[k]], sizeof(T));
    const MPI_Comm comm = partitioner->get_mpi_communicator();
    std::vector<MPI_Request> requests;
    requests.reserve(partitioner->ghost_targets().size() + partitioner->import_targets().size());
    unsigned int offset = 0;
    for (const auto& [rank, count] : partitioner->ghost_targets())
    {
      requests.emplace_back();
      MPI_Irecv(&receive[offset * n], count * n, MPI_DOUBLE, rank, tag, comm, &requests.back());
      offset += count;
    }
    offset = 0;
    for (const auto& [rank, count] : partitioner->import_targets())
    {
      requests.emplace_back();
      MPI_Isend(&send[offset * n], count * n, MPI_DOUBLE, rank, tag, comm, &requests.back());
      offset += count;
    }
    MPI_Waitall(requests.size(), requests.data(), MPI_STATUSES_IGNORE);
    for (unsigned int k = 0; k < recv_faces.size(); ++k)
      std::memcpy(&values[recv_faces[k]], &receive[k * n], sizeof(T));
  }
} // namespace fvfsi
