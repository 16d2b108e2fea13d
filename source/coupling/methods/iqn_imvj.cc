// IQN-IMVJ (Lindner et al. 2015): d <- d~ - J r with J = J_prev + (W - J_prev V) V^+, the
// inverse Jacobian of the earlier time steps, J_prev (coupling/inverse_jacobian.h: J and its
// memory, dense or implicit over a window of steps), updated with this step's columns. At each
// new time step the last step's columns go into J_prev. The first time step (J_prev = 0) is
// IQN-ILS without reuse, with its fixed iterations; later ones need none.
#include <fvfsi/coupling/interface_quasi_newton.h>
#include <fvfsi/coupling/inverse_jacobian.h>

namespace fvfsi
{
  namespace
  {
    class IqnImvj : public InterfaceQuasiNewton
    {
    public:
      explicit IqnImvj(const CouplingParameters& parameters)
          : InterfaceQuasiNewton(parameters),
            jacobian(parameters.imvj_dense_limit, parameters.imvj_time_steps)
      {
      }
      void new_time_step() override
      {
        CouplingMethod::new_time_step();
        // J_prev <- J_prev + (W - J_prev V) V^+ with the last step's columns.
        if (model.size() > 0)
        {
          const auto secants = model.kept_secants();
          jacobian.update(secants.dR, secants.dX, secants.Z);
        }
        model.clear();
      }
      void checkpoint(GlobalArchive& archive) override
      {
        InterfaceQuasiNewton::checkpoint(archive);
        archive& jacobian;
      }

    protected:
      bool quasi_newton_update(const InterfaceVector& r, const InterfaceVector& d_tilde,
                               InterfaceVector& result) const override
      {
        if (iteration <= prm.fixed_iterations && jacobian.empty())
          return false;
        // d <- d~ - J r = d~ + W c - J_prev (r + V c), c = argmin |r + V c| (W c = correction,
        // V c = fitted).
        InterfaceVector correction(r.size()), fitted(r.size()), rest = r;
        const bool columns = model.correction(r, correction, &fitted);
        if (!columns && jacobian.empty())
          return false;
        result = d_tilde;
        if (columns)
        {
          result += correction;
          rest += fitted;
        }
        InterfaceVector J_rest;
        jacobian.vmult(J_rest, rest);
        result -= J_rest;
        return true;
      }

    private:
      MultiVectorJacobian jacobian; ///< J_prev
    };

    const CouplingMethod::Registration<IqnImvj> registration("IQN-IMVJ");
  } // namespace
} // namespace fvfsi
