#pragma once
// The finite-volume geometry of a (distributed) mesh: per cell the centroid r_P and volume V_P, per
// face the centre r_f, area vector S_f n_f, d_f, d_fn, k_P, k_N and interpolation weight
// (paper section 3.1, Eqs 19-22, Appendix A). Computed from the vertex positions by triangle
// decomposition, stored, and recomputed only by reinit() when the vertices move. Face loops read
// these arrays; they never recompute geometry.

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <fvfsi/mesh/boundary_face_exchange.h>

#include <array>
#include <memory>
#include <vector>

namespace fvfsi
{
  /// A cell field with one value per locally owned cell, followed by the ghost cells' values.
  using CellVector = dealii::LinearAlgebra::distributed::Vector<double>;

  /// Marks "no cell" (the missing neighbour of a boundary face).
  constexpr unsigned int invalid_cell = static_cast<unsigned int>(-1);

  /// A point's coordinates as a map key: the exact bits of the doubles, which every rank computes
  /// identically for the same vertex (interface zones, parallel-consistency tests).
  template <int dim>
  std::array<double, dim> point_key(const dealii::Point<dim>& x)
  {
    std::array<double, dim> key;
    for (unsigned int d = 0; d < dim; ++d)
      key[d] = x[d];
    return key;
  }

  /// Which cells a face separates, and so who assembles it.
  enum class FaceKind : unsigned char
  {
    interior,      ///< between two locally owned cells
    processor,     ///< between a locally owned cell P and a ghost cell N
    boundary,      ///< a domain-boundary face of a locally owned cell
    ghost_boundary ///< a domain-boundary face of a ghost cell (only for vertex stencils)
  };

  template <int dim>
  struct FaceGeometry
  {
    static constexpr unsigned int max_vertices = dealii::GeometryInfo<dim>::vertices_per_face;

    unsigned int P = invalid_cell; ///< local index of the owner cell (the side S_f points out of)
    unsigned int N = invalid_cell; ///< local index of the neighbour, invalid_cell at a boundary
    unsigned int patch = 0;        ///< boundary id (boundary faces only)
    unsigned int face_no = 0;      ///< number of this face within cell P
    FaceKind kind = FaceKind::interior;
    /// True on exactly one rank for every face of the mesh: use it for global sums over faces.
    bool counted_here = true;

    dealii::Point<dim> centre;  ///< r_f [m]
    dealii::Tensor<1, dim> S;   ///< S_f n_f, pointing out of P [m^(dim-1)]
    double area = 0;            ///< S_f [m^(dim-1)]
    dealii::Tensor<1, dim> n;   ///< n_f, unit normal out of P
    dealii::Tensor<1, dim> d;   ///< d_f = r_N - r_P (boundary: r_f - r_P) [m]
    double d_n = 0;             ///< d_fn = n_f . d_f [m]
    dealii::Tensor<1, dim> k_P; ///< k_P = (I - n n) . (r_f - r_P)  (Eq. 21)
    dealii::Tensor<1, dim> k_N; ///< k_N = (I - n n) . (r_N - r_f)  (Eq. 22), zero at a boundary
    double w = 1;               ///< phi_f = w phi_P + (1 - w) phi_N (linear interpolation)

    /// phi_f = w phi_P + (1 - w) phi_N: a cell quantity (a number, vector, tensor or point)
    /// interpolated linearly to the face centre, as the solvers interpolate to faces.
    template <typename T>
    T interpolate(const T& at_P, const T& at_N) const
    {
      return w * at_P + (1 - w) * at_N;
    }
    /// (1/a)_f = w / a_P + (1 - w) / a_N: the interpolated reciprocal of a cell coefficient (the
    /// 1/a of the Rhie-Chow face flux).
    double interpolate_reciprocal(const double a_P, const double a_N) const
    {
      return w / a_P + (1 - w) / a_N;
    }

    /// Triangulation vertex indices, in cyclic order counter-clockwise about n_f.
    std::array<unsigned int, max_vertices> vertices;
    /// Weights of the vertex values in the Gauss-Green surface sum of Eq. 37:
    /// sum_tau n_tau phi_tau S_tau = sum_i gauss_green_weight[i] phi_{v_i}.
    std::array<dealii::Tensor<1, dim>, max_vertices> gauss_green_weight;
    /// Weights of the vertex values in the face tangential gradient of Eq. 39:
    /// (grad_s phi)_f = sum_i tangential_weight[i] phi_{v_i}.
    std::array<dealii::Tensor<1, dim>, max_vertices> tangential_weight;
  };

  template <int dim>
  class FVGeometry
  {
  public:
    using active_cell_iterator = typename dealii::DoFHandler<dim>::active_cell_iterator;

    /// Number the cells (one FE_DGQ(0) dof per cell) and compute the geometry from the
    /// triangulation's current vertex positions.
    explicit FVGeometry(const dealii::parallel::distributed::Triangulation<dim>& tria);

    /// Recompute all cell and face geometry from `vertex_positions` (indexed like the
    /// triangulation's vertices). Call once after every mesh motion.
    void reinit(const std::vector<dealii::Point<dim>>& vertex_positions);

