// Aitken's dynamic relaxation (Kuettler and Wall 2008): d <- d + omega_k r with
//   omega_k = -omega_(k-1) r_(k-1).(r_k - r_(k-1)) / |r_k - r_(k-1)|^2,
// after `Coupling/Fixed iterations` iterations with the fixed omega that start every time step
// (as the paper does), omega back to `Coupling/Relaxation` at each new time step.
#include <fvfsi/coupling/coupling_method.h>

namespace fvfsi
{
  namespace
  {
    class Aitken : public CouplingMethod
    {
    public:
      explicit Aitken(const CouplingParameters& parameters)
          : CouplingMethod(parameters), omega(parameters.relaxation)
      {
      }
      void new_time_step() override
      {
        CouplingMethod::new_time_step();
        omega = prm.relaxation;
      }
      std::string advice() const override
      {
        return "use Coupling/Method = IQN-ILS, or a smaller Coupling/Relaxation";
      }
      void checkpoint(GlobalArchive& archive) override
      {
        CouplingMethod::checkpoint(archive);
        archive& omega;
      }

    protected:
      InterfaceVector update(const InterfaceVector& d, const InterfaceVector& /*d_tilde*/,
                             const InterfaceVector& r) override
      {
        if (iteration > prm.fixed_iterations && previous_r.size() > 0)
        {
          InterfaceVector dr = r;
          dr -= previous_r;
          const double dr2 = dr * dr;
          if (dr2 > 0)
            omega = -omega * (previous_r * dr) / dr2;
        }
        return relaxed(d, r, omega);
      }

    private:
      double omega; ///< omega_k
    };

    const CouplingMethod::Registration<Aitken> registration("Aitken");
  } // namespace
} // namespace fvfsi
