#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

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
    add_selection(
      prm, "Preconditioner", preconditioner,
      {{"AMG", Preconditioner::amg},
       {"ILU", Preconditioner::ilu},
       {"Jacobi", Preconditioner::jacobi},
       {"direct", Preconditioner::direct}},
      "AMG (Trilinos ML, one V-cycle), ILU (Trilinos Ifpack ILU(0)), Jacobi, or "
      "direct: the whole matrix gathered and factorised (UMFPACK) on every rank, so "
      "that a solve is exact without Krylov iterations and the ranks meet once per solve (small "
      "systems only: every rank holds the whole factorisation; on the shipped FSI3's "
      "738-cell solid it is slower than AMG, doc/results/performance.md).");
    prm.add_parameter("Residual reduction", reduction,
                      "Stop when the residual has fallen by this factor (per linear solve). "
                      "In `Fluid momentum solver` and `Fluid pressure solver`, a steady run "
                      "(Fluid/Transient = false) that does not give it takes 1e-1 and 1e-2 (the "
                      "log's steady settings).",
                      Patterns::Double(0, 1), /*has_to_be_set: a given value is known*/ true);
    add_selection(prm, "Reduction relative to", reduction_reference,
                  {{"initial residual", ReductionReference::initial_residual},
                   {"right-hand side", ReductionReference::right_hand_side}},
                  "initial residual: every solve reduces the residual of its start value by "
                  "Residual reduction; right-hand side: the residual falls below Residual "
                  "reduction times |b| (the residual of a zero start), so a warm start that is "
                  "already that close takes no iteration.");
    prm.add_parameter("Absolute tolerance", absolute_tolerance,
                      "... or when the residual (l2 norm over all cells) falls below this value.",
                      Patterns::Double(0));
    prm.add_parameter("Max iterations", max_iterations, "Iteration limit of one linear solve.",
                      Patterns::Integer(1));
    prm.add_parameter(
      "AMG aggregation threshold", amg_aggregation_threshold,
      "With Preconditioner = AMG: ML's aggregation threshold. A connection a_ij with |a_ij| "
      "below this times sqrt(|a_ii a_jj|) counts as weak and does not join cells into one "
      "aggregate; on stretched cells a larger value lets the aggregates follow the strong "
      "direction (prm/turek_hron_fsi3.prm's pressure: 0.05, doc/results/performance.md).",
      Patterns::Double(0, 1));
    // ML's smoother degree and coarse size (doc/results/performance.md, section 15: on the CFD3
    // pressure neither 1 nor a larger coarse level gains in a whole run).
    prm.add_parameter("AMG smoother sweeps", amg_smoother_sweeps,
                      "With Preconditioner = AMG: "
                      "the degree of ML's Chebyshev smoother.",
                      Patterns::Integer(1, 10));
    prm.add_parameter("AMG coarse size", amg_coarse_size,
                      "With Preconditioner = AMG: at most "
                      "this many rows on ML's coarsest level, solved by KLU.",
                      Patterns::Integer(1));
    prm.leave_subsection();
  }

  LinearSolver::LinearSolver(const LinearSolverParameters& parameters) : parameters(parameters) {}

  void LinearSolver::initialize(const TrilinosWrappers::SparseMatrix& matrix)
  {
    preconditioner.reset();
    if (parameters.preconditioner == LinearSolverParameters::Preconditioner::direct)
      direct.factorize(matrix, GatheredDirectSolver::Where::every_rank);
    else if (parameters.preconditioner == LinearSolverParameters::Preconditioner::amg)
    {
      auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic = true;
      data.higher_order_elements = false;
      data.smoother_sweeps = parameters.amg_smoother_sweeps;
      data.aggregation_threshold = parameters.amg_aggregation_threshold;
      // deal.II's parameter list for ML, with the coarse size it does not expose.
      Teuchos::ParameterList list;
      std::unique_ptr<Epetra_MultiVector> constant_modes;
      data.set_parameters(list, constant_modes, matrix);
      list.set("coarse: max size", int(parameters.amg_coarse_size));
      amg->initialize(matrix, list);
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
    matrix_norm = matrix.linfty_norm();
    fresh_iterations = -1;
  }

  unsigned int LinearSolver::iteration_limit() const
  {
    return fresh_iterations < 0
             ? parameters.max_iterations
             : std::min(parameters.max_iterations, std::max(50u, 10u * unsigned(fresh_iterations)));
  }

  unsigned int LinearSolver::solve(const TrilinosWrappers::SparseMatrix& matrix, CellVector& x,
                                   const CellVector& b, const std::string& what, double reduction)
  {
    if (!initialized())
      initialize(matrix);
    if (parameters.preconditioner == LinearSolverParameters::Preconditioner::direct)
      return solve_directly(x, b, what);
    if (reduction < 0)
      reduction = parameters.reduction;
    const double b_norm = b.l2_norm(), x_norm = x.l2_norm();
    if (!std::isfinite(b_norm) || !std::isfinite(x_norm))
      throw std::runtime_error("linear solve of " + what +
                               ": the right-hand side or the start value is not finite (NaN or "
                               "inf): the solution diverged before this solve");
    const unsigned int iterations = solve_krylov(matrix, x, b, b_norm, x_norm, what, reduction);
    ++solve_count;
    iteration_count += iterations;
    if (fresh_iterations < 0) // the first solve with this preconditioner (the retry's, if any)
      fresh_iterations = int(iterations - failed_iterations);
    return iterations;
  }

  unsigned int LinearSolver::solve_directly(CellVector& x, const CellVector& b,
                                            const std::string& what)
  {
    // The factorisation is exact: no Krylov iteration, and with a copy of it on every rank the
    // ranks meet once per solve (the all-gather of b); x's ghosts are read from the whole
    // solution every rank holds.
    x.zero_out_ghost_values();
    try
    {
      direct.solve(x, b, /*with_ghosts=*/true);
    }
    catch (const std::exception& e)
    {
      throw std::runtime_error("linear solve of " + what + ": " + e.what());
    }
    ++solve_count;
    ++iteration_count;
    if (fresh_iterations < 0)
      fresh_iterations = 1;
    return 1;
  }

  template <typename Attempt, typename Restart>
  unsigned int LinearSolver::with_one_retry(const TrilinosWrappers::SparseMatrix& matrix,
                                            SolverControl& control, const std::string& what,
                                            const Attempt& attempt, const Restart& restart)
  {
    const auto steps = [&control]()
    { return control.last_step() == numbers::invalid_unsigned_int ? 0u : control.last_step(); };
    try
    {
      attempt();
      return 0;
    }
    catch (const std::exception&)
    {
      // A preconditioner kept from an earlier matrix (callers refresh it only every few steps)
      // can stop fitting the matrix: the smoother of an AMG hierarchy reads the new values with
      // old eigenvalue bounds. Rebuild it for this matrix and try once more from the same start.
      const unsigned int failed = steps();
      initialize(matrix);
      control.set_max_steps(parameters.max_iterations);
      restart();
      try
      {
        attempt();
      }
      catch (const std::exception&)
      {
        // The solver's own message is a page of deal.II text; the numbers say it all.
        throw std::runtime_error("linear solve of " + what + " failed after " +
                                 std::to_string(steps()) + " iterations (residual " +
                                 Utilities::to_string(control.last_value()) + ", target " +
                                 Utilities::to_string(control.tolerance()) +
                                 "), also with a preconditioner rebuilt for this matrix");
      }
      return failed;
    }
  }

  unsigned int LinearSolver::solve_krylov(const TrilinosWrappers::SparseMatrix& matrix,
                                          CellVector& x, const CellVector& b, const double b_norm,
                                          const double x_norm, const std::string& what,
                                          const double reduction)
  {
    // Stop at `reduction` times the initial residual (ReductionControl takes the solver's first
    // residual) or times |b| (Reduction relative to = right-hand side: a fixed target however
    // close the warm start is), or at the absolute tolerance; never ask for less than round-off
    // of b or of A x (Krylov methods stall there, and preconditioned CG started from round-off
    // noise can break down into NaN). |A| is that of the matrix the preconditioner was built for:
    // an estimate, the matrix changes a little between rebuilds.
    const double round_off = 1e-13 * std::max(b_norm, x_norm == 0 ? 0.0 : matrix_norm * x_norm);
    const double floor = std::max(parameters.absolute_tolerance, round_off);
    ReductionControl reduction_control(iteration_limit(), floor, reduction, false, false);
    SolverControl rhs_control(iteration_limit(), std::max(floor, reduction * b_norm), false, false);
    SolverControl& control =
      parameters.reduction_reference == LinearSolverParameters::ReductionReference::initial_residual
        ? reduction_control
        : rhs_control;
    // deal.II's solvers on the cell vectors themselves: no copies into Epetra vectors and no
    // AztecOO set-up per solve. On the pressure of the Turek-Hron CFD3 run (20 960 cells, about 5
    // CG iterations per solve) CG takes 2.37 instead of AztecOO's 3.20 ms per solve, with the same
    // iterations; GMRES with right preconditioning watches the true residual b - A x like CG
    // (doc/results/performance.md, sections 4 and 8).
    // The products A p on the cell vectors too (CellMatrixProduct: Epetra's rows read in place,
    // the ghost exchange overlapped with the rows that need none, no Epetra import).
    product.reinit(matrix, x);
    const auto krylov = [&]()
    {
      if (parameters.method == LinearSolverParameters::Method::cg)
        SolverCG<CellVector>(control).solve(product, x, b, *preconditioner);
      else
      {
        const typename SolverGMRES<CellVector>::AdditionalData restart_after_30(30, true);
        SolverGMRES<CellVector>(control, restart_after_30).solve(product, x, b, *preconditioner);
      }
    };
    x.zero_out_ghost_values(); // the solver writes the owned entries only
    const CellVector x_start(x);
    const unsigned int failed =
      with_one_retry(matrix, control, what, krylov, [&]() { x = x_start; });
    failed_iterations = failed;
    x.update_ghost_values();
    return failed +
           (control.last_step() == numbers::invalid_unsigned_int ? 0 : control.last_step());
  }
} // namespace fvfsi