    /// The volume [m^dim] each face sweeps when the vertices move from `old_positions` to
    /// `new_positions` (indexed like the triangulation's vertices), positive where the face moves
    /// out of its owner P, indexed like `faces`. Built from the same face pieces as the cell
    /// volumes, so that for every cell sum_f (+-) dV_f = V_P(new) - V_P(old) to round-off: the
    /// space conservation law (Eq. 3) holds exactly for mesh fluxes made of these volumes
    /// (source/mesh/swept_volume.cc). Needs no reinit(): a coupling iteration computes the swept
    /// volumes from the step's start positions and then the geometry once at the new ones.
    std::vector<double> swept_volumes(const std::vector<dealii::Point<dim>>& old_positions,
                                      const std::vector<dealii::Point<dim>>& new_positions) const;

    MPI_Comm comm() const { return tria.get_communicator(); }
    const dealii::parallel::distributed::Triangulation<dim>& triangulation() const { return tria; }
    const dealii::DoFHandler<dim>& dof_handler() const { return dofs; }
    const std::shared_ptr<const dealii::Utilities::MPI::Partitioner>& partitioner() const
    {
      return cell_partitioner;
    }

    unsigned int n_owned_cells() const { return n_owned; }
    unsigned int n_relevant_cells() const { return cell_volume.size(); }
    dealii::types::global_cell_index n_global_cells() const { return dofs.n_dofs(); }
    /// Global number of cell `c` (its dof index): the same on every rank within one run.
    dealii::types::global_dof_index global_index(unsigned int c) const
    {
      return cell_partitioner->local_to_global(c);
    }
    const active_cell_iterator& cell(unsigned int c) const { return cells[c]; }

    /// A zero cell field with ghost entries.
    CellVector make_cell_vector() const { return CellVector(cell_partitioner); }

    const std::vector<dealii::Point<dim>>& vertices() const { return vertex_positions; }
    /// Vertex indices of cell c (deal.II's lexicographic order).
    const std::array<unsigned int, dealii::GeometryInfo<dim>::vertices_per_cell>&
    cell_vertices(unsigned int c) const
    {
      return cell_vertex_indices[c];
    }
    /// Local face indices of cell c (owned cells: all faces; ghost cells: their boundary faces).
    const std::vector<unsigned int>& cell_faces(unsigned int c) const { return faces_of_cell[c]; }
    /// The number of faces of owned cells (kinds interior, processor, boundary): they come first
    /// in `faces`, the ghost_boundary faces after them.
    unsigned int n_owned_cell_faces() const { return n_faces_of_owned_cells; }
    /// The faces of kind `boundary` (domain-boundary faces of owned cells).
    const std::vector<unsigned int>& boundary_faces() const { return boundary_face_list; }
    /// The faces of kinds `boundary` and `ghost_boundary`.
    const std::vector<unsigned int>& all_boundary_faces() const { return all_boundary_face_list; }
    /// Copies per-face values of boundary faces to the ghost_boundary faces of the neighbours.
    const BoundaryFaceExchange& boundary_face_exchange() const { return boundary_exchange; }

    std::vector<dealii::Point<dim>> centroid; ///< r_P [m]
    std::vector<double> cell_volume;          ///< V_P [m^dim] (area in 2D: true 2D, unit depth)
    std::vector<FaceGeometry<dim>> faces;     ///< interior, processor, boundary, ghost_boundary

  private:
    void number_cells();
    void collect_faces();
    void compute_cell_geometry();
    void compute_face_geometry(FaceGeometry<dim>& face) const;
    /// The weights of the face tangential gradient (Eq. 39) of `face`, its normal and area set.
    void set_tangential_weights(FaceGeometry<dim>& face) const;

    const dealii::parallel::distributed::Triangulation<dim>& tria;
    dealii::FE_DGQ<dim> fe;
    dealii::DoFHandler<dim> dofs;
    std::shared_ptr<const dealii::Utilities::MPI::Partitioner> cell_partitioner;
    unsigned int n_owned = 0;
    std::vector<active_cell_iterator> cells;
    std::vector<std::array<unsigned int, dealii::GeometryInfo<dim>::vertices_per_cell>>
      cell_vertex_indices;
    std::vector<std::vector<unsigned int>> faces_of_cell;
    std::vector<unsigned int> boundary_face_list, all_boundary_face_list;
    unsigned int n_faces_of_owned_cells = 0;
    BoundaryFaceExchange boundary_exchange;
    /// Per cell and face: the face's vertices, counter-clockwise about the outward normal.
    std::vector<std::array<std::array<unsigned int, dealii::GeometryInfo<dim>::vertices_per_face>,
                           dealii::GeometryInfo<dim>::faces_per_cell>>
      cell_polygons;
    std::vector<dealii::Point<dim>> vertex_positions;
  };

  /// One mesh motion, from `old_positions` to `new_positions` (indexed like the triangulation's
  /// vertices): the swept volumes of every face (FVGeometry::swept_volumes, the mesh fluxes'
  /// volumes), then the geometry at the new positions (FVGeometry::reinit) and the vertices of the
  /// triangulation itself (for output and point location). Returns the swept volumes.
  template <int dim>
  std::vector<double> move_mesh(FVGeometry<dim>& geometry,
                                dealii::parallel::distributed::Triangulation<dim>& tria,
                                const std::vector<dealii::Point<dim>>& old_positions,
                                const std::vector<dealii::Point<dim>>& new_positions);
} // namespace fvfsi
