// IQN-ILS (Degroote et al. 2009): d <- d~ + W c, c = argmin |r + V c|, the columns of V and W
// from this time step's iterations and, with `Coupling/Reuse time steps` = q, from the q time
// steps before (interface_quasi_newton.h). Every time step starts with `Coupling/Fixed
// iterations` of fixed relaxation, as in the paper, unless it has columns of earlier steps: they
// model the Jacobian already.
#include <fvfsi/coupling/interface_quasi_newton.h>

namespace fvfsi
{
  namespace
  {
    class IqnIls : public InterfaceQuasiNewton
    {
    public:
      using InterfaceQuasiNewton::InterfaceQuasiNewton;
      void new_time_step() override
      {
        CouplingMethod::new_time_step();
        // Drop the columns older than the reuse window.
        if (time_step > prm.reuse_time_steps)
          model.drop_tagged_before(time_step - prm.reuse_time_steps);
      }

    protected:
      bool quasi_newton_update(const InterfaceVector& r, const InterfaceVector& d_tilde,
                               InterfaceVector& result) const override
      {
        const bool reused = model.size() > 0 && model.oldest_tag() < time_step;
        if (iteration <= prm.fixed_iterations && !reused)
          return false;
        InterfaceVector correction(r.size()); // W c
        if (!model.correction(r, correction))
          return false;
        result = d_tilde;
        result += correction;
        return true;
      }
    };

    const CouplingMethod::Registration<IqnIls> registration("IQN-ILS");
  } // namespace
} // namespace fvfsi
