// The meshes of the paper's channel flow over an elastic thick plate (section 4.5, Richter's 3D
// benchmark, half model): the fluid channel with the plate cut out (fvfsi_thick_plate_channel)
// and the plate (fvfsi_thick_plate), both block-structured hexahedra for a cell size h at the
// plate.
//
// Geometry [m] (doc/reference/benchmarks.md section 5): the channel [0, 1.5] x [0, 0.4] x
// [-0.4, 0], symmetry plane z = 0; the plate [0.45, 0.55] x [0, 0.2] x [-0.2, 0] stands on the
// channel floor y = 0 and reaches the symmetry plane. Side view (z = const > -0.2) and the
// spacings:
//
//   0.4 +-------------------------------------------------+
//       |    x: graded, growing away from the plate       |  y, z: uniform h
//   0.2 |               +---+                             |
//       |   inlet       |   | plate                outlet |
//     0 +---------------+---+-----------------------------+
//       0            0.45   0.55                        1.5
//
// The fluid mesh is deal.II's subdivided_hyper_rectangle with these step sizes and the plate's
// cells removed (create_triangulation_with_removed_cells); in x the cells are h over the plate
// and grow by the factor g from cell to cell away from it, up to 4 h. The plate mesh has the
// same h in every direction, so that the two meet vertex for vertex at the interface (the FSI
// transfer does not need it).

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <fvfsi/mesh/benchmark_meshes.h>

#include "generator_arguments.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;
  using namespace internal;

  namespace
  {
    // The geometry of the benchmark [m].
    constexpr double channel_length = 1.5, channel_height = 0.4, channel_depth = 0.4;
    constexpr double plate_x0 = 0.45, plate_x1 = 0.55, plate_height = 0.2, plate_depth = 0.2;

    /// The cell size h of `name`'s first argument: 0.1 / h (the cells across the plate) a whole
    /// number from 1 to 100.
    double plate_cell_size(const std::string& name, const std::vector<double>& x)
    {
      const double h = length_of(name, x, 0), n = 0.1 / h;
      if (!(n >= 1 - 1e-9 && n <= 100 && std::abs(n - std::round(n)) < 1e-9 * n))
        throw std::runtime_error(name +
                                 ": the cell size h must divide the plate's thickness "
                                 "0.1 m a whole number of times (e.g. 0.05, 0.025, "
                                 "0.0125), not " +
                                 Utilities::to_string(x[0]));
      return h;
    }

    unsigned int cells_of(const double length, const double h)
    {
      return static_cast<unsigned int>(std::round(length / h));
    }

    /// Step sizes over `length`: h, h g, h g^2, ... (at most 4 h), scaled so that they add up to
    /// `length` exactly; the first step is the one next to the plate.
    std::vector<double> growing_steps(const double length, const double h, const double g)
    {
      std::vector<double> steps;
      double sum = 0;
      for (double s = h; sum + 0.5 * s < length; s = std::min(s * g, 4 * h))
      {
        steps.push_back(s);
        sum += s;
      }
      for (double& s : steps)
        s *= length / sum;
      return steps;
    }
  } // namespace

  void make_thick_plate_channel(const std::string& arguments, Triangulation<3>& tria)
  {
    const std::string name = "fvfsi_thick_plate_channel";
    auto x = numbers_of(name, arguments, 1, 2);
    const double h = plate_cell_size(name, x), g = x.size() > 1 ? x[1] : 1.15;
    if (!(g >= 1 && g <= 2))
      throw std::runtime_error(name +
                               ": argument 2 is the growth factor of the cells away from "
                               "the plate, from 1 to 2, not " +
                               Utilities::to_string(g));

    std::vector<std::vector<double>> steps(3);
    steps[0] = growing_steps(plate_x0, h, g);
    std::reverse(steps[0].begin(), steps[0].end());
    steps[0].insert(steps[0].end(), cells_of(plate_x1 - plate_x0, h), h);
    const auto downstream = growing_steps(channel_length - plate_x1, h, g);
    steps[0].insert(steps[0].end(), downstream.begin(), downstream.end());
    steps[1].assign(cells_of(channel_height, h), h);
    steps[2].assign(cells_of(channel_depth, h), h);

    Triangulation<3> box;
    GridGenerator::subdivided_hyper_rectangle(box, steps, Point<3>(0, 0, -channel_depth),
                                              Point<3>(channel_length, channel_height, 0));
    const auto in_plate = [](const Point<3>& c)
    { return c[0] > plate_x0 && c[0] < plate_x1 && c[1] < plate_height && c[2] > -plate_depth; };
    std::set<Triangulation<3>::active_cell_iterator> plate;
    for (const auto& cell : box.active_cell_iterators())
      if (in_plate(cell->center()))
        plate.insert(cell);
    GridGenerator::create_triangulation_with_removed_cells(box, plate, tria);

    // Patches: 0 inlet (x = 0), 1 outlet (x = 1.5), 2 walls (y = 0, y = 0.4, z = -0.4),
    // 3 symmetry (z = 0), 4 interface (the plate's faces x = 0.45, 0.55, y = 0.2, z = -0.2).
    const double tol = 1e-6 * h;
    for (const auto& face : tria.active_face_iterators())
      if (face->at_boundary())
      {
        const Point<3> c = face->center();
        const bool on_plate = c[0] > plate_x0 - tol && c[0] < plate_x1 + tol &&
                              c[1] < plate_height + tol && c[2] > -plate_depth - tol;
        face->set_boundary_id(std::abs(c[0]) < tol                    ? 0
                              : std::abs(c[0] - channel_length) < tol ? 1
                              : std::abs(c[2]) < tol                  ? 3
                              : on_plate && c[1] > tol                ? 4
                                                                      : 2);
      }
  }

  void make_thick_plate(const std::string& arguments, Triangulation<3>& tria)
  {
    const std::string name = "fvfsi_thick_plate";
    const auto x = numbers_of(name, arguments, 1, 1);
    const double h = plate_cell_size(name, x);
    GridGenerator::subdivided_hyper_rectangle(
      tria, {cells_of(plate_x1 - plate_x0, h), cells_of(plate_height, h), cells_of(plate_depth, h)},
      Point<3>(plate_x0, 0, -plate_depth), Point<3>(plate_x1, plate_height, 0), true);
    // colorize: 0 x = 0.45, 1 x = 0.55, 2 y = 0, 3 y = 0.2, 4 z = -0.2, 5 z = 0
    // -> 0 clamped (y = 0), 1 symmetry (z = 0), 2 interface (the wet faces).
    for (const auto& face : tria.active_face_iterators())
      if (face->at_boundary())
      {
        const auto id = face->boundary_id();
        face->set_boundary_id(id == 2 ? 0 : id == 5 ? 1 : 2);
      }
  }
} // namespace fvfsi
