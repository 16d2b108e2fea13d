// The meshes of the cavity-with-a-flexible-bottom benchmark (paper section 4.2), fvfsi_cavity_channel
// (fluid) and fvfsi_cavity_plate (solid), for h = 0.1 and 0.05, built by fvfsi::make_mesh into a
// parallel::distributed::Triangulation<2> (serial and mpirun=2).
//
// Asserts:
//  - fluid area = 14 + 4 + 2 (r^2 - pi r^2 / 4), r = 0.25, to the error of the polygonal arcs. The
//    cells' edges are straight, so each arc face (a chord subtending theta_f) adds the circular
//    segment (r^2 / 2) (theta_f - sin theta_f) to the fluid (the arcs' centres are outside the
//    fluid, the chords cut into the rounded solid corner). The tolerance of "area = exact area" is
//    the sum D of these segments over the arc faces (D = 6.3e-4 at h = 0.1); the mesh area must
//    moreover equal exact + D to 1e-12 relative (round-off of a sum of O(10^4) cell areas, 1e-16
//    each), which holds only if every arc vertex is on the arc;
//  - plate area 1.6 (1e-12 relative);
//  - every boundary id present, no other id, each with its expected total length (1e-12 relative;
//    the walls' expected length counts the arcs by their chords): fluid 0 inlet 1, 1 outlet 1,
//    2 walls 25 + pi/4 - (arc minus chords), 3 interface 4; plate 0 clamped 0.8, 1 bottom 4,
//    2 interface 4;
//  - both interfaces have 4/h faces and the same vertices (x = 2 + k h, y = -1, to 1e-12);
//  - all cell volumes (FVGeometry's V_P) are positive;
//  - after one global refinement (Mesh/Global refinements = 1) the new arc vertices are on the arcs
//    (the PolarManifolds attached by the generator survive make_mesh's copy_triangulation): max
//    radial error of the arc boundary vertices < 1e-12 (round-off of cos/sin on a radius 0.25;
//    a vertex left on a chord would be off by r (1 - cos(theta/2)) ~ 1e-3), and the area again
//    equals exact + D for the refined chords;
//  - the graded plate `0.05: 1.5` (cells shrinking towards the clamped ends and both surfaces):
//    the uniform plate's cell count, area and boundary lengths (1e-12), its end cells exactly
//    2 Delta_s^beta long and its surface cells 0.2 Delta_s^beta thick (the map's values, 1e-12),
//    its middle cells beta h wide to O(Delta_s) (the map's slope at the middle);
//  - bad arguments are rejected with a message naming the generator.
// Printed mesh quality (owned cells; identical for any number of ranks): the cell aspect ratio
// (longest / shortest edge), the interior angles, the edge lengths / h, and the non-orthogonality
// of the interior faces, the angle between d_f = r_N - r_P and n_f.

#include <deal.II/base/utilities.h>

#include <fvfsi/mesh/fv_geometry.h>

#include "fv_core_test_tools.h"

#include <algorithm>
#include <cmath>
#include <map>

using namespace dealii;
using namespace fvfsi_core_test;

namespace
{
  const double r = 0.25;
  const Point<2> centres[2] = {Point<2>(1.75, -0.25), Point<2>(6.25, -0.25)};

  void make(parallel::distributed::Triangulation<2>& tria, const std::string& generator,
            const double h, const unsigned int refinements = 0, const std::string& extra = "")
  {
    fvfsi::MeshParameters p;
    p.generator = generator;
    p.generator_arguments = format("%g", h) + extra;
    p.n_global_refinements = refinements;
    p.distortion = 0;
    fvfsi::make_mesh(p, tria);
  }

  /// The arc (0 left, 1 right) a wall face lies on by position, or -1 (straight walls).
  int arc_of(const Point<2>& face_centre)
  {
    for (int k = 0; k < 2; ++k)
    {
      const Point<2>& c = centres[k];
      const bool in_quadrant =
        face_centre[1] > c[1] - 1e-12 &&
        (k == 0 ? face_centre[0] > c[0] - 1e-12 : face_centre[0] < c[0] + 1e-12);
      if (in_quadrant && face_centre.distance(c) < 1.1 * r)
        return k;
    }
    return -1;
  }

  struct Summary
  {
    double area = 0;
    std::map<unsigned int, double> length; // per boundary id
    std::map<unsigned int, unsigned int> faces;
    double segments = 0, chords = 0, radial_error = 0; // over the arc faces
    unsigned int arc_faces = 0, left_arc_faces = 0;
    bool arc_manifold_ids = true, positive = true;
    std::vector<double> interface_x; // vertices of the interface faces, on rank 0 (sorted, unique)
    double interface_y_error = 0;
  };

