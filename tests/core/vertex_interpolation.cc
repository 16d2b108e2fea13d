// VertexInterpolation (weighted least-squares vertex values, paper Appendix B) on randomly
// distorted meshes (distortion 0.25 of the refined mesh), 2D and 3D, serial and mpirun=2.
//
// Asserts:
//  - vertices() lists exactly the vertices of the locally owned cells;
//  - linear exactness: with cell values phi(r_P) and boundary values phi(r_f) of a linear field
//    phi = a + b.x on every boundary and ghost_boundary face, the interpolated value at every vertex
//    of an owned cell, interior and boundary vertices alike, is phi(x_v). The fit is a linear
//    least-squares fit, so this holds up to round-off; tolerance 1e-12 relative to max |phi|. The
//    measured errors (FVFSI_TEST_VERBOSE=1) are <= 7e-16 at interior vertices and <= 5e-14 at
//    boundary vertices, the largest at the domain corners, where the value is extrapolated from
//    one cell and dim boundary faces (larger coefficients amplify round-off); an O(h^2)
//    interpolation error would be ~1e-3;
//  - (a) the stencil of every vertex is complete: n_stencil_cells(i) equals the number of cells of
//    the whole mesh around that vertex. The global count is obtained by gathering the vertices of
//    all owned cells of all ranks to rank 0, keyed by their exact coordinates; the number of
//    distinct coordinates must be the mesh's vertex count (which also shows that all ranks hold
//    bitwise the same vertex positions). In parallel this proves the ghost layer holds every cell
//    that shares a vertex with an owned cell;
//  - (b) parallel consistency: for a non-linear field, every rank that computes a vertex value
//    computes exactly the same double (compared with ==; stencils are summed in global cell order).
//    On np = 2 at least one vertex must be shared by both ranks, so the check is not vacuous.

#include <deal.II/base/utilities.h>

#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/mesh/fv_geometry.h>

#include "fv_core_test_tools.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

using namespace dealii;
using namespace fvfsi_core_test;

template <int dim>
double nonlinear(const Point<dim>& x)
{
  double f = std::sin(3 * x[0]) * std::cos(2 * x[1]) + 0.3 * x[0] * x[1];
  if (dim == 3)
    f *= std::exp(0.5 * x[dim - 1]);
  return f;
}

/// Cell values f(r_P) (ghosts updated) and boundary values f(r_f) on every face without N.
/// (Filled in place: copying a LinearAlgebra::distributed::Vector zeroes its ghost entries.)
template <int dim, typename Function>
void sample(const fvfsi::FVGeometry<dim>& fv, const Function& f, fvfsi::CellVector& phi,
            fvfsi::FaceVector& boundary)
{
  phi.reinit(fv.partitioner());
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
    phi.local_element(c) = f(fv.centroid[c]);
  phi.update_ghost_values();
  boundary.assign(fv.faces.size(), 0.0);
  for (unsigned int i = 0; i < fv.faces.size(); ++i)
    if (fv.faces[i].N == fvfsi::invalid_cell)
      boundary[i] = f(fv.faces[i].centre);
}

