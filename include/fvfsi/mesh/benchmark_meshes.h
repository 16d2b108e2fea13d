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
   * Fill `tria` with the benchmark mesh `name` ("fvfsi_quarter_plate_with_hole" or
   * "fvfsi_turek_hron_flag"), `arguments` separated by `:`.
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
   */
  /// The Turek-Hron fluid domain (fvfsi_turek_hron_channel), in turek_hron_channel.cc.
  void make_turek_hron_channel(const std::string& arguments, dealii::Triangulation<2>& tria);

  template <int dim>
  void make_benchmark_mesh(const std::string& name, const std::string& arguments, dealii::Triangulation<dim>& tria);
} // namespace fvfsi
