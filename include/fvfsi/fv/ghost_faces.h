#pragma once
// Boundary-face values of a ghost cell, copied from the rank that owns the cell: what a rank
// computes on the boundary faces of its owned cells becomes visible on the ghost_boundary faces
// of its neighbours (needed where a boundary value depends on vertex data a neighbour lacks).

#include <deal.II/grid/grid_tools.h>

#include <fvfsi/mesh/fv_geometry.h>

#include <cstring>
#include <type_traits>
#include <vector>

namespace fvfsi
{
  /// `values` is indexed like FVGeometry::faces; T is double or a dealii::Tensor of doubles.
  template <int dim, typename T>
  void update_ghost_boundary_faces(const FVGeometry<dim>& geometry, std::vector<T>& values)
  {
    static_assert(std::is_trivially_copyable_v<T> && sizeof(T) % sizeof(double) == 0);
    if (dealii::Utilities::MPI::n_mpi_processes(geometry.comm()) == 1)
      return; // no ghost cells
    constexpr unsigned int n = sizeof(T) / sizeof(double);
    using Cell = typename FVGeometry<dim>::active_cell_iterator;
    const auto local = [&geometry](const Cell& cell)
    { return geometry.partitioner()->global_to_local(cell->dof_index(0)); };
    // Per cell: face number, then the n doubles of its value, for each boundary face.
    const auto pack = [&](const Cell& cell) -> dealii::std_cxx17::optional<std::vector<double>>
    {
      std::vector<double> data;
      for (const unsigned int f : geometry.cell_faces(local(cell)))
        if (geometry.faces[f].N == invalid_cell)
        {
          data.push_back(geometry.faces[f].face_no);
          const auto old_size = data.size();
          data.resize(old_size + n);
          std::memcpy(&data[old_size], &values[f], sizeof(T));
        }
      return data;
    };
    const auto unpack = [&](const Cell& cell, const std::vector<double>& data)
    {
      const auto& faces = geometry.cell_faces(local(cell));
      for (unsigned int i = 0; i < data.size(); i += n + 1)
        for (const unsigned int f : faces)
          if (geometry.faces[f].face_no == static_cast<unsigned int>(data[i]))
            std::memcpy(&values[f], &data[i + 1], sizeof(T));
    };
    const auto at_boundary = [](const Cell& cell) { return cell->at_boundary(); };
    dealii::GridTools::exchange_cell_data_to_ghosts<std::vector<double>, dealii::DoFHandler<dim>>(
      geometry.dof_handler(), pack, unpack, at_boundary);
  }
} // namespace fvfsi
