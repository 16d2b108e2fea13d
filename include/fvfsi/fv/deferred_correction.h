#pragma once
// The deferred-correction iteration of an FV equation whose implicit part is a fixed matrix A (the
// orthogonal part of Eq. 19) and whose explicit part depends on the gradients of the solution (the
// non-orthogonal correction, paper section 3.2):
//
//   repeat:  rhs = b + explicit(grad phi);  solve A phi = rhs;  update grad phi from phi
//
// a fixed number of times (the PISO pressure, the mesh motion) or until phi stops changing (the
// Poisson scene). The Poisson scene, the fluid's pressure equation and the Laplace mesh motion all
// call this one loop.

#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/fv/linear_solver.h>
#include <fvfsi/mesh/fv_geometry.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fvfsi
{
  struct DeferredCorrection
  {
    unsigned int max_iterations = 1; ///< linear solves at most
    /// > 0: stop as soon as max |phi change| / max |phi| < tolerance; 0: always max_iterations.
    double tolerance = 0;
    /// false: no gradient update after the last solve (the PISO flux correction needs the
    /// gradient of the correction that was solved with).
    bool update_after_last = true;
    /// Residual reductions of the linear solves but the last, and of the last (< 0: the
    /// solver's own; see LinearSolver::solve).
    double reduction = -1, last_reduction = -1;
  };

  struct DeferredCorrectionResult
  {
    unsigned int iterations = 0, linear_iterations = 0;
    double change = 0; ///< max |phi change| / max |phi| of the last iteration (tolerance > 0)
    bool converged = true;
  };

  /// `add_explicit(rhs)` adds the explicit part with the current gradients to rhs; `update()`
  /// recomputes them from phi (collective). `what` names the equation in error messages.
  template <typename AddExplicit, typename Update>
  DeferredCorrectionResult
  solve_deferred_correction(const DeferredCorrection& control, LinearSolver& solver,
                            const dealii::TrilinosWrappers::SparseMatrix& A, const CellVector& b,
                            CellVector& phi, const AddExplicit& add_explicit, const Update& update,
                            const std::string& what)
  {
    DeferredCorrectionResult result;
    result.converged = control.tolerance == 0;
    CellVector rhs(b), phi_old;
    for (unsigned int k = 1; k <= control.max_iterations; ++k)
    {
      rhs = b;
      add_explicit(rhs);
      if (control.tolerance > 0)
        phi_old = phi;
      result.linear_iterations += solver.solve(
        A, phi, rhs, what, k < control.max_iterations ? control.reduction : control.last_reduction);
      result.iterations = k;
      if (k < control.max_iterations || control.update_after_last)
        update();
      if (control.tolerance == 0)
        continue;
      double max_change = 0, max_phi = 0;
      for (unsigned int c = 0; c < phi.locally_owned_size(); ++c)
      {
        max_change =
          std::max(max_change, std::abs(phi.local_element(c) - phi_old.local_element(c)));
        max_phi = std::max(max_phi, std::abs(phi.local_element(c)));
      }
      const MPI_Comm comm = phi.get_mpi_communicator();
      result.change = dealii::Utilities::MPI::max(max_change, comm) /
                      std::max(dealii::Utilities::MPI::max(max_phi, comm), 1e-300);
      if (!std::isfinite(result.change))
        throw std::runtime_error(what + " is not finite after correction iteration " +
                                 std::to_string(k));
      if (result.change < control.tolerance)
      {
        result.converged = true;
        return result;
      }
    }
    return result;
  }
} // namespace fvfsi
