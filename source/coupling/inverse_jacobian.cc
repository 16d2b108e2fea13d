#include <fvfsi/coupling/inverse_jacobian.h>

namespace fvfsi
{
  MultiVectorJacobian::MultiVectorJacobian(const unsigned int dense_limit,
                                           const unsigned int window)
      : dense_limit(dense_limit), window(std::max(window, 1u))
  {
  }

  void MultiVectorJacobian::vmult(InterfaceVector& y, const InterfaceVector& x) const
  {
    y.reinit(x.size());
    if (n_updates == 0)
      return;
    if (dense)
      J.vmult(y, x);
    else
      apply_steps(steps.size(), y, x);
  }

  void MultiVectorJacobian::apply_steps(const unsigned int n_steps, InterfaceVector& y,
                                        const InterfaceVector& x) const
  {
    y = 0;
    for (unsigned int k = 0; k < n_steps; ++k)
      for (unsigned int i = 0; i < steps[k].Z.size(); ++i)
        y.add(steps[k].Z[i] * x, steps[k].W_tilde[i]);
  }

  void MultiVectorJacobian::compute_w_tilde(const unsigned int k)
  {
    Step& step = steps[k];
    step.W_tilde = step.W;
    InterfaceVector JV;
    for (unsigned int i = 0; i < step.V.size(); ++i)
    {
      JV.reinit(step.V[i].size());
      apply_steps(k, JV, step.V[i]);
      step.W_tilde[i] -= JV;
    }
  }

  void MultiVectorJacobian::update(const std::vector<InterfaceVector>& dR,
                                   const std::vector<InterfaceVector>& dX,
                                   const std::vector<InterfaceVector>& Z)
  {
    if (dR.empty())
      return;
    const unsigned int n = dR[0].size();
    if (n_updates == 0)
    {
      dense = n <= dense_limit;
      if (dense)
        J.reinit(n, n);
    }
    ++n_updates;
    if (dense)
    {
      // W~ = W - J V from the old J, then J += W~ Z^T.
      std::vector<InterfaceVector> W_tilde = dX;
      InterfaceVector JV(n);
      for (unsigned int i = 0; i < dR.size(); ++i)
      {
        J.vmult(JV, dR[i]);
        W_tilde[i] -= JV;
      }
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int i = 0; i < dR.size(); ++i)
        {
          const double w = W_tilde[i](a);
          for (unsigned int b = 0; b < n; ++b)
            J(a, b) += w * Z[i](b);
        }
      return;
    }
    steps.push_back({dR, dX, Z, {}});
    if (steps.size() > window)
    {
      // The window slides: J restarts from 0 at its new oldest step.
      steps.pop_front();
      for (unsigned int k = 0; k + 1 < steps.size(); ++k)
        compute_w_tilde(k);
    }
    compute_w_tilde(steps.size() - 1);
  }
} // namespace fvfsi
