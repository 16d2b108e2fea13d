#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <fvfsi/base/selection.h>
#include <fvfsi/fv/linear_solver.h>

#include <cmath>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  void LinearSolverParameters::declare(ParameterHandler& prm, const std::string& name)
  {
    prm.enter_subsection(name);
    add_selection(prm, "Method", method, {{"CG", Method::cg}, {"GMRES", Method::gmres}},
                  "Krylov method: CG for symmetric matrices, GMRES otherwise.");
    add_selection(prm, "Preconditioner", preconditioner,
                  {{"AMG", Preconditioner::amg},
                   {"ILU", Preconditioner::ilu},
                   {"Jacobi", Preconditioner::jacobi}},
                  "AMG (Trilinos ML, one V-cycle), ILU (Trilinos Ifpack ILU(0)) or Jacobi.");
    prm.add_parameter("Residual reduction", reduction,
                      "Stop when the residual has fallen by this factor (per linear solve).",
                      Patterns::Double(0, 1));
    prm.add_parameter("Absolute tolerance", absolute_tolerance,
                      "... or when the residual (l2 norm over all cells) falls below this value.",
                      Patterns::Double(0));
    prm.add_parameter("Max iterations", max_iterations, "Iteration limit of one linear solve.",
                      Patterns::Integer(1));
    prm.leave_subsection();
  }

  LinearSolver::LinearSolver(const LinearSolverParameters& parameters) : parameters(parameters) {}

  void LinearSolver::initialize(const TrilinosWrappers::SparseMatrix& matrix)
  {
    if (parameters.preconditioner == LinearSolverParameters::Preconditioner::amg)
    {
      auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic = true;
      data.higher_order_elements = false;
      data.smoother_sweeps = 2;
      data.aggregation_threshold = 0.02;
      amg->initialize(matrix, data);
      preconditioner = std::move(amg);
    }
    else if (parameters.preconditioner == LinearSolverParameters::Preconditioner::ilu)
    {
      auto ilu = std::make_unique<TrilinosWrappers::PreconditionILU>();
      ilu->initialize(matrix);
      preconditioner = std::move(ilu);
    }
    else
    {
      auto jacobi = std::make_unique<TrilinosWrappers::PreconditionJacobi>();
      jacobi->initialize(matrix);
      preconditioner = std::move(jacobi);
    }
    x_trilinos.reinit(matrix.locally_owned_domain_indices(), matrix.get_mpi_communicator());
    b_trilinos.reinit(x_trilinos);
  }

  unsigned int LinearSolver::solve(const TrilinosWrappers::SparseMatrix& matrix, CellVector& x,
                                   const CellVector& b, const std::string& what)
  {
    if (!preconditioner)
      initialize(matrix);
    // Owned entries of a CellVector and of an owned-only Trilinos vector share their local order.
    const unsigned int n = x.locally_owned_size();
    for (unsigned int i = 0; i < n; ++i)
    {
      x_trilinos.trilinos_vector()[0][i] = x.local_element(i);
      b_trilinos.trilinos_vector()[0][i] = b.local_element(i);
    }
    // Stop at `reduction` times the initial residual, or at the absolute tolerance; never ask
    // for less than round-off of the right-hand side or of A x (Krylov methods stall there, and
    // preconditioned CG started from round-off noise can break down into NaN).
    TrilinosWrappers::MPI::Vector r(b_trilinos);
    const double r0 = matrix.residual(r, x_trilinos, b_trilinos);
    const double x_norm = x_trilinos.l2_norm(); // |A| (a pass over the matrix) only if x != 0
    const double round_off =
      1e-13 * std::max(b_trilinos.l2_norm(), x_norm == 0 ? 0.0 : matrix.linfty_norm() * x_norm);
    SolverControl control(
      parameters.max_iterations,
      std::max({parameters.absolute_tolerance, parameters.reduction * r0, round_off}), false,
      false);
    if (!std::isfinite(r0))
      throw std::runtime_error("linear solve of " + what +
                               ": the right-hand side or the start value is not finite (NaN or "
                               "inf): the solution diverged before this solve");
    if (r0 <= control.tolerance())
      return 0;
    const auto attempt = [&]()
    {
      if (parameters.method == LinearSolverParameters::Method::cg)
        TrilinosWrappers::SolverCG(control).solve(matrix, x_trilinos, b_trilinos, *preconditioner);
      else
        TrilinosWrappers::SolverGMRES(control).solve(matrix, x_trilinos, b_trilinos,
                                                     *preconditioner);
    };
    unsigned int iterations = 0;
    try
    {
      attempt();
    }
    catch (const std::exception&)
    {
      // A preconditioner kept from an earlier matrix (callers refresh it only every few steps)
      // can stop fitting the matrix: the smoother of an AMG hierarchy reads the new values with
      // old eigenvalue bounds. Rebuild it for this matrix and try once more from the same start.
      iterations = control.last_step() == numbers::invalid_unsigned_int ? 0 : control.last_step();
      initialize(matrix); // (re-creates x_trilinos and b_trilinos)
      for (unsigned int i = 0; i < n; ++i)
      {
        x_trilinos.trilinos_vector()[0][i] = x.local_element(i);
        b_trilinos.trilinos_vector()[0][i] = b.local_element(i);
      }
      try
      {
        attempt();
      }
      catch (const std::exception&)
      {
        // The solver's own message is a page of deal.II text; the numbers say it all.
        const unsigned int steps =
          control.last_step() == numbers::invalid_unsigned_int ? 0 : control.last_step();
        throw std::runtime_error("linear solve of " + what + " failed after " +
                                 std::to_string(steps) + " iterations (residual " +
                                 Utilities::to_string(control.last_value()) + ", target " +
                                 Utilities::to_string(control.tolerance()) +
                                 "), also with a preconditioner rebuilt for this matrix");
      }
    }
    for (unsigned int i = 0; i < n; ++i)
      x.local_element(i) = x_trilinos.trilinos_vector()[0][i];
    x.update_ghost_values();
    return iterations + control.last_step();
  }
} // namespace fvfsi
