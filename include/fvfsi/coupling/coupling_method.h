#pragma once
// The update of the interface displacement in the coupling iterations of Algorithm 1 (paper
// section 3.4, Eqs 30-31). The fluid takes an interface displacement d (at the fluid interface
// vertices), the solid answers with d~ = S(F(d)); the residual is r = d~ - d, and a coupling
// method makes the next d from d, d~ and r:
//
//   fixed relaxation:  d <- d + omega r                                              (31)
//   Aitken:            the same with omega_k = -omega_(k-1) r_(k-1).(r_k - r_(k-1)) / |r_k - r_(k-1)|^2
//                      (Kuettler and Wall's dynamic relaxation)
//   IQN-ILS:           d <- d~ + W c, with c the least-squares solution of V c = -r, where the
//                      columns of V and W are the differences of r and of d~ between iterations
//                      (Degroote et al.: an approximate inverse Jacobian of the residual built
//                      from the iterations seen; columns of earlier time steps may be reused).
//   IQN-IMVJ:          d <- d~ - J r with J = J_prev + (W - J_prev V) V^+: the inverse Jacobian
//                      of the earlier time steps, J_prev, updated with this step's columns
//                      (Lindner et al. 2015; coupling/inverse_jacobian.h: J and its memory).
//
// This base class holds what every method shares: the residual and its norms, the convergence
// test, the counters, and a checkpoint of them. Each method is one class in one file of
// source/coupling/methods/ that overrides update() (and new_time_step() if it keeps state from
// step to step) and registers itself under the name `Coupling/Method` selects:
//
//   class MyMethod : public CouplingMethod { ... InterfaceVector update(...) override; ... };
//   const CouplingMethod::Registration<MyMethod> registration("My method");
//
// A new method is that one file (CMake compiles every file of source/ into the shared library
// fvfsi_lib, whose static Registration objects run when it loads; a static library would drop
// the methods no other file refers to).
//
// Convergence (converged()): |r| <= Tolerance |d~| (Eq. 30) or, if `Residual reduction` > 0,
// |r| <= Residual reduction x the largest |r| of the step's iterations (Lindner et al.: 1e-6);
// with both set, whichever is met first ends the step.
//
// The vectors are the whole interface, replicated on every rank (InterfaceZone's InterfaceVector),
// so every rank computes the same update; nothing here communicates.

#include <fvfsi/coupling/coupling_parameters.h>
#include <fvfsi/coupling/interface_zone.h>
#include <fvfsi/io/checkpoint.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fvfsi
{
  class CouplingMethod
  {
  public:
    /// The method `parameters.method` names.
    static std::unique_ptr<CouplingMethod> create(const CouplingParameters& parameters);
    /// The names of the methods there are (Coupling/Method's choices), sorted.
    static std::vector<std::string> names();

    /// Put a method on the list under `name` (one object per method, in the method's file).
    template <class Method>
    struct Registration
    {
      explicit Registration(const std::string& name)
      {
        add(name, [](const CouplingParameters& p) { return std::make_unique<Method>(p); });
      }
    };

    explicit CouplingMethod(const CouplingParameters& parameters);
    virtual ~CouplingMethod() = default;

    /// Start a time step: the iteration count and the step's residuals back to none. A method
    /// that keeps something from step to step (Aitken's omega, IQN's columns) extends it.
    virtual void new_time_step();

    /// The next interface displacement from the one used, d, and the solid's answer, d~.
    InterfaceVector next(const InterfaceVector& d, const InterfaceVector& d_tilde);

    /// |r|_2 / max(|d~|_2, tiny) of the last call to next().
    double relative_residual() const { return last_relative_residual; }

    /// Whether the last call to next() met the convergence test (see above).
    bool converged() const;

    /// What to change when the coupling iterations of this method diverge or stall.
    virtual std::string advice() const = 0;

    /// Save or load the state kept between time steps (a checkpoint, or the start of a time step
    /// kept in memory). A method with state of its own extends it.
    virtual void checkpoint(GlobalArchive& archive);

  protected:
    /// The method's rule: the next d from d, d~ and r = d~ - d (called by next(), before r and
    /// d~ become previous_r and previous_d_tilde).
    virtual InterfaceVector update(const InterfaceVector& d, const InterfaceVector& d_tilde,
                                   const InterfaceVector& r) = 0;
    /// Eq. 31: d + omega r.
    static InterfaceVector relaxed(const InterfaceVector& d, const InterfaceVector& r,
                                   double omega);

    const CouplingParameters prm;
    unsigned int iteration = 0; ///< within the time step, counting the present one
    unsigned int time_step = 0; ///< time steps started
    /// r and d~ of the iteration before (empty on a step's first iteration).
    InterfaceVector previous_r, previous_d_tilde;

  private:
    using Factory = std::function<std::unique_ptr<CouplingMethod>(const CouplingParameters&)>;
    static void add(const std::string& name, Factory factory);
    /// The methods there are, by name, filled by the Registration objects while the library
    /// loads (a function's static, so whatever the order of its files).
    static std::map<std::string, Factory>& registry();
    double last_relative_residual = 0, last_residual = 0, largest_residual = 0;
  };
} // namespace fvfsi
