// A rigid or elastic plate standing on the floor of a channel (the hard-case issue's case, after
// the perpendicular-flap tutorial of preCICE): the channel [-3, 3] x [0, 4] m without the plate
// [-0.05, 0.05] x [0, 1] m, meshed as OpenFOAM's blockMesh meshes it from five blocks:
//
//   4 +------------------+---+------------------+
//     |  n_x x n_2       |n_p|  n_x x n_2       |   rows graded g_y : 1 upwards
//   1 +------------------+---+------------------+
//     |  n_x x n_1       |###|  n_x x n_1       |   ### the plate (not meshed)
//   0 +------------------+---+------------------+
//    -3              -0.05   0.05               3
//
// Columns on either side of the plate are graded so that the cell next to the plate is 1 / g_x
// times the one at the inlet or outlet (blockMesh's simpleGrading 0.5 and 2 for g_x = 2). The
// blocks form a tensor-product grid, so GridGenerator::subdivided_hyper_rectangle with step sizes
// builds it, the plate's cells removed by an invalid material id.

#include <deal.II/base/table.h>
#include <deal.II/grid/grid_generator.h>

#include <fvfsi/mesh/benchmark_meshes.h>

#include "generator_arguments.h"

#include <cmath>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    /// n step sizes over `length`, in geometric progression from first to last with
    /// last / first = ratio (blockMesh's expansion ratio).
    std::vector<double> graded_steps(const double length, const unsigned int n, const double ratio)
    {
      const double q = n > 1 ? std::pow(ratio, 1.0 / (n - 1)) : 1.0;
      std::vector<double> steps(n);
      double sum = 0;
      for (unsigned int i = 0; i < n; ++i)
        sum += (steps[i] = std::pow(q, i));
      for (double& s : steps)
        s *= length / sum;
      return steps;
    }

    void append(std::vector<double>& to, const std::vector<double>& steps)
    {
      to.insert(to.end(), steps.begin(), steps.end());
    }
  } // namespace

  void make_wall_plate_channel(const std::string& arguments, Triangulation<2>& tria)
  {
    const std::string name = "fvfsi_wall_plate_channel";
    const auto x = internal::numbers_of(name, arguments, 4, 6);
    const unsigned int n_x = internal::count_of(name, x, 0), n_p = internal::count_of(name, x, 1),
                       n_1 = internal::count_of(name, x, 2), n_2 = internal::count_of(name, x, 3);
    const double g_x = x.size() > 4 ? internal::length_of(name, x, 4) : 2.0,
                 g_y = x.size() > 5 ? internal::length_of(name, x, 5) : 2.0;
    std::vector<std::vector<double>> steps(2);
    append(steps[0], graded_steps(2.95, n_x, 1 / g_x)); // towards the plate
    append(steps[0], graded_steps(0.1, n_p, 1));
    append(steps[0], graded_steps(2.95, n_x, g_x)); // away from it
    append(steps[1], graded_steps(1, n_1, 1));
    append(steps[1], graded_steps(3, n_2, g_y));
    Table<2, types::material_id> material(steps[0].size(), steps[1].size());
    material.fill(types::material_id(0));
    for (unsigned int i = n_x; i < n_x + n_p; ++i)
      for (unsigned int j = 0; j < n_1; ++j)
        material(i, j) = numbers::invalid_material_id;
    GridGenerator::subdivided_hyper_rectangle(tria, steps, Point<2>(-3, 0), material);
    const double tol = 1e-9;
    for (const auto& face : tria.active_face_iterators())
      if (face->at_boundary())
      {
        const Point<2> c = face->center();
        const bool on_plate = std::abs(c[0]) < 0.05 + tol && c[1] < 1 + tol && c[1] > tol;
        face->set_boundary_id(std::abs(c[0] + 3) < tol   ? 0
                              : std::abs(c[0] - 3) < tol ? 1
                              : on_plate                 ? 2
                                                         : 3);
      }
  }

  void make_wall_plate(const std::string& arguments, Triangulation<2>& tria)
  {
    const std::string name = "fvfsi_wall_plate";
    const auto x = internal::numbers_of(name, arguments, 2, 2);
    const unsigned int n_p = internal::count_of(name, x, 0), n_1 = internal::count_of(name, x, 1);
    GridGenerator::subdivided_hyper_rectangle(tria, {n_p, n_1}, Point<2>(-0.05, 0),
                                              Point<2>(0.05, 1));
    for (const auto& face : tria.active_face_iterators())
      if (face->at_boundary())
        face->set_boundary_id(face->center()[1] < 1e-9 ? 0 : 1);
  }
} // namespace fvfsi
