#pragma once
// Helpers shared by the FV core tests geometry.cc, vertex_interpolation.cc and gradients.cc.
//
// deal.II test convention: a test writes its results to a file called `output` in its working
// directory (rank 0 only), which ctest compares with NAME.output (or NAME.mpirun=2.output) by
// numdiff. Only stable text goes there: counts, fixed-precision numbers and yes/NO verdicts of
// round-off checks (never the round-off errors themselves). Setting FVFSI_TEST_VERBOSE=1 prints the
// measured errors to stderr, which is how the tolerances in the tests were chosen.

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/distributed/tria.h>

#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_builder.h>
#include <fvfsi/mesh/mesh_parameters.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace fvfsi_core_test
{
  using namespace dealii;

  /// The `output` file on rank 0, an unopened (silent) stream elsewhere.
  inline std::ofstream open_output()
  {
    std::ofstream out;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      out.open("output");
    return out;
  }

  inline bool verbose()
  {
    const char* v = std::getenv("FVFSI_TEST_VERBOSE");
    return v != nullptr && std::string(v) != "0";
  }

  /// printf-style formatting into a std::string.
  template <typename... Args>
  std::string format(const char* fmt, Args... args)
  {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, fmt, args...);
    return buffer;
  }

  /// One check: `error <= tolerance` on every rank (the error is reduced by MPI max). Writes
  /// "<what>: yes" (or "NO") to `out` and, with FVFSI_TEST_VERBOSE, the error to stderr.
  inline bool check(std::ostream& out, const std::string& what, const double local_error,
                    const double tolerance)
  {
    const double error = Utilities::MPI::max(local_error, MPI_COMM_WORLD);
    const bool ok = error <= tolerance; // a NaN fails
    out << what << " (< " << format("%.0e", tolerance) << "): " << (ok ? "yes" : "NO") << std::endl;
    if (verbose() && Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cerr << "  [" << what << "] error = " << format("%.3e", error) << std::endl;
    return ok;
  }

  /// A yes/no property that must hold on every rank (MPI logical and).
  inline bool check(std::ostream& out, const std::string& what, const bool local_ok)
  {
    const bool ok = Utilities::MPI::min(local_ok ? 1u : 0u, MPI_COMM_WORLD) == 1u;
    out << what << ": " << (ok ? "yes" : "NO") << std::endl;
    return ok;
  }

  /// A mesh of `generator` with `refinements`, its refined interior vertices shifted by `distortion`
  /// times the shortest adjacent edge (fvfsi's partition-independent hashed distortion).
  template <int dim>
  void make_test_mesh(parallel::distributed::Triangulation<dim>& tria, const std::string& generator,
                      const std::string& arguments, const unsigned int refinements,
                      const double distortion)
  {
    fvfsi::MeshParameters p;
    p.generator = generator;
    p.generator_arguments = arguments;
    p.n_global_refinements = refinements;
    p.distortion = distortion;
    p.distort_coarse_mesh = false;
    p.distortion_seed = 7;
    fvfsi::make_mesh(p, tria);
  }

  /// A distorted test mesh (make_test_mesh, distortion 0.25) and its FV geometry, announced by
  /// a line in `out` that names it.
  template <int dim>
  struct TestMesh
  {
    TestMesh(std::ostream& out, const std::string& generator, const std::string& arguments,
             const unsigned int refinements)
        : tria(MPI_COMM_WORLD)
    {
      out << "--- " << dim << "D " << generator << " (" << arguments << "), " << refinements
          << " refinements, distortion 0.25" << std::endl;
      make_test_mesh(tria, generator, arguments, refinements, 0.25);
      fv = std::make_unique<fvfsi::FVGeometry<dim>>(tria);
    }
    parallel::distributed::Triangulation<dim> tria;
    std::unique_ptr<fvfsi::FVGeometry<dim>> fv;
  };

  /// The main program of an exactness test: `test<dim>(out, generator, arguments, refinements)`
  /// on the four distorted meshes, the cube and the L-shape, 2D (4 and 3 refinements) and 3D (3
  /// and 2), the results in the file `output`.
  template <void (*test_2d)(std::ostream&, const std::string&, const std::string&, unsigned int),
            void (*test_3d)(std::ostream&, const std::string&, const std::string&, unsigned int)>
  int exactness_main(int argc, char** argv)
  {
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    std::ofstream out;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      out.open("output");
    test_2d(out, "hyper_cube", "-0.5 : 1.5 : true", 4);
    test_2d(out, "hyper_L", "-1 : 1 : false", 3);
    test_3d(out, "hyper_cube", "-0.5 : 1.5 : true", 3);
    test_3d(out, "hyper_L", "-1 : 1 : false", 2);
    return 0;
  }

  /// A field's exact values: at the cell centroids (ghosts included) and on the boundary and
  /// ghost_boundary faces (other entries 0).
  template <int dim, typename Field>
  void exact_values(const fvfsi::FVGeometry<dim>& fv, const Field& field, fvfsi::CellVector& phi,
                    fvfsi::FaceVector& boundary)
  {
    phi = fv.make_cell_vector();
    for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
      phi.local_element(c) = field(fv.centroid[c]);
    phi.update_ghost_values();
    boundary.assign(fv.faces.size(), 0.0);
    for (const unsigned int f : fv.all_boundary_faces())
      boundary[f] = field(fv.faces[f].centre);
  }

  /// phi = a + b . x, the field every linear-exactness check uses.
  template <int dim>
  struct LinearField
  {
    double a = 0.7;
    Tensor<1, dim> b;
    LinearField()
    {
      const double coefficients[3] = {1.3, -0.4, 0.9};
      for (unsigned int d = 0; d < dim; ++d)
        b[d] = coefficients[d];
    }
    double operator()(const Point<dim>& x) const { return a + b * x; }
  };

  /// Gather records of `width` doubles from all ranks to rank 0 (bit-exact: deal.II packs the raw
  /// bytes). Returns the concatenation on rank 0, nothing elsewhere.
  inline std::vector<double> gather_to_root(const std::vector<double>& local)
  {
    const auto all = Utilities::MPI::gather(MPI_COMM_WORLD, local, 0);
    std::vector<double> result;
    for (const auto& part : all)
      result.insert(result.end(), part.begin(), part.end());
    return result;
  }
} // namespace fvfsi_core_test
