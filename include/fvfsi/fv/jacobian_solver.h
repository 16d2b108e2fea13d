#pragma once
// Solves with a Jacobian of a vector problem (e.g. ProbedJacobian's, block layout: block_size
// consecutive unknowns per node): a sparse direct factorisation on one rank (SuiteSparse's
// multifrontal UMFPACK through deal.II, much faster on the wide stencils of 2D and 3D meshes, or
// Trilinos Amesos KLU; Amesos_Mumps of Debian's Trilinos 13.2 crashed in deal.II 9.4's
// SolverDirect, so it is not offered), or GMRES (deal.II's, on the distributed vectors) preconditioned by Trilinos ML AMG
// for systems (block size = number of PDE equations, one constant mode per component) or by
// Ifpack ILU(0). The factorisation / preconditioner is kept until initialize() is called again, so
// that a Newton iteration can reuse it.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/fv/gathered_direct_solver.h>

#include <memory>
#include <string>

namespace fvfsi
{
  struct JacobianSolverParameters
  {
    enum class Method
    {
      klu,       ///< Amesos KLU (serial factorisation: the matrix is gathered on one rank)
      umfpack,   ///< UMFPACK through deal.II (the matrix gathered on rank 0)
      gmres_amg, ///< GMRES + ML AMG for systems
      gmres_ilu  ///< GMRES + Ifpack ILU(0)
    };
    Method method = Method::umfpack;
    double reduction = 1e-12; ///< GMRES: relative residual reduction
    unsigned int max_iterations = 1000;
    unsigned int restart = 100; ///< GMRES: Krylov vectors before a restart

    /// Declares `subsection <name>`.
    void declare(dealii::ParameterHandler& prm, const std::string& name);
  };

  class JacobianSolver
  {
  public:
    using Vector = dealii::LinearAlgebra::distributed::Vector<double>;

    explicit JacobianSolver(const JacobianSolverParameters& parameters);

    /// Factorise `matrix` / build the preconditioner (block_size: unknowns per node).
    void initialize(const dealii::TrilinosWrappers::SparseMatrix& matrix, unsigned int block_size);
    bool initialized() const { return matrix != nullptr; }
    /// Whether solve() is exact (a direct factorisation), so that two solves with the same
    /// right-hand side give the same x.
    bool direct_method() const
    {
      return parameters.method == JacobianSolverParameters::Method::klu ||
             parameters.method == JacobianSolverParameters::Method::umfpack;
    }

    /// matrix x = b (x: start value for GMRES). Returns the Krylov iterations (0: direct).
    /// `reduction` >= 0 replaces the parameters' Residual reduction for this solve. Throws a
    /// std::runtime_error naming `what` if GMRES does not converge.
    unsigned int solve(Vector& x, const Vector& b, const std::string& what, double reduction = -1);

  private:
    JacobianSolverParameters parameters;
    const dealii::TrilinosWrappers::SparseMatrix* matrix = nullptr;
    dealii::SolverControl direct_control;
    std::unique_ptr<dealii::TrilinosWrappers::SolverDirect> direct;
    std::unique_ptr<GatheredDirectSolver> umfpack; ///< on rank 0
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionBase> preconditioner;
  };
} // namespace fvfsi
