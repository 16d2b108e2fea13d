#include <fvfsi/coupling/interface_quasi_newton.h>

namespace fvfsi
{
  std::string InterfaceQuasiNewton::advice() const
  {
    // At the default solver reductions the interface residual stalls at 5e-7 (FSI3) to 1e-4
    // (rho_s / rho_f = 0.1, Poisson's ratio 0.49 and 0.499), and IQN-ILS asked for 1e-8 diverges
    // from the noise it fits (rho_s / rho_f = 10); with the solves tighter the same cases
    // converge (doc/results/hard_cases.md, section 7).
    return "a quasi-Newton coupling fits the fluid's and solid's answers, so they must be "
           "solved well below Coupling/Tolerance: lower the Residual reduction of the "
           "Fluid momentum, Fluid pressure, Mesh motion and Solid linear solvers and "
           "Solid/Outer tolerance, or raise Coupling/Tolerance";
  }

  InterfaceVector InterfaceQuasiNewton::update(const InterfaceVector& d,
                                               const InterfaceVector& d_tilde,
                                               const InterfaceVector& r)
  {
    if (previous_r.size() > 0)
    {
      InterfaceVector V = r, W = d_tilde;
      V -= previous_r;
      W -= previous_d_tilde;
      model.add_column(V, W, time_step);
    }
    InterfaceVector result;
    if (quasi_newton_update(r, d_tilde, result))
      return result;
    return relaxed(d, r, prm.relaxation);
  }

  void InterfaceQuasiNewton::checkpoint(GlobalArchive& archive)
  {
    CouplingMethod::checkpoint(archive);
    archive& model;
  }
} // namespace fvfsi