  Summary summarise(const parallel::distributed::Triangulation<2>& tria,
                    const fvfsi::FVGeometry<2>& fv, const unsigned int interface_id,
                    const bool fluid)
  {
    Summary s;
    std::vector<double> x;
    for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
    {
      s.area += fv.cell_volume[c];
      s.positive = s.positive && fv.cell_volume[c] > 0;
    }
    for (const auto& cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
          {
            const auto face = cell->face(f);
            const double length = face->vertex(0).distance(face->vertex(1));
            s.length[face->boundary_id()] += length;
            s.faces[face->boundary_id()] += 1;
            if (face->boundary_id() == interface_id)
              for (const unsigned int v : {0u, 1u})
              {
                x.push_back(face->vertex(v)[0]);
                s.interface_y_error =
                  std::max(s.interface_y_error, std::abs(face->vertex(v)[1] + 1));
              }
            const int k = fluid && face->boundary_id() == 2 ? arc_of(face->center()) : -1;
            if (k >= 0)
            {
              const double theta = 2 * std::asin(length / (2 * r));
              s.segments += r * r / 2 * (theta - std::sin(theta));
              s.chords += length;
              ++s.arc_faces;
              s.left_arc_faces += k == 0 ? 1 : 0;
              s.arc_manifold_ids =
                s.arc_manifold_ids && face->manifold_id() == types::manifold_id(k + 1);
              for (const unsigned int v : {0u, 1u})
                s.radial_error =
                  std::max(s.radial_error, std::abs(face->vertex(v).distance(centres[k]) - r));
            }
          }
    const MPI_Comm comm = MPI_COMM_WORLD;
    s.area = Utilities::MPI::sum(s.area, comm);
    s.segments = Utilities::MPI::sum(s.segments, comm);
    s.chords = Utilities::MPI::sum(s.chords, comm);
    s.arc_faces = Utilities::MPI::sum(s.arc_faces, comm);
    s.left_arc_faces = Utilities::MPI::sum(s.left_arc_faces, comm);
    for (unsigned int id = 0; id < 8; ++id)
    {
      const double l = Utilities::MPI::sum(s.length.count(id) ? s.length[id] : 0.0, comm);
      const unsigned int n = Utilities::MPI::sum(s.faces.count(id) ? s.faces[id] : 0u, comm);
      s.length.erase(id);
      s.faces.erase(id);
      if (n > 0)
      {
        s.length[id] = l;
        s.faces[id] = n;
      }
    }
    s.interface_x = gather_to_root(x);
    std::sort(s.interface_x.begin(), s.interface_x.end());
    s.interface_x.erase(std::unique(s.interface_x.begin(), s.interface_x.end(),
                                    [](double a, double b) { return std::abs(a - b) < 1e-9; }),
                        s.interface_x.end());
    return s;
  }

  void check_boundaries(std::ostream& out, const Summary& s,
                        const std::map<unsigned int, double>& expected)
  {
    bool same_ids = s.length.size() == expected.size();
    double error = 0;
    for (const auto& [id, length] : expected)
    {
      const bool present = s.length.count(id) > 0;
      same_ids = same_ids && present;
      const double l = present ? s.length.at(id) : 0.0;
      out << format("  boundary id %u: %u faces, length %.8f (expected %.8f)", id,
                    present ? s.faces.at(id) : 0u, l, length)
          << std::endl;
      error = std::max(error, std::abs(l - length) / length);
    }
    check(out, "every expected boundary id present, no other", same_ids);
    check(out, "boundary lengths as expected", error, 1e-12);
  }

  void print_quality(std::ostream& out, const parallel::distributed::Triangulation<2>& tria,
                     const fvfsi::FVGeometry<2>& fv, const double h)
  {
    double min_ar = 1e300, max_ar = 0, min_angle = 180, max_angle = 0, min_edge = 1e300,
           max_edge = 0;
    for (const auto& cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        double shortest = 1e300, longest = 0;
        for (unsigned int l = 0; l < 4; ++l)
        {
          const double e = cell->line(l)->vertex(0).distance(cell->line(l)->vertex(1));
          shortest = std::min(shortest, e);
          longest = std::max(longest, e);
        }
        min_ar = std::min(min_ar, longest / shortest);
        max_ar = std::max(max_ar, longest / shortest);
        min_edge = std::min(min_edge, shortest);
        max_edge = std::max(max_edge, longest);
        // Interior angles, vertices in cyclic order 0 1 3 2.
        const unsigned int cyclic[4] = {0, 1, 3, 2};
        for (unsigned int i = 0; i < 4; ++i)
        {
          const Point<2> p = cell->vertex(cyclic[i]), prev = cell->vertex(cyclic[(i + 3) % 4]),
                         next = cell->vertex(cyclic[(i + 1) % 4]);
          const Tensor<1, 2> a = prev - p, b = next - p;
          const double angle =
            std::acos(std::clamp(a * b / (a.norm() * b.norm()), -1.0, 1.0)) * 180 / numbers::PI;
          min_angle = std::min(min_angle, angle);
          max_angle = std::max(max_angle, angle);
        }
      }
    double max_non_orthogonality = 0;
    for (const auto& face : fv.faces)
      if (face.N != fvfsi::invalid_cell)
        max_non_orthogonality =
          std::max(max_non_orthogonality,
                   std::acos(std::clamp(face.d_n / face.d.norm(), -1.0, 1.0)) * 180 / numbers::PI);
    const MPI_Comm comm = MPI_COMM_WORLD;
    out << format("  aspect ratio (longest / shortest edge): min %.3f, max %.3f",
                  Utilities::MPI::min(min_ar, comm), Utilities::MPI::max(max_ar, comm))
        << std::endl;
    out << format("  interior angles: min %.2f, max %.2f degrees",
                  Utilities::MPI::min(min_angle, comm), Utilities::MPI::max(max_angle, comm))
        << std::endl;
    out << format("  edge length / h: min %.3f, max %.3f", Utilities::MPI::min(min_edge, comm) / h,
                  Utilities::MPI::max(max_edge, comm) / h)
        << std::endl;
    out << format("  max non-orthogonality: %.2f degrees",
                  Utilities::MPI::max(max_non_orthogonality, comm))
        << std::endl;
  }

  /// The fluid mesh's area and arc checks; returns its interface vertices (rank 0).
  Summary check_fluid(std::ostream& out, const double h, const unsigned int refinements)
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    make(tria, "fvfsi_cavity_channel", h, refinements);
    const fvfsi::FVGeometry<2> fv(tria);
    const Summary s = summarise(tria, fv, 3, true);
    const double h_cells = h / (1 << refinements);
    out << "--- fvfsi_cavity_channel " << format("%g", h)
        << ", Global refinements = " << refinements << ": " << tria.n_global_active_cells()
        << " cells" << std::endl;
    const double exact = 14 + 4 + 2 * (r * r - numbers::PI * r * r / 4);
    out << format("  area %.8f, exact %.8f, difference %.4e; polygonal-arc segments D = %.4e over "
                  "%u arc faces",
                  s.area, exact, s.area - exact, s.segments, s.arc_faces)
        << std::endl;
    check(out, "  fluid area = exact area to D", std::abs(s.area - exact) - s.segments * (1 + 1e-9),
          1e-12 * exact);
    check(out, "  fluid area = exact area + D", std::abs(s.area - exact - s.segments) / exact,
          1e-12);
    check(out, "  all cell volumes positive", s.positive);
    check(out, "  as many arc faces on the left arc as on the right",
          2 * s.left_arc_faces == s.arc_faces);
    check(out, "  arc faces carry manifold ids 1 (left), 2 (right)", s.arc_manifold_ids);
    check(out, "  arc vertices on the arcs", s.radial_error, 1e-12);
    check(out, "  interface has 4/h faces",
          s.faces.count(3) && s.faces.at(3) == std::lround(4 / h_cells));
    const double arc_length = numbers::PI / 4; // two quarter circles of radius 0.25
    check_boundaries(out, s,
                     {{0, 1.0}, {1, 1.0}, {2, 14 + 1.75 + 7.75 + 2 * 0.75 + s.chords}, {3, 4.0}});
    out << format("  wall length %.8f = 25 + pi/4 - %.4e (arcs by chords)", s.length.at(2),
                  arc_length - s.chords)
        << std::endl;
    print_quality(out, tria, fv, h_cells);
    return s;
  }

