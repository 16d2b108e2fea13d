// Observed order of the FV Poisson solver (Eq. 19 Laplacian with deferred non-orthogonal
// correction, vertex-based Gauss-Green gradients) for a non-polynomial manufactured solution,
// in 2D and 3D, on systematically refined, randomly distorted meshes: the coarse mesh (8x8 in 2D,
// 4x4x4 in 3D) has every interior vertex moved by 0.25 of its shortest edge
// (GridTools::distort_random), and each finer mesh is its uniform subdivision.
//
// Asserted: the order of the max cell error on the finest pair is >= 1.9, and the order of the
// L2 face-normal-gradient error (Eq. 19, interior faces, weights S_f d_fn) is >= 1.5.
// Why not more for the face gradient: for a quadratic field, Eq. 19 with exact gradients errs by
// n.H.n (d_Nn - d_Pn)/2 + (k_P.H.k_P - k_N.H.k_N)/(2 d_fn), which is O(h^2) where the mesh is
// smooth (inside a coarse cell) but O(h) on the faces where two distorted coarse cells meet.
// Those faces are a fraction O(h) of all faces, so the L2 error falls as h^1.5 and the max error
// as h^1 (the printed max-norm orders approach 1; they are recorded so that a change is noticed).
//
// Errors are printed with 3 significant digits (numdiff's relative tolerance 1e-8 is then far
// below what Debug/Release round-off changes), orders with 2 decimals.
#include <fvfsi/apps/poisson.h>

#include "../test_utilities.h"

#include <cmath>
#include <vector>

using namespace fvfsi_test;

template <int dim>
void convergence(std::ofstream& out, const std::vector<unsigned int>& refinements)
{
  fvfsi::MeshParameters mesh;
  mesh.generator = "subdivided_hyper_cube";
  mesh.generator_arguments = dim == 2 ? "8: 0: 1: true" : "4: 0: 1: true";
  mesh.distortion = 0.25;
  mesh.distort_coarse_mesh = true;
  fvfsi::PoissonParameters parameters = manufactured_poisson<dim>();

  out << dim << "D: cells, max cell error, order, max face-gradient error, order, L2 face-gradient error, order\n";
  double previous_h = 0, previous_e = 0, previous_g = 0, previous_l2g = 0, cell_order = 0, l2g_order = 0;
  for (const unsigned int r : refinements)
  {
    mesh.n_global_refinements = r;
    fvfsi::PoissonProblem<dim> problem(mesh, parameters, MPI_COMM_WORLD);
    problem.run();
    const auto& res = problem.results();
    out << res.n_cells << "  " << format("%.3e", res.max_cell_error);
    if (previous_h > 0)
    {
      cell_order = std::log(previous_e / res.max_cell_error) / std::log(previous_h / res.h);
      const double g_order = std::log(previous_g / res.max_face_gradient_error) / std::log(previous_h / res.h);
      l2g_order = std::log(previous_l2g / res.l2_face_gradient_error) / std::log(previous_h / res.h);
      out << format("  %.2f", cell_order) << "  " << format("%.3e", res.max_face_gradient_error)
          << format("  %.2f", g_order) << "  " << format("%.3e", res.l2_face_gradient_error)
          << format("  %.2f", l2g_order);
    }
    else
      out << "  -  " << format("%.3e", res.max_face_gradient_error) << "  -  "
          << format("%.3e", res.l2_face_gradient_error) << "  -";
    out << "\n";
    previous_h = res.h;
    previous_e = res.max_cell_error;
    previous_g = res.max_face_gradient_error;
    previous_l2g = res.l2_face_gradient_error;
  }
  out << dim << "D: order of the max cell error on the finest pair >= 1.9: " << yes_no(cell_order >= 1.9)
      << "\n";
  out << dim << "D: order of the L2 face-gradient error on the finest pair >= 1.5: "
      << yes_no(l2g_order >= 1.5) << "\n";
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  convergence<2>(out, {1, 2, 3});
  convergence<3>(out, {1, 2, 3});
}
