#pragma once
// Builds the distributed mesh that a .prm file describes (`subsection Mesh`).

#include <deal.II/distributed/tria.h>

#include <fvfsi/mesh/mesh_parameters.h>

#include <string>

namespace fvfsi
{
  /**
   * Fill `tria` from `params`: a GridGenerator function or a mesh file, then global refinement, then
   * the optional random distortion of interior vertices. `prm_directory` resolves relative file names.
   * Throws std::runtime_error naming the parameter or the file on bad input, and on a mesh with
   * hanging faces (fvfsi's FV operators need conforming meshes).
   */
  template <int dim>
  void make_mesh(const MeshParameters& params,
                 dealii::parallel::distributed::Triangulation<dim>& tria,
                 const std::string& prm_directory = ".");

  /**
   * The coarse mesh of `params` alone (make_mesh() before its refinement and interior distortion):
   * what parallel::distributed::Triangulation::load() needs to read a checkpoint's mesh.
   */
  template <int dim>
  void make_coarse_mesh(const MeshParameters& params,
                        dealii::parallel::distributed::Triangulation<dim>& tria,
                        const std::string& prm_directory = ".");

  /**
   * Shift every interior vertex by `factor` times its shortest adjacent edge, in a random direction.
   * This is GridTools::distort_random's rule, but the random numbers are hashed from the vertex's
   * coordinates instead of drawn in rank-local vertex order, so every rank, and every number of
   * ranks, produces the same mesh (np = 2 can then be compared with np = 1).
   */
  template <int dim>
  void distort_interior_vertices(dealii::parallel::distributed::Triangulation<dim>& tria,
                                 double factor, unsigned int seed);
} // namespace fvfsi
