#pragma once
// What the interface quasi-Newton methods (IQN-ILS, IQN-IMVJ; source/coupling/methods/) share:
// the columns V (differences of r) and W (differences of d~) of the iterations seen, each tagged
// with its time step, in a least-squares model with the QR filter (`QR filter`, default 1e-2,
// preCICE's QR2 filter: the columns are taken newest first, and one whose part orthogonal to the
// newer ones is at most filter x its norm is left out of the least-squares problem; without it
// nearly dependent columns, late iterations of a converging step or reused old steps, make the
// problem ill-conditioned and amplify round-off and noise into the update; too large a filter
// throws away information and costs iterations). The model is the one of the solid's Anderson
// acceleration (fv/least_squares_model.h).
//
// An iteration adds its column, then asks the method for the quasi-Newton update; where the
// method has none yet (the fixed iterations that start a step, as in the paper, or too few
// columns) the update is fixed relaxation (Eq. 31).

#include <fvfsi/coupling/coupling_method.h>
#include <fvfsi/fv/least_squares_model.h>

namespace fvfsi
{
  class InterfaceQuasiNewton : public CouplingMethod
  {
  public:
    explicit InterfaceQuasiNewton(const CouplingParameters& parameters)
        : CouplingMethod(parameters), model(parameters.qr_filter)
    {
    }
    /// Measured on the FSI3 flag (doc/results/hard_cases.md, section 7): at the default solver
    /// reductions the interface residual stalls, with tighter solves the same cases converge.
    std::string advice() const override;
    void checkpoint(GlobalArchive& archive) override;

  protected:
    InterfaceVector update(const InterfaceVector& d, const InterfaceVector& d_tilde,
                           const InterfaceVector& r) override;
    /// The method's quasi-Newton update into `result`; false (result untouched) where fixed
    /// relaxation is to be used.
    virtual bool quasi_newton_update(const InterfaceVector& r, const InterfaceVector& d_tilde,
                                     InterfaceVector& result) const = 0;

    /// The columns V, W, tagged with their time step.
    LeastSquaresModel<InterfaceVector> model;
  };
} // namespace fvfsi
