#include <deal.II/base/index_set.h>

#include <fvfsi/mesh/boundary_face_exchange.h>

#include <map>

namespace fvfsi
{
  using namespace dealii;

  void BoundaryFaceExchange::reinit(
    const Utilities::MPI::Partitioner& cells, const unsigned int faces_per_cell,
    const std::vector<std::vector<std::pair<unsigned int, unsigned int>>>& cell_faces)
  {
    partitioner.reset();
    send_faces.clear();
    recv_faces.clear();
    const MPI_Comm comm = cells.get_mpi_communicator();
    if (Utilities::MPI::n_mpi_processes(comm) == 1)
      return;
    // A face's number: (global cell index) * faces_per_cell + face_no. A rank owns the numbers of
    // all faces of its cells (a contiguous range, as the Partitioner needs) and asks for those of
    // the boundary faces of its ghost cells; the Partitioner finds who sends what to whom.
    const types::global_dof_index F = faces_per_cell;
    const auto [first, last] = cells.local_range();
    IndexSet owned(cells.size() * F), ghost(cells.size() * F);
    owned.add_range(first * F, last * F);
    std::map<types::global_dof_index, unsigned int> ghost_face; // number -> local face
    for (unsigned int c = cells.locally_owned_size(); c < cell_faces.size(); ++c)
      for (const auto& [face_no, f] : cell_faces[c])
        ghost_face[cells.local_to_global(c) * F + face_no] = f;
    for (const auto& [number, f] : ghost_face)
      ghost.add_index(number);
    ghost.compress();
    partitioner = std::make_shared<Utilities::MPI::Partitioner>(owned, ghost, comm);

    // The ghost entries come in increasing number, as the map holds them.
    for (const auto& [number, f] : ghost_face)
      recv_faces.push_back(f);
    // The entries to send, rank by rank: owned local number i = (local cell) * F + face_no.
    for (const auto& [begin, end] : partitioner->import_indices())
      for (unsigned int i = begin; i < end; ++i)
      {
        const unsigned int c = i / F, face_no = i % F;
        unsigned int face = numbers::invalid_unsigned_int;
        for (const auto& [no, f] : cell_faces[c])
          if (no == face_no)
            face = f;
        AssertThrow(face != numbers::invalid_unsigned_int,
                    ExcMessage("a neighbouring rank asked for a face that is not on the boundary"));
        send_faces.push_back(face);
      }
  }
} // namespace fvfsi