template <int dim>
void test(std::ostream& out, const std::string& generator, const std::string& arguments,
          const unsigned int refinements, const unsigned int expected_vertices)
{
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const TestMesh<dim> mesh(out, generator, arguments, refinements);
  const fvfsi::FVGeometry<dim>& fv = *mesh.fv;
  const fvfsi::VertexInterpolation<dim> interpolation(fv);
  const auto& x = fv.vertices();

  // vertices() = the vertices of the owned cells.
  std::set<unsigned int> owned_cell_vertices;
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
    owned_cell_vertices.insert(fv.cell_vertices(c).begin(), fv.cell_vertices(c).end());
  std::set<unsigned int> listed(interpolation.vertices().begin(), interpolation.vertices().end());
  check(out, "vertices() are the vertices of the owned cells",
        listed == owned_cell_vertices && listed.size() == interpolation.vertices().size());

  // Linear exactness.
  {
    const LinearField<dim> phi_exact;
    fvfsi::CellVector phi;
    fvfsi::FaceVector boundary;
    sample(fv, phi_exact, phi, boundary);
    std::vector<double> values(x.size(), std::numeric_limits<double>::quiet_NaN());
    interpolation.interpolate(phi, boundary, values);
    std::vector<bool> at_boundary(x.size(), false);
    for (const auto& face : fv.faces)
      if (face.N == fvfsi::invalid_cell)
        for (const unsigned int v : face.vertices)
          at_boundary[v] = true;
    double scale = 0;
    for (const unsigned int v : interpolation.vertices())
      scale = std::max(scale, std::abs(phi_exact(x[v])));
    scale = Utilities::MPI::max(scale, MPI_COMM_WORLD);
    double interior_error = 0, boundary_error = 0;
    for (const unsigned int v : interpolation.vertices())
    {
      const double e = std::abs(values[v] - phi_exact(x[v])) / scale;
      double& error = at_boundary[v] ? boundary_error : interior_error;
      error = std::isfinite(e) ? std::max(error, e) : std::numeric_limits<double>::infinity();
    }
    check(out, "linear field exact at interior vertices", interior_error, 1e-12);
    check(out, "linear field exact at boundary vertices", boundary_error, 1e-12);
  }

  // (a) Stencil sizes against the global number of cells around each vertex.
  {
    std::vector<double> owned_corners, stencils; // (x, y[, z]) and (x, y[, z], n_stencil_cells)
    for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
      for (const unsigned int v : fv.cell_vertices(c))
        for (unsigned int d = 0; d < dim; ++d)
          owned_corners.push_back(x[v][d]);
    for (unsigned int i = 0; i < interpolation.vertices().size(); ++i)
    {
      for (unsigned int d = 0; d < dim; ++d)
        stencils.push_back(x[interpolation.vertices()[i]][d]);
      stencils.push_back(interpolation.n_stencil_cells(i));
    }
    const auto all_corners = gather_to_root(owned_corners);
    const auto all_stencils = gather_to_root(stencils);
    bool ok = true;
    std::map<std::array<double, dim>, unsigned int> n_cells_around;
    if (root)
    {
      for (std::size_t i = 0; i < all_corners.size(); i += dim)
      {
        std::array<double, dim> k;
        std::copy(all_corners.begin() + i, all_corners.begin() + i + dim, k.begin());
        ++n_cells_around[k];
      }
      for (std::size_t i = 0; i < all_stencils.size(); i += dim + 1)
      {
        std::array<double, dim> k;
        std::copy(all_stencils.begin() + i, all_stencils.begin() + i + dim, k.begin());
        const auto it = n_cells_around.find(k);
        ok = ok && it != n_cells_around.end() && double(it->second) == all_stencils[i + dim];
      }
      out << "distinct vertices: " << n_cells_around.size() << " (expected " << expected_vertices
          << ")" << std::endl;
    }
    check(out, "distinct vertex coordinates over all ranks = vertices of the mesh",
          !root || n_cells_around.size() == expected_vertices);
    check(out, "n_stencil_cells = global number of cells around the vertex, for every vertex", ok);
  }

  // (b) A non-linear field: identical bits on every rank that computes a vertex.
  {
    fvfsi::CellVector phi;
    fvfsi::FaceVector boundary;
    sample(fv, nonlinear<dim>, phi, boundary);
    std::vector<double> values;
    interpolation.interpolate(phi, boundary, values);
    std::vector<double> records; // (x, y[, z], value)
    for (const unsigned int v : interpolation.vertices())
    {
      for (unsigned int d = 0; d < dim; ++d)
        records.push_back(x[v][d]);
      records.push_back(values[v]);
    }
    const auto all = gather_to_root(records);
    bool same = true;
    unsigned int n_shared = 0;
    if (root)
    {
      std::map<std::array<double, dim>, std::pair<double, unsigned int>> first_value;
      for (std::size_t i = 0; i < all.size(); i += dim + 1)
      {
        std::array<double, dim> k;
        std::copy(all.begin() + i, all.begin() + i + dim, k.begin());
        const auto [it, inserted] = first_value.emplace(k, std::make_pair(all[i + dim], 0u));
        if (!inserted)
        {
          same = same && it->second.first == all[i + dim];
          if (it->second.second++ == 0)
            ++n_shared;
        }
      }
    }
    check(out, "non-linear field: every rank computes bitwise the same vertex value", same);
    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      check(out, "parallel: some vertices are computed by more than one rank",
            !root || n_shared > 0);
  }
}

int main(int argc, char** argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const auto pow = [](unsigned int b, unsigned int e)
  {
    unsigned int r = 1;
    while (e-- > 0)
      r *= b;
    return r;
  };
  // Vertex counts: (2^r + 1)^dim for the cube; for hyper_L the grid of the cube (-1, 1)^dim with
  // 2^(r+1) cells per direction, minus the (2^r)^dim grid points of the missing quadrant/octant
  // that do not lie on its faces shared with the remaining cells.
  test<2>(out, "hyper_cube", "-0.5 : 1.5 : true", 4, pow(17, 2));
  test<2>(out, "hyper_L", "-1 : 1 : false", 3, pow(17, 2) - pow(8, 2));
  test<3>(out, "hyper_cube", "-0.5 : 1.5 : true", 3, pow(9, 3));
  test<3>(out, "hyper_L", "-1 : 1 : false", 2, pow(9, 3) - pow(4, 3));
}
