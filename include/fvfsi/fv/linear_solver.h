#pragma once
// Krylov solve of an assembled FV system (Trilinos matrix): deal.II's SolverCG or SolverGMRES
// directly on the cell vectors; Trilinos ML AMG, Ifpack ILU or Jacobi preconditioners, or an exact
// one (a factorisation of the whole matrix on every rank) for small systems.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fvfsi/fv/cell_matrix_product.h>
#include <fvfsi/fv/gathered_direct_solver.h>
#include <fvfsi/mesh/fv_geometry.h>

#include <memory>
#include <string>

namespace fvfsi
{
  struct LinearSolverParameters
  {
    enum class Method
    {
      cg,   ///< conjugate gradients: symmetric positive definite matrices
      gmres ///< GMRES: any matrix
    };
    enum class Preconditioner
    {
      amg,    ///< Trilinos ML algebraic multigrid, one V-cycle
      ilu,    ///< Trilinos Ifpack ILU(0)
      jacobi, ///< diagonal scaling
      direct  ///< the whole matrix factorised on every rank (UMFPACK): small systems
    };
    /// What Residual reduction is relative to.
    enum class ReductionReference
    {
      initial_residual, ///< the residual of the start value (every solve gains the same factor)
      right_hand_side   ///< |b|, the residual of a zero start: a warm start that is already
                        ///< close needs few or no iterations (mesh motion inside FSI)
    };
    Method method = Method::cg;
    Preconditioner preconditioner = Preconditioner::amg;
    double reduction = 1e-6; ///< relative residual reduction per solve
    ReductionReference reduction_reference = ReductionReference::initial_residual;
    double absolute_tolerance = 1e-14; ///< ... or this absolute residual
    unsigned int max_iterations = 2000;
    /// ML's aggregation threshold: a connection a_ij with |a_ij| below this times
    /// sqrt(|a_ii a_jj|) is weak and ignored when the AMG forms its aggregates.
    double amg_aggregation_threshold = 0.02;
    /// ML's smoother: the degree of its Chebyshev polynomial (deal.II's smoother_sweeps).
    unsigned int amg_smoother_sweeps = 2;
    /// ML's coarsest level: at most this many rows, solved directly (KLU).
    unsigned int amg_coarse_size = 2000;

    /// Declares `subsection <name>` (e.g. "Linear solver").
    void declare(dealii::ParameterHandler& prm, const std::string& name = "Linear solver");
  };

  class LinearSolver
  {
  public:
    explicit LinearSolver(const LinearSolverParameters& parameters);

    /// Build the preconditioner for `matrix` (call again when its values change).
    void initialize(const dealii::TrilinosWrappers::SparseMatrix& matrix);

    /// Solve matrix x = b, starting from x. Returns the number of iterations. Throws a
    /// std::runtime_error naming `what` if the solver fails. `reduction` >= 0 replaces the
    /// parameters' Residual reduction for this solve (e.g. the PISO correctors before the last).
    unsigned int solve(const dealii::TrilinosWrappers::SparseMatrix& matrix, CellVector& x,
                       const CellVector& b, const std::string& what, double reduction = -1);

    /// Number of solve() calls and their Krylov iterations so far.
    /// Whether initialize() has built a preconditioner (a restarted run has none yet).
    bool initialized() const { return preconditioner != nullptr || direct.initialized(); }
    unsigned long n_solves() const { return solve_count; }
    unsigned long n_iterations() const { return iteration_count; }

  private:
    /// CG or GMRES (right-preconditioned, restarted after 30 iterations) by deal.II's solvers
    /// directly on the cell vectors (the Trilinos matrix and preconditioner take
    /// LinearAlgebra::distributed::Vector): no copies into Epetra vectors, no AztecOO set-up and
    /// no separate initial residual per solve; the products A p by CellMatrixProduct on the
    /// cell vectors (no Epetra import). `b_norm`, `x_norm`: |b| and |x| of the start,
    /// computed once per solve (each is a meeting of all ranks).
    unsigned int solve_krylov(const dealii::TrilinosWrappers::SparseMatrix& matrix, CellVector& x,
                              const CellVector& b, double b_norm, double x_norm,
                              const std::string& what, double reduction);
    /// Preconditioner = direct: x = A^-1 b by the factorisation alone (counted as one
    /// iteration), x's ghosts included.
    unsigned int solve_directly(CellVector& x, const CellVector& b, const std::string& what);
    /// Run `attempt`; if it fails, rebuild the preconditioner for `matrix`, call `restart` and
    /// try once more (see linear_solver.cc). Returns the iterations of the failed attempt.
    template <typename Attempt, typename Restart>
    unsigned int with_one_retry(const dealii::TrilinosWrappers::SparseMatrix& matrix,
                                dealii::SolverControl& control, const std::string& what,
                                const Attempt& attempt, const Restart& restart);

    LinearSolverParameters parameters;
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionBase> preconditioner;
    GatheredDirectSolver direct; ///< Preconditioner = direct
    CellMatrixProduct product;   ///< A x of the Krylov solvers
    double matrix_norm = 0;      ///< |A|_inf of the matrix of the last initialize()
    unsigned long solve_count = 0, iteration_count = 0;
    /// Iterations of the first solve after initialize() (-1: none yet). A later solve that needs
    /// ten times as many (at least 50) has outlived its preconditioner: it stops there and is
    /// repeated with a rebuilt one (with_one_retry), instead of running to Max iterations. (A
    /// steady fluid's pressure matrix changes with every pseudo step; the cavity of paper 4.2 at
    /// h = 0.0125 m took 574 s for 30 pseudo steps that way, 14.6 s with a rebuild every step.)
    int fresh_iterations = -1;
    unsigned int failed_iterations = 0; ///< of the last solve's failed attempt, if any
    unsigned int iteration_limit() const;
  };
} // namespace fvfsi
