// Laplace mesh motion (MeshMotion, Type = Laplace), 2D and 3D, serial and mpirun=2.
//
// Asserted, on randomly distorted meshes (distortion 0.25) of the unit square / cube:
//  - an affine motion of the whole boundary, d = A X + b, moves every vertex affinely: the FV
//    Laplacian with uniform diffusivity and converged non-orthogonal corrections (30), and the
//    least-squares vertex reconstruction (App. B), are exact for linear fields; error relative to
//    max |d| below 1e-6 (the linear solver's 1e-8 reduction sets the level; measured ~1e-9);
//  - the same with the quadratic-inverse-distance diffusivity when only one patch moves, rigidly
//    (d = b on the moving patch x = 0... every vertex then satisfies 0 <= d.b/|b|^2 <= 1 and
//    the vertices of the moving patch move by exactly b (boundary vertices take the given value);
//  - a patch displacement set from outside (MeshMotion::set_patch_displacement, used by the FSI
//    coupling) gives the same vertex positions as the same displacement given by an expression;
//  - a sliding patch (the bottom y = 0): the other patches move by an affine field with a zero
//    normal component and a zero normal gradient there, d = (0.1 x + 0.02, 0.08 y[, 0.01 x -
//    0.06 z]); the sliding vertices' in-plane motion comes from the solution, and every vertex
//    must move by d (the same 1e-6 as the affine case); a patch both moving and sliding is an
//    error naming it;
//  - every rank computes the same vertex positions (mpirun=2 output equals the serial one: the
//    printed sums over owned cells' vertices, each vertex converged to the solver's 1e-8
//    reduction, agree to the 4 printed decimals; numdiff's default 1e-6 tolerance applies).
#include <fvfsi/ale/mesh_motion.h>

#include <fvfsi/base/parsed_function.h>

#include "fv_core_test_tools.h"

#include <cmath>

using namespace fvfsi_core_test;

// max |x_v - X_v - d(X_v)| / max |d(X_v)| over the vertices of the owned cells, d the expression
// at t = 1 s.
template <int dim>
double relative_error(const fvfsi::FVGeometry<dim>& reference, const std::vector<Point<dim>>& x,
                      const std::string& d_expression)
{
  FunctionParser<dim> exact(dim);
  fvfsi::initialize_function(exact, d_expression, "test");
  exact.set_time(1.0);
  double error = 0, scale = 0;
  for (unsigned int c = 0; c < reference.n_owned_cells(); ++c)
    for (const unsigned int v : reference.cell_vertices(c))
      for (unsigned int j = 0; j < dim; ++j)
      {
        const double d = exact.value(reference.vertices()[v], j);
        error = std::max(error, std::abs(x[v][j] - reference.vertices()[v][j] - d));
        scale = std::max(scale, std::abs(d));
      }
  return Utilities::MPI::max(error, MPI_COMM_WORLD) / Utilities::MPI::max(scale, MPI_COMM_WORLD);
}