  Summary check_plate(std::ostream& out, const double h)
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    make(tria, "fvfsi_cavity_plate", h);
    const fvfsi::FVGeometry<2> fv(tria);
    const Summary s = summarise(tria, fv, 2, false);
    const unsigned int n_x = std::lround(4 / h), n_y = std::max(2l, std::lround(0.4 / h));
    out << "--- fvfsi_cavity_plate " << format("%g", h) << ": " << tria.n_global_active_cells()
        << " cells" << std::endl;
    check(out, "  (4/h) x max(2, round(0.4/h)) cells", tria.n_global_active_cells() == n_x * n_y);
    out << format("  area %.8f", s.area) << std::endl;
    check(out, "  plate area = 1.6", std::abs(s.area - 1.6) / 1.6, 1e-12);
    check(out, "  all cell volumes positive", s.positive);
    check(out, "  interface has 4/h faces", s.faces.count(2) && s.faces.at(2) == n_x);
    check_boundaries(out, s, {{0, 0.8}, {1, 4.0}, {2, 4.0}});
    print_quality(out, tria, fv, h);
    return s;
  }

  /// The graded plate `h: beta`: the same cells, area and boundaries as the uniform one; the
  /// cells at the clamped ends (x = 2, 6) Delta_s^beta long in x with Delta_s = 2 h / 4, those at
  /// the surfaces 0.2 Delta_s^beta thick with Delta_s = 2 h / 0.4; the cells at the middle beta
  /// times wider than uniform (to first order in Delta_s).
  void check_graded_plate(std::ostream& out, const double h, const double beta)
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    make(tria, "fvfsi_cavity_plate", h, 0, format(": %g", beta));
    const fvfsi::FVGeometry<2> fv(tria);
    const Summary s = summarise(tria, fv, 2, false);
    out << "--- fvfsi_cavity_plate " << format("%g: %g", h, beta) << ": "
        << tria.n_global_active_cells() << " cells" << std::endl;
    check(out, "  as many cells as uniform",
          tria.n_global_active_cells() == std::lround(4 / h) * std::lround(0.4 / h));
    check(out, "  plate area = 1.6", std::abs(s.area - 1.6), 1e-12);
    check(out, "  all cell volumes positive", s.positive);
    double dx_min = 1e9, dy_min = 1e9, dx_max = 0;
    for (const auto& cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        const double dx = cell->extent_in_direction(0), dy = cell->extent_in_direction(1);
        dx_min = std::min(dx_min, dx);
        dy_min = std::min(dy_min, dy);
        dx_max = std::max(dx_max, dx);
      }
    dx_min = Utilities::MPI::min(dx_min, MPI_COMM_WORLD);
    dy_min = Utilities::MPI::min(dy_min, MPI_COMM_WORLD);
    dx_max = Utilities::MPI::max(dx_max, MPI_COMM_WORLD);
    const double ds_x = 2 * h / 4, ds_y = 2 * h / 0.4;
    out << format("  end cell %.6e x %.6e, middle cell width %.6e", dx_min, dy_min, dx_max)
        << std::endl;
    check(out, "  end cells Delta_s^beta long", std::abs(dx_min - 2 * std::pow(ds_x, beta)), 1e-12);
    check(out, "  surface cells 0.2 Delta_s^beta thick",
          std::abs(dy_min - 0.2 * std::pow(ds_y, beta)), 1e-12);
    check(out, "  middle cells beta h wide to O(Delta_s)", std::abs(dx_max / h - beta), 2 * ds_x);
    check_boundaries(out, s, {{0, 0.8}, {1, 4.0}, {2, 4.0}});
  }

  void check_rejected(std::ostream& out, const std::string& generator, const std::string& arguments)
  {
    parallel::distributed::Triangulation<2> tria(MPI_COMM_WORLD);
    fvfsi::MeshParameters p;
    p.generator = generator;
    p.generator_arguments = arguments;
    p.n_global_refinements = 0;
    std::string message = "(accepted)";
    try
    {
      fvfsi::make_mesh(p, tria);
    }
    catch (const std::exception& e)
    {
      message = e.what();
    }
    out << "  `" << arguments << "`: " << message << std::endl;
    check(out, "  rejected, naming the generator", message.find(generator) != std::string::npos);
  }
} // namespace

