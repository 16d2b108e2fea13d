#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <fvfsi/fv/probed_jacobian.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    /// All ranks' `local` arrays, concatenated in rank order, on every rank.
    template <typename T>
    std::vector<T> all_gather_concatenated(const std::vector<T>& local, MPI_Comm comm,
                                           MPI_Datatype type)
    {
      const int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      const int size = local.size();
      std::vector<int> sizes(n_ranks), offsets(n_ranks + 1, 0);
      MPI_Allgather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, comm);
      for (int r = 0; r < n_ranks; ++r)
        offsets[r + 1] = offsets[r] + sizes[r];
      std::vector<T> all(offsets[n_ranks]);
      MPI_Allgatherv(local.data(), size, type, all.data(), sizes.data(), offsets.data(), type,
                     comm);
      return all;
    }
  } // namespace

  template <int dim>
  ProbedJacobian<dim>::ProbedJacobian(const FVGeometry<dim>& geometry,
                                      const std::vector<unsigned int>& extra_nodes,
                                      const std::vector<double>& node_scale,
                                      const unsigned int block_size, const unsigned int radius)
      : geometry(geometry), components(block_size)
  {
    node_start = {0};
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
      node_start.push_back(node_start.back() + 1 + extra_nodes[c]);
    const unsigned long long n_local = n_local_nodes();
    MPI_Exscan(&n_local, &first_node, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, geometry.comm());
    if (Utilities::MPI::this_mpi_process(geometry.comm()) == 0)
      first_node = 0; // MPI_Exscan leaves rank 0's result undefined
    const unsigned long long n_global = Utilities::MPI::sum(n_local, geometry.comm());
    owned = IndexSet(n_global * components);
    owned.add_range(first_node * components, (first_node + n_local) * components);
    owned.compress();
    gather_graph(extra_nodes, node_scale);
    colour_nodes(radius);
    find_stencils(radius);
  }

  template <int dim>
  void ProbedJacobian<dim>::gather_graph(const std::vector<unsigned int>& extra_nodes,
                                         const std::vector<double>& node_scale)
  {
    // Vertex neighbours of the owned cells: the p4est ghost layer holds every cell that shares a
    // vertex with an owned cell.
    std::vector<std::vector<unsigned int>> cells_at_vertex(geometry.vertices().size());
    for (unsigned int c = 0; c < geometry.n_relevant_cells(); ++c)
      for (const unsigned int v : geometry.cell_vertices(c))
        cells_at_vertex[v].push_back(c);
    // Per owned cell: global index, first global node, node count, neighbour count, neighbours.
    std::vector<unsigned long long> record;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      std::vector<unsigned long long> n;
      for (const unsigned int v : geometry.cell_vertices(c))
        for (const unsigned int d : cells_at_vertex[v])
          if (d != c)
            n.push_back(geometry.global_index(d));
      std::sort(n.begin(), n.end());
      n.erase(std::unique(n.begin(), n.end()), n.end());
      record.insert(record.end(), {geometry.global_index(c), first_node + node_start[c],
                                   1ull + extra_nodes[c], n.size()});
      record.insert(record.end(), n.begin(), n.end());
    }
    const auto all = all_gather_concatenated(record, geometry.comm(), MPI_UNSIGNED_LONG_LONG);
    const unsigned long long n_cells = geometry.n_global_cells();
    global_first_node.assign(n_cells, 0);
    global_n_nodes.assign(n_cells, 0);
    std::vector<std::vector<unsigned long long>> lists(n_cells);
    for (std::size_t i = 0; i < all.size(); i += 4 + all[i + 3])
    {
      global_first_node[all[i]] = all[i + 1];
      global_n_nodes[all[i]] = all[i + 2];
      lists[all[i]].assign(all.begin() + i + 4, all.begin() + i + 4 + all[i + 3]);
    }
    neighbour_start = {0};
    for (const auto& l : lists)
    {
      neighbours.insert(neighbours.end(), l.begin(), l.end());
      neighbour_start.push_back(neighbours.size());
    }
    // The node scales, in global node order (rank order = global node order).
    global_node_scale = all_gather_concatenated(node_scale, geometry.comm(), MPI_DOUBLE);
    stamp.assign(n_cells, 0);
  }

  template <int dim>
  void ProbedJacobian<dim>::ball(const unsigned long long start, const unsigned int depth,
                                 std::vector<unsigned long long>& cells) const
  {
    ++current_stamp;
    cells = {start};
    stamp[start] = current_stamp;
    std::size_t begin = 0;
    for (unsigned int level = 0; level < depth; ++level)
    {
      const std::size_t end = cells.size();
      for (std::size_t i = begin; i < end; ++i)
        for (auto k = neighbour_start[cells[i]]; k < neighbour_start[cells[i] + 1]; ++k)
          if (stamp[neighbours[k]] != current_stamp)
          {
            stamp[neighbours[k]] = current_stamp;
            cells.push_back(neighbours[k]);
          }
      begin = end;
    }
  }

  template <int dim>
  void ProbedJacobian<dim>::colour_nodes(const unsigned int radius)
  {
    // Greedy in global cell order: every node takes the smallest colour that no node within
    // 2 R steps has (the same result on every rank).
    constexpr unsigned int none = static_cast<unsigned int>(-1);
    colour.assign(global_node_scale.size(), none);
    std::vector<unsigned long long> cells;
    std::vector<bool> used;
    for (unsigned long long gc = 0; gc < global_first_node.size(); ++gc)
    {
      ball(gc, 2 * radius, cells);
      used.assign(used.size(), false);
      for (const auto d : cells)
        for (unsigned int i = 0; i < global_n_nodes[d]; ++i)
          if (const unsigned int k = colour[global_first_node[d] + i]; k != none)
          {
            if (k >= used.size())
              used.resize(k + 1, false);
            used[k] = true;
          }
      for (unsigned int i = 0; i < global_n_nodes[gc]; ++i)
      {
        unsigned int k = 0;
        while (k < used.size() && used[k])
          ++k;
        if (k >= used.size())
          used.resize(k + 1, false);
        used[k] = true;
        colour[global_first_node[gc] + i] = k;
        colour_count = std::max(colour_count, k + 1);
      }
    }
  }

  template <int dim>
  void ProbedJacobian<dim>::find_stencils(const unsigned int radius)
  {
    stencil.resize(geometry.n_owned_cells());
    std::vector<unsigned long long> cells;
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
    {
      ball(geometry.global_index(c), radius, cells);
      auto& s = stencil[c];
      for (const auto d : cells)
        for (unsigned int i = 0; i < global_n_nodes[d]; ++i)
          s.emplace_back(colour[global_first_node[d] + i], global_first_node[d] + i);
      std::sort(s.begin(), s.end());
      for (std::size_t i = 1; i < s.size(); ++i)
        if (s[i].first == s[i - 1].first)
          throw std::logic_error("ProbedJacobian: two nodes of one colour in a stencil");
    }
  }

  template <int dim>
  void ProbedJacobian<dim>::assemble(const Residual& residual, const Vector& x, const Vector& F_x,
                                     const double h, const bool central,
                                     TrilinosWrappers::SparseMatrix& matrix) const
  {
    std::vector<std::vector<unsigned int>> nodes_of_colour(colour_count);
    for (unsigned int a = 0; a < n_local_nodes(); ++a)
      nodes_of_colour[colour[first_node + a]].push_back(a);
    // Entries per local row: (global column, value).
    std::vector<Row> rows(n_local_nodes() * components);
    Vector x_probe(x), F(F_x), F_back(F_x);
    const auto probe =
      [&](const unsigned int k, const unsigned int j, const double step, Vector& result)
    {
      for (const unsigned int a : nodes_of_colour[k])
        x_probe.local_element(a * components + j) += step * global_node_scale[first_node + a];
      residual(x_probe, result);
      for (const unsigned int a : nodes_of_colour[k])
        x_probe.local_element(a * components + j) = x.local_element(a * components + j);
    };
    const double width = central ? 2 * h : h;
    for (unsigned int k = 0; k < colour_count; ++k)
      for (unsigned int j = 0; j < components; ++j)
      {
        probe(k, j, h, F);
        if (central)
          probe(k, j, -h, F_back);
        const Vector& base = central ? F_back : F_x;
        for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
        {
          const auto& s = stencil[c];
          const auto it = std::lower_bound(s.begin(), s.end(), std::make_pair(k, 0ull));
          if (it == s.end() || it->first != k)
            continue;
          const double step = width * global_node_scale[it->second];
          const types::global_dof_index column = it->second * components + j;
          for (unsigned int row = node_start[c] * components; row < node_start[c + 1] * components;
               ++row)
            if (const double change = F.local_element(row) - base.local_element(row); change != 0)
              rows[row].emplace_back(column, change / step);
        }
      }
    build_matrix(rows, matrix);
  }

  template <int dim>
  void ProbedJacobian<dim>::build_matrix(const std::vector<Row>& rows,
                                         TrilinosWrappers::SparseMatrix& matrix) const
  {
    DynamicSparsityPattern dsp(owned.size(), owned.size(), owned);
    const types::global_dof_index first_row = first_node * components;
    for (unsigned int row = 0; row < rows.size(); ++row)
      for (const auto& [column, value] : rows[row])
        dsp.add(first_row + row, column);
    matrix.reinit(owned, owned, dsp, geometry.comm());
    std::vector<types::global_dof_index> columns;
    std::vector<double> values;
    for (unsigned int row = 0; row < rows.size(); ++row)
    {
      columns.clear();
      values.clear();
      for (const auto& [column, value] : rows[row])
      {
        columns.push_back(column);
        values.push_back(value);
      }
      matrix.set(first_row + row, columns.size(), columns.data(), values.data());
    }
    matrix.compress(VectorOperation::insert);
  }

  template class ProbedJacobian<2>;
  template class ProbedJacobian<3>;
} // namespace fvfsi