template <int dim>
void run(std::ofstream& out)
{
  parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
  make_test_mesh(tria, "subdivided_hyper_cube", dim == 2 ? "8: 0: 1: true" : "4: 0: 1: true", 1,
                 0.25);
  fvfsi::FVGeometry<dim> reference(tria);
  fvfsi::MeshParameters mesh;
  mesh.patch_names = {{0, "left"}, {1, "right"}, {2, "bottom"}, {3, "top"}};
  if (dim == 3)
    mesh.patch_names.insert({{4, "front"}, {5, "back"}});

  // Affine motion of the whole boundary.
  const std::string d_affine = dim == 2
                                 ? "0.1*x - 0.05*y + 0.02*t; 0.03*x + 0.08*y"
                                 : "0.1*x - 0.05*y + 0.02*z + 0.02*t; 0.03*x + 0.08*y - 0.04*z; "
                                   "0.05*x + 0.01*y - 0.06*z";
  fvfsi::TimeControl clock(1.0, 1.0); // the motion at t = 1 s
  clock.advance();
  fvfsi::MeshMotionParameters p;
  p.type = fvfsi::MeshMotionParameters::Type::laplace;
  p.diffusivity = fvfsi::MeshMotionParameters::Diffusivity::uniform;
  p.non_orthogonal_correctors = 30;
  for (const auto& [id, name] : mesh.patch_names)
    p.moving_patches += (p.moving_patches.empty() ? "" : " | ") + name + ": " + d_affine;
  fvfsi::MeshMotion<dim> affine(reference, mesh, p, clock);
  check(out, format("%dD: affine boundary motion moves every vertex affinely", dim),
        relative_error(reference, affine.vertex_positions(), d_affine), 1e-6);

  // The bottom slides, the other patches move by d_slide.
  const std::string d_slide =
    dim == 2 ? "0.1*x + 0.02; 0.08*y" : "0.1*x + 0.02; 0.08*y; 0.01*x - 0.06*z";
  p.moving_patches.clear();
  for (const auto& [id, name] : mesh.patch_names)
    if (name != "bottom")
      p.moving_patches += (p.moving_patches.empty() ? "" : " | ") + name + ": " + d_slide;
  p.sliding_patches = "bottom";
  fvfsi::MeshMotion<dim> sliding(reference, mesh, p, clock);
  check(
    out,
    format("%dD: a sliding patch with affine motion elsewhere moves every vertex affinely", dim),
    relative_error(reference, sliding.vertex_positions(), d_slide), 1e-6);
  p.sliding_patches = "bottom, right";
  bool named = false;
  try
  {
    fvfsi::MeshMotion<dim> both(reference, mesh, p, clock);
  }
  catch (const std::exception& e)
  {
    named = std::string(e.what()).find("`right` is both a Moving and a Sliding patch") !=
            std::string::npos;
  }
  check(out, format("%dD: a patch both moving and sliding is an error naming it", dim), named);
  p.sliding_patches.clear();

  // One patch translated rigidly, quadratic inverse distance diffusivity.
  p.diffusivity = fvfsi::MeshMotionParameters::Diffusivity::quadratic_inverse_distance;
  p.non_orthogonal_correctors = 2;
  p.moving_patches = dim == 2 ? "left: 0.1; 0.05" : "left: 0.1; 0.05; 0.02";
  fvfsi::MeshMotion<dim> rigid(reference, mesh, p, clock);
  const auto y = rigid.vertex_positions();
  Tensor<1, dim> b;
  b[0] = 0.1;
  b[1] = 0.05;
  if (dim == 3)
    b[2] = 0.02;
  bool bounded = true, patch_exact = true;
  double sum = 0;
  for (unsigned int c = 0; c < reference.n_owned_cells(); ++c)
    for (const unsigned int v : reference.cell_vertices(c))
    {
      const Tensor<1, dim> d = y[v] - reference.vertices()[v];
      const double s = d * b / b.norm_square();
      bounded = bounded && s >= -1e-12 && s <= 1 + 1e-12;
      if (std::abs(reference.vertices()[v][0]) < 1e-12)
        patch_exact = patch_exact && (d - b).norm() < 1e-14;
      sum += s;
    }
  const auto all = [](const bool b) { return Utilities::MPI::min(b ? 1 : 0, MPI_COMM_WORLD) == 1; };
  check(out, format("%dD: one patch moved rigidly, every vertex moves between 0 and b", dim),
        all(bounded));
  check(out, format("%dD: the moving patch's vertices move by exactly b", dim), all(patch_exact));

  // The same motion with the patch displacement given from outside (as the FSI coupling does):
  // the patch starts fixed and receives d = b at its vertices; the vertex positions must agree
  // with the expression-driven run to round-off (the same linear systems are solved).
  p.moving_patches = dim == 2 ? "left: 0; 0" : "left: 0; 0; 0";
  fvfsi::MeshMotion<dim> external(reference, mesh, p, clock);
  std::vector<Tensor<1, dim>> given(reference.vertices().size());
  for (const unsigned int v : external.patch_vertices("left"))
    given[v] = b;
  external.set_patch_displacement("left", given);
  const auto z = external.vertex_positions();
  double difference = 0;
  for (unsigned int c = 0; c < reference.n_owned_cells(); ++c)
    for (const unsigned int v : reference.cell_vertices(c))
      difference = std::max(difference, (z[v] - y[v]).norm());
  check(out,
        format("%dD: patch displacement set from outside moves the mesh as the expression", dim),
        Utilities::MPI::max(difference, MPI_COMM_WORLD), 1e-14);
  out << format("%dD: sum over owned cells' vertices of d.b/|b|^2: %.4f", dim,
                Utilities::MPI::sum(sum, MPI_COMM_WORLD))
      << std::endl;
}

int main(int argc, char** argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  run<2>(out);
  run<3>(out);
}
