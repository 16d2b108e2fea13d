#pragma once
// Displacement fields of 2D solid scenes compared cell by cell, whatever the ranks: gathered on
// rank 0 by cell centroid (tests solid_coupled, solid_limit_point).

#include <deal.II/base/mpi.h>

#include <fvfsi/scenes/solid_scene.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace fvfsi_test
{
  /// u [m] by cell centroid: all cells on rank 0, empty elsewhere.
  using SolidField = std::map<std::array<double, 2>, std::array<double, 2>>;

  inline SolidField displacement_by_centroid(const fvfsi::SolidScene<2>& scene)
  {
    std::vector<std::pair<std::array<double, 2>, std::array<double, 2>>> local;
    const auto& fv = scene.geometry();
    const auto& u = scene.solver().displacement();
    for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
      local.push_back({{fv.centroid[c][0], fv.centroid[c][1]}, {u[c][0], u[c][1]}});
    SolidField field;
    for (const auto& part : dealii::Utilities::MPI::gather(MPI_COMM_WORLD, local))
      for (const auto& [x, value] : part)
        field[x] = value;
    return field;
  }

  /// max |u_a - u_b| / max |u_b| over the cells of b; `matched`: a has the same cells.
  inline double max_relative_difference(const SolidField& a, const SolidField& b, bool& matched)
  {
    double max_u = 0, max_difference = 0;
    matched = a.size() == b.size();
    for (const auto& [x, u] : b)
    {
      max_u = std::max({max_u, std::abs(u[0]), std::abs(u[1])});
      const auto it = a.find(x);
      matched = matched && it != a.end();
      if (it != a.end())
        max_difference = std::max(
          {max_difference, std::abs(u[0] - it->second[0]), std::abs(u[1] - it->second[1])});
    }
    return max_difference / max_u;
  }
} // namespace fvfsi_test
