#include <fvfsi/coupling/coupling_method.h>

#include <algorithm>
#include <stdexcept>

namespace fvfsi
{
  std::map<std::string, CouplingMethod::Factory>& CouplingMethod::registry()
  {
    static std::map<std::string, Factory> methods;
    return methods;
  }

  void CouplingMethod::add(const std::string& name, Factory factory)
  {
    if (!registry().emplace(name, std::move(factory)).second)
      throw std::logic_error("CouplingMethod: two methods named " + name);
  }

  std::vector<std::string> CouplingMethod::names()
  {
    std::vector<std::string> list;
    for (const auto& entry : registry())
      list.push_back(entry.first);
    return list;
  }

  std::unique_ptr<CouplingMethod> CouplingMethod::create(const CouplingParameters& parameters)
  {
    const auto method = registry().find(parameters.method);
    if (method == registry().end())
    {
      std::string known;
      for (const std::string& name : names())
        known += (known.empty() ? "" : ", ") + name;
      throw std::runtime_error("Coupling/Method = " + parameters.method +
                               ": no such coupling method (there are: " + known + ")");
    }
    return method->second(parameters);
  }

  CouplingMethod::CouplingMethod(const CouplingParameters& parameters) : prm(parameters) {}

  void CouplingMethod::new_time_step()
  {
    ++time_step;
    iteration = 0;
    previous_r.reinit(0);
    previous_d_tilde.reinit(0);
    largest_residual = 0;
  }

  bool CouplingMethod::converged() const
  {
    return last_relative_residual <= prm.tolerance ||
           (prm.residual_reduction > 0 &&
            last_residual <= prm.residual_reduction * largest_residual);
  }

  InterfaceVector CouplingMethod::next(const InterfaceVector& d, const InterfaceVector& d_tilde)
  {
    ++iteration;
    InterfaceVector r = d_tilde;
    r -= d; // Eq. 30
    last_residual = r.l2_norm();
    largest_residual = std::max(largest_residual, last_residual);
    last_relative_residual = last_residual / std::max(d_tilde.l2_norm(), 1e-300);
    InterfaceVector result = update(d, d_tilde, r);
    previous_r = r;
    previous_d_tilde = d_tilde;
    return result;
  }

  InterfaceVector CouplingMethod::relaxed(const InterfaceVector& d, const InterfaceVector& r,
                                          const double omega)
  {
    InterfaceVector result = d;
    result.add(omega, r);
    return result;
  }

  void CouplingMethod::checkpoint(GlobalArchive& archive)
  {
    archive& iteration& previous_r& previous_d_tilde& time_step& last_relative_residual&
      last_residual& largest_residual;
  }
} // namespace fvfsi
