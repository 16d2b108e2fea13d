#pragma once
// Krylov solve of an assembled FV system with Trilinos (AztecOO CG/GMRES, ML AMG or ILU/Jacobi).

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

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
      amg,   ///< Trilinos ML algebraic multigrid, one V-cycle
      ilu,   ///< Trilinos Ifpack ILU(0)
      jacobi ///< diagonal scaling
    };
    Method method = Method::cg;
    Preconditioner preconditioner = Preconditioner::amg;
    double reduction = 1e-6;           ///< relative residual reduction per solve
    double absolute_tolerance = 1e-14; ///< ... or this absolute residual
    unsigned int max_iterations = 2000;

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
    /// std::runtime_error naming `what` if the solver fails.
    unsigned int solve(const dealii::TrilinosWrappers::SparseMatrix& matrix, CellVector& x,
                       const CellVector& b, const std::string& what);

  private:
    LinearSolverParameters parameters;
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionBase> preconditioner;
    dealii::TrilinosWrappers::MPI::Vector x_trilinos, b_trilinos;
  };
} // namespace fvfsi
