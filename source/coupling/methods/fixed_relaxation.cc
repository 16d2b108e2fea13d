// Fixed relaxation (paper Eq. 31): d <- d + omega r with omega = `Coupling/Relaxation`.
#include <fvfsi/coupling/coupling_method.h>

namespace fvfsi
{
  namespace
  {
    class FixedRelaxation : public CouplingMethod
    {
    public:
      using CouplingMethod::CouplingMethod;
      std::string advice() const override
      {
        return "use Coupling/Method = IQN-ILS or Aitken, or a smaller Coupling/Relaxation";
      }

    protected:
      InterfaceVector update(const InterfaceVector& d, const InterfaceVector& /*d_tilde*/,
                             const InterfaceVector& r) override
      {
        return relaxed(d, r, prm.relaxation);
      }
    };

    const CouplingMethod::Registration<FixedRelaxation> registration("fixed");
  } // namespace
} // namespace fvfsi