int main(int argc, char** argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  for (const double h : {0.1, 0.05})
  {
    const Summary fluid = check_fluid(out, h, 0);
    const Summary plate = check_plate(out, h);
    out << "--- interface, h = " << format("%g", h) << std::endl;
    check(out, "  same number of interface faces on both sides",
          fluid.faces.count(3) && plate.faces.count(2) && fluid.faces.at(3) == plate.faces.at(2));
    bool same_vertices = fluid.interface_x.size() == plate.interface_x.size();
    double x_error = 0;
    for (unsigned int i = 0; same_vertices && i < fluid.interface_x.size(); ++i)
      x_error = std::max({x_error, std::abs(fluid.interface_x[i] - plate.interface_x[i]),
                          std::abs(fluid.interface_x[i] - (2 + i * h))});
    check(out, "  interface vertices coincide, x = 2 + k h",
          Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0 ||
            (same_vertices && x_error < 1e-12));
    check(out, "  interface vertices at y = -1",
          std::max(fluid.interface_y_error, plate.interface_y_error), 1e-12);
    check_fluid(out, h, 1);
  }
  check_graded_plate(out, 0.05, 1.5);
  out << "--- bad arguments" << std::endl;
  check_rejected(out, "fvfsi_cavity_channel", "0.3");
  check_rejected(out, "fvfsi_cavity_channel", "0.03");
  check_rejected(out, "fvfsi_cavity_channel", "0.1: 2");
  check_rejected(out, "fvfsi_cavity_plate", "h");
  check_rejected(out, "fvfsi_cavity_plate", "0.1: 0.5");
  check_rejected(out, "fvfsi_cavity_plate", "0.1: 1.5: 2");
}
