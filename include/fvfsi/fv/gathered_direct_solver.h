#pragma once
// A sparse direct solve (SuiteSparse's UMFPACK through deal.II) of a distributed Trilinos matrix
// whose rows are gathered onto rank 0 alone or onto every rank.
//
// On rank 0 alone, every solve gathers b there and sends x back: the other ranks wait while rank
// 0 solves. On every rank, each rank holds the whole factorisation and solves the whole system
// itself: one all-gather of b per solve and nobody waits. Meant for small systems used often;
// for the segregated solid of the shipped FSI3 (738 cells) it did not pay against ML's AMG (one CG
// iteration per solve there too): 7-9% dearer on one and on two ranks, even as the
// whole linear solve without CG around it (doc/results/performance.md, section 8).

#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace fvfsi
{
  class GatheredDirectSolver
  {
  public:
    using Vector = dealii::LinearAlgebra::distributed::Vector<double>;
    enum class Where
    {
      rank_0,    ///< the factorisation on rank 0 only (large systems: memory on one rank)
      every_rank ///< a copy of the factorisation on every rank (small systems: no waiting)
    };

    /// Gathers `matrix` and factorises it; `matrix` is not kept. Each rank must own one
    /// contiguous range of rows (true of deal.II's cell numbering).
    void factorize(const dealii::TrilinosWrappers::SparseMatrix& matrix, Where where);

    /// x = A^-1 b for the A of factorize() (x's and b's owned entries). With `with_ghosts`, x's
    /// ghost entries too: on every rank they are read from the whole solution (no exchange), on
    /// rank 0 they are exchanged. On every rank a solution that is not finite throws the same
    /// std::runtime_error on all ranks (they hold the same whole system).
    void solve(Vector& x, const Vector& b, bool with_ghosts = false) const;

    bool initialized() const { return umfpack != nullptr; }

  private:
    MPI_Comm comm = MPI_COMM_SELF;
    Where where = Where::rank_0;
    /// Rows owned by each rank and the first of them (rank order = row order).
    std::vector<int> counts, offsets;
    std::unique_ptr<dealii::SparseDirectUMFPACK> umfpack; ///< on the ranks that solve
    mutable dealii::Vector<double> whole; ///< b, then x, of the whole system (ranks that solve)
  };
} // namespace fvfsi
