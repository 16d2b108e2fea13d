#pragma once
// The Jacobian dF/dx of a finite-volume residual F(x), assembled by probing: F is evaluated at
// x + h sum_{a of colour k} s_a e_(a,j) for every colour k and component j, and the change of each
// row is the entry of the one node of colour k that the row depends on. The nodes are the cells
// (one per cell) and optional extra nodes attached to a cell (e.g. boundary-face unknowns), each
// with `block_size` unknowns stored consecutively (the block layout that AMG for vector problems
// needs). The caller states the stencil radius R: the rows of a node at cell P depend only on the
// nodes at cells within R vertex-neighbour steps of P. Two nodes get different colours if their
// cells are within 2R steps, so no row sees two nodes of one colour.
//
// The colouring is computed from the global cell graph (cells, their vertex neighbours and their
// nodes, in global cell numbers), gathered on every rank: the same greedy colouring in global
// cell order on every rank and for every number of ranks. The price is O(n_global_cells) memory per
// rank (about 100 bytes per cell in 2D): fine for the meshes fvfsi runs (up to ~10^6 cells).
//
// For an affine F the probed Jacobian is exact up to round-off, for any step h; for a nonlinear F
// it is the forward-difference approximation. Rows that do not depend on a probed node see the
// same bits in both evaluations, so structural zeros come out exactly zero and are left out of
// the sparsity pattern.

#include <deal.II/base/index_set.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/mesh/fv_geometry.h>

#include <functional>
#include <vector>

namespace fvfsi
{
  template <int dim>
  class ProbedJacobian
  {
  public:
    using Vector = dealii::LinearAlgebra::distributed::Vector<double>;
    using Residual = std::function<void(const Vector& x, Vector& F)>;

    /// `extra_nodes[c]`: number of extra nodes of owned cell c (stored after the cell's own node);
    /// `node_scale[i]` (per local node, in the order of local_node()): the probe of node i moves
    /// its unknowns by h node_scale[i]. Collective.
    ProbedJacobian(const FVGeometry<dim>& geometry, const std::vector<unsigned int>& extra_nodes,
                   const std::vector<double>& node_scale, unsigned int block_size,
                   unsigned int radius);

    /// Local index of node i of owned cell c (i = 0: the cell's own node, then its extra nodes).
    unsigned int local_node(const unsigned int c, const unsigned int i = 0) const
    {
      return node_start[c] + i;
    }
    unsigned int n_local_nodes() const { return node_start.back(); }
    unsigned int block_size() const { return components; }
    /// The locally owned unknowns (global numbers node * block_size + j).
    const dealii::IndexSet& owned_unknowns() const { return owned; }
    /// A zero vector of the unknowns (owned entries only); local_element(node * block_size + j).
    Vector make_vector() const { return Vector(owned, geometry.comm()); }
    unsigned int n_colours() const { return colour_count; }

    /// J = dF/dx at x (F_x = F(x)) into `matrix` (rebuilt with the sparsity found); `residual` is
    /// called n_colours() x block_size() times (collective). `central`: central differences
    /// (F(x + h p) - F(x - h p)) / 2h, twice the evaluations, error O(h^2) instead of O(h).
    void assemble(const Residual& residual, const Vector& x, const Vector& F_x, double h,
                  bool central, dealii::TrilinosWrappers::SparseMatrix& matrix) const;

  private:
    /// The entries (global column, value) of one row.
    using Row = std::vector<std::pair<dealii::types::global_dof_index, double>>;
    /// `matrix` with the sparsity and values of `rows` (the owned rows, in local order).
    void build_matrix(const std::vector<Row>& rows,
                      dealii::TrilinosWrappers::SparseMatrix& matrix) const;
    /// The global cell graph and the nodes of every cell, gathered on every rank.
    void gather_graph(const std::vector<unsigned int>& extra_nodes,
                      const std::vector<double>& node_scale);
    /// Cells within `depth` vertex-neighbour steps of global cell `start` (including it).
    void ball(unsigned long long start, unsigned int depth,
              std::vector<unsigned long long>& cells) const;
    void colour_nodes(unsigned int radius);
    void find_stencils(unsigned int radius);

    const FVGeometry<dim>& geometry;
    unsigned int components;
    std::vector<unsigned int> node_start; ///< per owned cell (CSR), plus the total
    unsigned long long first_node = 0;    ///< global number of this rank's first node
    dealii::IndexSet owned;

    // Global graph: per global cell its first global node, node count and vertex neighbours.
    std::vector<unsigned long long> global_first_node, neighbour_start, neighbours;
    std::vector<unsigned int> global_n_nodes;
    std::vector<double> global_node_scale; ///< per global node
    std::vector<unsigned int> colour;      ///< per global node
    unsigned int colour_count = 0;
    mutable std::vector<unsigned int> stamp; ///< BFS marks per global cell
    mutable unsigned int current_stamp = 0;

    /// Per owned cell: the (colour, global node) pairs of the nodes within the stencil radius,
    /// sorted by colour.
    std::vector<std::vector<std::pair<unsigned int, unsigned long long>>> stencil;
  };
} // namespace fvfsi
