// fvfsi's 3D benchmark meshes. The meshes of the elastic tube benchmark (paper section 4.4), fvfsi_tube_fluid (the fluid
// cylinder) and fvfsi_tube_wall (the tube wall), R = 5 mm, t = 1 mm, L = 50 mm, n = 12 cells along
// the axis on the coarse mesh, built by fvfsi::make_mesh into a
// parallel::distributed::Triangulation<3> with 0, 1 and 2 global refinements (serial and
// mpirun=2). With N = 4 2^k faces round the circumference, the boundaries are faceted circles
// whose vertices lie on the circles (CylindricalManifold), so the exact values below are those of
// the polygons: A(r) = (N / 2) r^2 sin(2 pi / N) the area of the N-gon in the circle of radius r.
// Asserts (1e-12 relative: the round-off of sums of O(10^4) cell volumes and face areas):
//  - cell counts: fluid 5 4^k x 12 2^k, wall 4 2^k x 2^k x 12 2^k;
//  - volumes: fluid A(R) L, wall (A(R + t) - A(R)) L (the cells fill the faceted domains);
//  - boundary ids and areas: fluid 0 wall N 2 R sin(pi / N) L, 1 inlet and 2 outlet A(R); wall
//    0 inner N 2 R sin(pi / N) L, 1 outer the same with R + t, 2 ends 2 (A(R + t) - A(R));
//  - every interface vertex on the circle r = R (1e-12), and the fluid's wall and the solid's
//    inner surface have the same faces and vertices (the interface is conforming on every level);
//  - bad arguments are rejected with a message naming the generator.
// The cells' shape: the largest aspect ratio (longest / shortest edge) is printed.
//
// The meshes of the thick plate benchmark (paper section 4.5), fvfsi_thick_plate_channel and
// fvfsi_thick_plate, for h = 0.05 and 0.025 m (1e-12 relative as above):
//  - the fluid volume 1.5 x 0.4 x 0.4 - 0.1 x 0.2 x 0.2 = 0.236 m^3 (the plate's cells removed);
//    the plate's 0.004 m^3 in (0.1 / h) (0.2 / h)^2 cells;
//  - fluid patch areas: inlet, outlet 0.16; walls 0.58 + 0.6 + 0.6; symmetry 0.58; interface
//    0.12 (x = 0.45, 0.55: 0.04 each, y = 0.2 and z = -0.2: 0.02 each); plate: clamped and
//    symmetry 0.02, interface 0.12;
//  - a conforming interface for equal h (the same faces and vertices on both sides, to 1e-9 m:
//    the channel's coordinates are sums of step sizes, the plate's products);
//  - an h that does not divide 0.1 m, or a growth factor out of [1, 2], is rejected.
// The fluid cell count is printed (the x grading sets it).

#include <fvfsi/mesh/fv_geometry.h>

#include "fv_core_test_tools.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

using namespace dealii;
using namespace fvfsi_core_test;

namespace
{
  const double R = 0.005, t = 0.001, L = 0.05;
  const unsigned int n = 12;

  double polygon_area(const unsigned int N, const double r)
  {
    return 0.5 * N * r * r * std::sin(2 * numbers::PI / N);
  }

  double polygon_perimeter(const unsigned int N, const double r)
  {
    return 2.0 * N * r * std::sin(numbers::PI / N);
  }

  struct Mesh
  {
    double volume = 0;
    std::map<unsigned int, double> area;        ///< boundary id -> total area
    std::map<unsigned int, unsigned int> faces; ///< boundary id -> faces
    std::vector<double> interface_vertices;     ///< x, y, z of the interface faces' vertices
    double radial_error = 0, aspect_ratio = 0;
    unsigned int cells = 0;
  };

  Mesh measure(const std::string& generator, const std::string& arguments,
               const unsigned int refinements, const unsigned int interface_id)
  {
    parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
    make_test_mesh(tria, generator, arguments, refinements, 0.0);
    const fvfsi::FVGeometry<3> fv(tria);
    Mesh m;
    m.cells = tria.n_global_active_cells();
    for (const auto& cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        m.volume += cell->measure();
        double shortest = 1e300, longest = 0;
        for (unsigned int l = 0; l < GeometryInfo<3>::lines_per_cell; ++l)
        {
          shortest = std::min(shortest, cell->line(l)->diameter());
          longest = std::max(longest, cell->line(l)->diameter());
        }
        m.aspect_ratio = std::max(m.aspect_ratio, longest / shortest);
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
          {
            const auto face = cell->face(f);
            m.area[face->boundary_id()] += face->measure();
            ++m.faces[face->boundary_id()];
            if (face->boundary_id() == interface_id)
              for (const unsigned int v : face->vertex_indices())
              {
                const Point<3> x = face->vertex(v);
                m.radial_error = std::max(m.radial_error, std::abs(std::hypot(x[1], x[2]) - R) / R);
                m.interface_vertices.insert(m.interface_vertices.end(), {x[0], x[1], x[2]});
              }
          }
      }
    m.volume = Utilities::MPI::sum(m.volume, MPI_COMM_WORLD);
    for (unsigned int id = 0; id < 5; ++id)
    {
      m.area[id] = Utilities::MPI::sum(m.area[id], MPI_COMM_WORLD);
      m.faces[id] = Utilities::MPI::sum(m.faces[id], MPI_COMM_WORLD);
    }
    m.radial_error = Utilities::MPI::max(m.radial_error, MPI_COMM_WORLD);
    m.aspect_ratio = Utilities::MPI::max(m.aspect_ratio, MPI_COMM_WORLD);
    m.interface_vertices = gather_to_root(m.interface_vertices);
    return m;
  }

