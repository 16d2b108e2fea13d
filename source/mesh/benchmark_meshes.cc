#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <fvfsi/mesh/benchmark_meshes.h>

#include "generator_arguments.h"

#include <cmath>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    using namespace internal;

    void quarter_plate_with_hole(const std::string& arguments, Triangulation<2>& tria)
    {
      const auto x = numbers_of("fvfsi_quarter_plate_with_hole", arguments, 3, 4);
      const double a = x[0], b = x[1], beta = x.size() > 3 ? x[3] : 2.0;
      const unsigned int n = count_of("fvfsi_quarter_plate_with_hole", x, 2);
      if (!(a > 0 && b > a && n > 0))
        throw std::runtime_error("fvfsi_quarter_plate_with_hole: needs 0 < a < b and n > 0");
      const auto graded = [beta](const double xi)
      { return beta == 0 ? xi : (std::exp(beta * xi) - 1) / (std::exp(beta) - 1); };
      Triangulation<2> blocks[2];
      for (unsigned int k = 0; k < 2; ++k)
      {
        GridGenerator::subdivided_hyper_rectangle(blocks[k], {n, n}, Point<2>(0, 0),
                                                  Point<2>(1, 1));
        // (xi, eta) -> the point at fraction graded(xi) from the hole to the plate edge along the
        // ray at angle theta; block 0 covers theta in [0, pi/4] (edge x = b), block 1 [pi/4, pi/2].
        GridTools::transform(
          [&](const Point<2>& p)
          {
            const double theta = (k + p[1]) * numbers::PI / 4;
            const Point<2> inner(a * std::cos(theta), a * std::sin(theta));
            const Point<2> outer = k == 0 ? Point<2>(b, b * std::tan(theta))
                                          : Point<2>(b * std::cos(theta) / std::sin(theta), b);
            return Point<2>(inner + graded(p[0]) * (outer - inner));
          },
          blocks[k]);
      }
      GridGenerator::merge_triangulations(blocks[0], blocks[1], tria, 1e-9 * b);
      const double tol = 1e-9 * b;
      for (const auto& face : tria.active_face_iterators())
        if (face->at_boundary())
        {
          const Point<2> c = face->center();
          face->set_boundary_id(std::abs(c[0]) < tol       ? 3
                                : std::abs(c[1]) < tol     ? 4
                                : std::abs(c[0] - b) < tol ? 1
                                : std::abs(c[1] - b) < tol ? 2
                                                           : 0);
        }
    }

    void turek_hron_flag(const std::string& arguments, Triangulation<2>& tria)
    {
      const auto x = numbers_of("fvfsi_turek_hron_flag", arguments, 2, 2);
      const unsigned int nx = count_of("fvfsi_turek_hron_flag", x, 0),
                         ny = count_of("fvfsi_turek_hron_flag", x, 1);
      GridGenerator::subdivided_hyper_rectangle(tria, {nx, ny}, Point<2>(0, 0), Point<2>(1, 1),
                                                true);
      const double r = 0.05, x_end = 0.6, y0 = 0.19, h = 0.02;
      GridTools::transform(
        [&](const Point<2>& p)
        {
          const double y = y0 + h * p[1];
          const double x_cylinder = 0.2 + std::sqrt(r * r - (y - 0.2) * (y - 0.2));
          return Point<2>(x_cylinder + p[0] * (x_end - x_cylinder), y);
        },
        tria);
      for (const auto& face : tria.active_face_iterators())
        if (face->at_boundary())
          face->set_boundary_id(face->boundary_id() == 0 ? 0 : 1);
    }
  } // namespace

  bool is_benchmark_mesh(const std::string& name)
  {
    return name == "fvfsi_quarter_plate_with_hole" || name == "fvfsi_turek_hron_flag" ||
           name == "fvfsi_turek_hron_channel" || name == "fvfsi_cavity_channel" ||
           name == "fvfsi_cavity_plate" || name == "fvfsi_tube_fluid" ||
           name == "fvfsi_tube_wall" || name == "fvfsi_thick_plate_channel" ||
           name == "fvfsi_thick_plate" || name == "fvfsi_wall_plate_channel" ||
           name == "fvfsi_wall_plate";
  }

  template <int dim>
  void make_benchmark_mesh(const std::string& name, const std::string& arguments,
                           Triangulation<dim>& tria)
  {
    if constexpr (dim == 2)
    {
      if (name == "fvfsi_quarter_plate_with_hole")
        return quarter_plate_with_hole(arguments, tria);
      if (name == "fvfsi_turek_hron_flag")
        return turek_hron_flag(arguments, tria);
      if (name == "fvfsi_turek_hron_channel")
        return make_turek_hron_channel(arguments, tria);
      if (name == "fvfsi_cavity_channel")
        return make_cavity_channel(arguments, tria);
      if (name == "fvfsi_cavity_plate")
        return make_cavity_plate(arguments, tria);
      if (name == "fvfsi_wall_plate_channel")
        return make_wall_plate_channel(arguments, tria);
      if (name == "fvfsi_wall_plate")
        return make_wall_plate(arguments, tria);
    }
    if constexpr (dim == 3)
    {
      if (name == "fvfsi_tube_fluid")
        return make_tube_fluid(arguments, tria);
      if (name == "fvfsi_tube_wall")
        return make_tube_wall(arguments, tria);
      if (name == "fvfsi_thick_plate_channel")
        return make_thick_plate_channel(arguments, tria);
      if (name == "fvfsi_thick_plate")
        return make_thick_plate(arguments, tria);
    }
    throw std::runtime_error("Mesh/Generator = " + name + " is not available in " +
                             std::to_string(dim) + "D");
  }

  template void make_benchmark_mesh(const std::string&, const std::string&, Triangulation<2>&);
  template void make_benchmark_mesh(const std::string&, const std::string&, Triangulation<3>&);
} // namespace fvfsi
