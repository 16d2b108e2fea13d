#include <deal.II/lac/solver_gmres.h>

#include <fvfsi/base/selection.h>
#include <fvfsi/fv/jacobian_solver.h>

#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  void JacobianSolverParameters::declare(ParameterHandler& prm, const std::string& name)
  {
    prm.enter_subsection(name);
    add_selection(prm, "Method", method,
                  {{"KLU", Method::klu},
                   {"UMFPACK", Method::umfpack},
                   {"GMRES-AMG", Method::gmres_amg},
                   {"GMRES-ILU", Method::gmres_ilu}},
                  "Solver of the Newton systems: sparse direct (UMFPACK, multifrontal; or Trilinos "
                  "Amesos KLU, 1.7 times slower on the plate with a hole and the 3D plate, 5 times "
                  "with OpenBLAS, "
                  "doc/results/solid_coupled.md; both factorise the matrix gathered on one rank), "
                  "or GMRES with ML AMG for systems (block size dim) or "
                  "Ifpack ILU(0).");
    prm.add_parameter("Residual reduction", reduction,
                      "GMRES: relative residual reduction of a Newton system.",
                      Patterns::Double(0, 1));
    prm.add_parameter("Max iterations", max_iterations, "GMRES: iteration limit.",
                      Patterns::Integer(1));
    prm.add_parameter("Restart", restart, "GMRES: Krylov vectors kept before a restart.",
                      Patterns::Integer(2));
    prm.leave_subsection();
  }

  JacobianSolver::JacobianSolver(const JacobianSolverParameters& parameters)
      : parameters(parameters)
  {
  }

  void JacobianSolver::initialize(const TrilinosWrappers::SparseMatrix& A,
                                  const unsigned int block_size)
  {
    using Method = JacobianSolverParameters::Method;
    matrix = &A;
    direct.reset();
    umfpack.reset();
    preconditioner.reset();
    if (parameters.method == Method::umfpack)
    {
      umfpack = std::make_unique<GatheredDirectSolver>();
      umfpack->factorize(A, GatheredDirectSolver::Where::rank_0);
    }
    else if (parameters.method == Method::klu)
    {
      direct = std::make_unique<TrilinosWrappers::SolverDirect>(
        direct_control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Klu"));
      direct->initialize(A);
    }
    else if (parameters.method == Method::gmres_amg)
    {
      // One constant mode per component: ML aggregates the nodes, block_size unknowns at a time.
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic = true;
      data.higher_order_elements = false;
      data.smoother_sweeps = 2;
      data.aggregation_threshold = 0.02;
      const unsigned int n = A.local_size();
      data.constant_modes.assign(block_size, std::vector<bool>(n, false));
      for (unsigned int i = 0; i < n; ++i)
        data.constant_modes[i % block_size][i] = true;
      auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      amg->initialize(A, data);
      preconditioner = std::move(amg);
    }
    else
    {
      auto ilu = std::make_unique<TrilinosWrappers::PreconditionILU>();
      ilu->initialize(A);
      preconditioner = std::move(ilu);
    }
  }

  unsigned int JacobianSolver::solve(Vector& x, const Vector& b, const std::string& what,
                                     const double reduction)
  {
    if (direct)
    {
      direct->solve(x, b);
      return 0;
    }
    if (umfpack)
    {
      umfpack->solve(x, b);
      return 0;
    }
    SolverControl control(parameters.max_iterations,
                          (reduction >= 0 ? reduction : parameters.reduction) * b.l2_norm(), false,
                          false);
    // Right preconditioning: the control sees the true residual.
    SolverGMRES<Vector> gmres(control,
                              SolverGMRES<Vector>::AdditionalData(parameters.restart, true));
    try
    {
      gmres.solve(*matrix, x, b, *preconditioner);
    }
    catch (const std::exception&)
    {
      throw std::runtime_error("GMRES on " + what + " did not converge: residual " +
                               Utilities::to_string(control.last_value()) + " after " +
                               std::to_string(control.last_step()) + " iterations (target " +
                               Utilities::to_string(control.tolerance()) + ")");
    }
    return control.last_step();
  }
} // namespace fvfsi