  /// The distinct points of a list of x, y, z triples, rounded to q [m] (1e-12 R for the tube).
  std::set<std::array<long long, 3>> distinct(const std::vector<double>& xyz,
                                              const double q = 1e-12 * R)
  {
    std::set<std::array<long long, 3>> points;
    for (unsigned int i = 0; i + 2 < xyz.size(); i += 3)
      points.insert(
        {std::llround(xyz[i] / q), std::llround(xyz[i + 1] / q), std::llround(xyz[i + 2] / q)});
    return points;
  }

  double relative(const double a, const double b)
  {
    return std::abs(a - b) / std::abs(b);
  }

  void check_level(std::ostream& out, const unsigned int k)
  {
    const unsigned int N = 4u << k, axial = n << k;
    out << "--- " << k << " global refinements: " << N << " faces round, " << axial << " along"
        << std::endl;
    const Mesh f = measure("fvfsi_tube_fluid", format("%g: %g: %u", R, L, n), k, 0),
               w = measure("fvfsi_tube_wall", format("%g: %g: %g: %u", R, t, L, n), k, 0);
    check(out, "  cell counts: fluid 5 4^k 12 2^k, wall 4 2^k 2^k 12 2^k",
          f.cells == 5 * (1u << (2 * k)) * axial && w.cells == N * (1u << k) * axial);
    check(out, "  fluid volume A(R) L", relative(f.volume, polygon_area(N, R) * L), 1e-12);
    check(out, "  wall volume (A(R + t) - A(R)) L",
          relative(w.volume, (polygon_area(N, R + t) - polygon_area(N, R)) * L), 1e-12);
    const double inner = polygon_perimeter(N, R) * L, outer = polygon_perimeter(N, R + t) * L,
                 ring = polygon_area(N, R + t) - polygon_area(N, R);
    check(out, "  fluid boundary areas: wall, inlet, outlet",
          std::max({relative(f.area.at(0), inner), relative(f.area.at(1), polygon_area(N, R)),
                    relative(f.area.at(2), polygon_area(N, R))}),
          1e-12);
    check(out, "  wall boundary areas: inner, outer, ends",
          std::max({relative(w.area.at(0), inner), relative(w.area.at(1), outer),
                    relative(w.area.at(2), 2 * ring)}),
          1e-12);
    check(out, "  interface vertices on the circle r = R", std::max(f.radial_error, w.radial_error),
          1e-12);
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    check(out, "  conforming interface: the same faces and vertices on both sides",
          !root || (f.faces.at(0) == w.faces.at(0) && f.faces.at(0) == N * axial &&
                    distinct(f.interface_vertices) == distinct(w.interface_vertices)));
    out << "  largest aspect ratio: fluid " << format("%.2f", f.aspect_ratio) << ", wall "
        << format("%.2f", w.aspect_ratio) << std::endl;
  }

  void check_thick_plate(std::ostream& out, const double h)
  {
    out << "--- thick plate, h = " << h << std::endl;
    const Mesh f = measure("fvfsi_thick_plate_channel", format("%g", h), 0, 4),
               s = measure("fvfsi_thick_plate", format("%g", h), 0, 2);
    const unsigned int n = static_cast<unsigned int>(std::round(0.1 / h));
    check(out, "  plate cells (0.1 / h) (0.2 / h)^2", s.cells == 4 * n * n * n);
    check(out, "  volumes: fluid 0.236, plate 0.004",
          std::max(relative(f.volume, 0.236), relative(s.volume, 0.004)), 1e-12);
    check(out, "  fluid areas: inlet, outlet, walls, symmetry, interface",
          std::max({relative(f.area.at(0), 0.16), relative(f.area.at(1), 0.16),
                    relative(f.area.at(2), 1.78), relative(f.area.at(3), 0.58),
                    relative(f.area.at(4), 0.12)}),
          1e-12);
    check(out, "  plate areas: clamped, symmetry, interface",
          std::max({relative(s.area.at(0), 0.02), relative(s.area.at(1), 0.02),
                    relative(s.area.at(2), 0.12)}),
          1e-12);
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    check(out, "  conforming interface: the same faces and vertices on both sides",
          !root || (f.faces.at(4) == s.faces.at(2) &&
                    distinct(f.interface_vertices, 1e-9) == distinct(s.interface_vertices, 1e-9)));
    out << "  fluid cells " << f.cells << ", largest aspect ratio "
        << format("%.2f", f.aspect_ratio) << std::endl;
  }

  void check_bad_arguments(std::ostream& out)
  {
    for (const auto& [generator, arguments] : std::vector<std::pair<std::string, std::string>>{
           {"fvfsi_thick_plate_channel", "0.03"},
           {"fvfsi_thick_plate_channel", "0.05: 3"},
           {"fvfsi_thick_plate", "0.05: 1"},
           {"fvfsi_tube_fluid", "0.005: 0.05"},
           {"fvfsi_tube_fluid", "0.005: -1: 12"},
           {"fvfsi_tube_wall", "0.005: 0.001: 0.05: 0"},
           {"fvfsi_tube_wall", "0: 0.001: 0.05: 4"}})
    {
      std::string message;
      try
      {
        parallel::distributed::Triangulation<3> tria(MPI_COMM_WORLD);
        make_test_mesh(tria, generator, arguments, 0, 0.0);
      }
      catch (const std::exception& e)
      {
        message = e.what();
      }
      check(out, generator + " `" + arguments + "` rejected, naming the generator",
            message.find(generator) != std::string::npos);
    }
  }
} // namespace

int main(int argc, char** argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  for (unsigned int k = 0; k <= 2; ++k)
    check_level(out, k);
  for (const double h : {0.05, 0.025})
    check_thick_plate(out, h);
  check_bad_arguments(out);
}
