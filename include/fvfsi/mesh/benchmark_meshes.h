#pragma once
// Coarse meshes of the paper's benchmarks that deal.II's GridGenerator does not have. They are
// selected in a .prm file like GridGenerator functions: `Mesh/Generator = fvfsi_<name>`.

#include <deal.II/grid/tria.h>

#include <string>

namespace fvfsi
{
  /// True if `name` is one of fvfsi's own generators.
  bool is_benchmark_mesh(const std::string& name);

  /**
   * Fill `tria` with the benchmark mesh `name` (one of those below), `arguments` separated by
   * `:`.
   *
   * fvfsi_quarter_plate_with_hole  a: b: n[: beta]   (paper section 4.1)
   *   The quarter plate [0,b]^2 without the disc of radius a about the origin, as two blocks of
   *   n x n cells between the hole and the edges x = b and y = b (2 n^2 cells), hole vertices on
   *   the circle, radial spacing graded towards the hole by exp(beta xi) (beta = 2 by default).
   *   Boundary ids: 0 hole, 1 right (x = b), 2 top (y = b), 3 left (x = 0), 4 bottom (y = 0).
   *
   * fvfsi_turek_hron_flag  nx: ny   (Turek & Hron 2006, CSM tests)
   *   The elastic flag 0.35 x 0.02 behind the cylinder of radius 0.05 at (0.2, 0.2): x from the
   *   cylinder arc to 0.6, y in [0.19, 0.21], nx x ny cells. Boundary ids: 0 on the cylinder
   *   (clamped end), 1 elsewhere (the flag surface).
   *
   * fvfsi_cavity_channel  h   (paper section 4.2, channel over a cavity with a flexible bottom)
   *   The fluid domain: channel [0, 14] x [0, 1] over the cavity [2, 6] x [-1, 0], whose top
   *   corners (2, 0) and (6, 0) are rounded with radius 0.25 (arcs about (1.75, -0.25) and
   *   (6.25, -0.25)), as a block-structured quadrilateral mesh with cells of size about h (an
   *   O-grid quadrant around each rounded corner, see cavity_meshes.cc). 4/h must be an integer
   *   and h <= 0.2: the cavity floor has exactly 4/h cells of length h, matching
   *   fvfsi_cavity_plate with the same h vertex for vertex. Arc vertices lie on the arcs; the arc
   *   faces carry PolarManifolds (manifold ids 1, 2), so Global refinements keep the arcs.
   *   Boundary ids: 0 inlet (x = 0), 1 outlet (x = 14), 2 walls (channel top and floor, cavity
   *   walls, rounded corners), 3 interface (the cavity floor y = -1).
   *
   * fvfsi_cavity_plate  h[: beta]   (the elastic cavity bottom of the same benchmark)
   *   The plate [2, 6] x [-1.4, -1] as (4/h) x max(2, round(0.4/h)) cells (same conditions on h).
   *   With a grading exponent 1 < beta <= 3 the cells shrink towards the clamped ends and both
   *   surfaces (s -> sign(s) (1 - (1 - |s|)^beta) across the length and the thickness), for the
   *   stress singularities at the four corners; the interface vertices then no longer match the
   *   fluid's (the transfer is non-matching anyway).
   *   Boundary ids: 0 clamped (x = 2 and x = 6), 1 bottom (y = -1.4), 2 interface (top, y = -1).
   *
   * fvfsi_tube_fluid  R: L: n   (3D; paper section 4.4, the fluid in the elastic tube)
   *   The cylinder of radius R about the x axis, x in [0, L]: deal.II's subdivided_cylinder (a
   *   cross-section of 5 cells, a square and four around it) with n cells along the axis. The
   *   hull carries a CylindricalManifold (id 0) and the cells a TransfiniteInterpolationManifold
   *   (id 1), so Global refinements k give 5 4^k cells per cross-section, 4 2^k hull faces round
   *   it and n 2^k cells along. Boundary ids: 0 wall (the hull), 1 inlet (x = 0), 2 outlet (x = L).
   *
   * fvfsi_tube_wall  R: t: L: n   (3D; the tube wall of the same benchmark)
   *   The shell R <= r <= R + t about the x axis, x in [0, L]: deal.II's cylinder_shell with 4
   *   cells round, one through the wall and n along, turned so that its inner vertices are those
   *   of fvfsi_tube_fluid with the same R, L and n, refinement for refinement (a conforming
   *   interface). CylindricalManifold about the x axis (id 0). Boundary ids: 0 inner surface
   *   (r = R), 1 outer surface (r = R + t), 2 ends (x = 0 and x = L).
   *
   * fvfsi_thick_plate_channel  h[: g]   (3D; paper section 4.5, Richter's thick plate, half model)
   *   The channel [0, 1.5] x [0, 0.4] x [-0.4, 0] without the plate [0.45, 0.55] x [0, 0.2] x
   *   [-0.2, 0]: hexahedra of size h in y and z and over the plate in x, growing by the factor g
   *   (1.15 by default, from 1 to 2) per cell away from the plate in x, up to 4 h. 0.1 / h must be
   *   a whole number. Boundary ids: 0 inlet (x = 0), 1 outlet (x = 1.5), 2 walls (y = 0, y = 0.4,
   *   z = -0.4), 3 symmetry (z = 0), 4 interface (the plate's wet faces).
   *
   * fvfsi_thick_plate  h   (3D; the plate of the same benchmark)
   *   The plate as (0.1 / h) x (0.2 / h) x (0.2 / h) cubes of size h, vertex for vertex with
   *   fvfsi_thick_plate_channel's interface for the same h. Boundary ids: 0 clamped (y = 0),
   *   1 symmetry (z = 0), 2 interface (x = 0.45, x = 0.55, y = 0.2, z = -0.2).
   *
   * fvfsi_wall_plate_channel  n_x: n_p: n_1: n_2[: g_x[: g_y]]   (the hard-case issue's channel)
   *   The channel [-3, 3] x [0, 4] without the plate [-0.05, 0.05] x [0, 1] standing on its
   *   floor, five blocks as blockMesh makes them: n_x columns on each side of the plate graded so
   *   that the cell next to it is 1 / g_x (2) times the outer one, n_p columns over the plate,
   *   n_1 rows up to y = 1 and n_2 above, graded g_y (2) : 1 upwards. The tutorial's mesh refined
   *   r times is 30r: 3r: 15r: 30r (2 790 r^2 cells). Boundary ids: 0 inlet (x = -3), 1 outlet
   *   (x = 3), 2 plate, 3 walls (floor and top).
   *
   * fvfsi_wall_plate  n_p: n_1   (the plate of the same case as a solid)
   *   [-0.05, 0.05] x [0, 1] as n_p x n_1 cells, vertex for vertex with the channel's plate faces
   *   for the same n_p, n_1. Boundary ids: 0 clamped (y = 0), 1 the wet faces.
   */
  /// The Turek-Hron fluid domain (fvfsi_turek_hron_channel), in turek_hron_channel.cc.
  void make_turek_hron_channel(const std::string& arguments, dealii::Triangulation<2>& tria);
  /// The cavity benchmark's fluid domain (fvfsi_cavity_channel) and plate (fvfsi_cavity_plate),
  /// in cavity_meshes.cc.
  void make_cavity_channel(const std::string& arguments, dealii::Triangulation<2>& tria);
  void make_cavity_plate(const std::string& arguments, dealii::Triangulation<2>& tria);

  /// The elastic tube benchmark's fluid (fvfsi_tube_fluid) and wall (fvfsi_tube_wall), in
  /// tube_meshes.cc.
  void make_tube_fluid(const std::string& arguments, dealii::Triangulation<3>& tria);
  void make_tube_wall(const std::string& arguments, dealii::Triangulation<3>& tria);

  /// The thick plate benchmark's channel (fvfsi_thick_plate_channel) and plate
  /// (fvfsi_thick_plate), in thick_plate_meshes.cc.
  void make_thick_plate_channel(const std::string& arguments, dealii::Triangulation<3>& tria);
  void make_thick_plate(const std::string& arguments, dealii::Triangulation<3>& tria);

  /// The plate in a channel (fvfsi_wall_plate_channel) and the plate (fvfsi_wall_plate), in
  /// wall_plate_meshes.cc.
  void make_wall_plate_channel(const std::string& arguments, dealii::Triangulation<2>& tria);
  void make_wall_plate(const std::string& arguments, dealii::Triangulation<2>& tria);

  template <int dim>
  void make_benchmark_mesh(const std::string& name, const std::string& arguments,
                           dealii::Triangulation<dim>& tria);
} // namespace fvfsi
