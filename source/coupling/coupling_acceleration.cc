#include <fvfsi/coupling/coupling_acceleration.h>

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    double dot(const std::vector<double>& a, const std::vector<double>& b)
    {
      return std::inner_product(a.begin(), a.end(), b.begin(), 0.0);
    }
    std::vector<double> difference(const std::vector<double>& a, const std::vector<double>& b)
    {
      std::vector<double> d(a.size());
      for (unsigned int i = 0; i < a.size(); ++i)
        d[i] = a[i] - b[i];
      return d;
    }
  } // namespace

  void CouplingParameters::declare(ParameterHandler& prm)
  {
    prm.enter_subsection("Coupling");
    prm.add_parameter("Method", method,
                      "How the interface displacement is updated between the fluid and solid "
                      "solves of a time step (Algorithm 1): fixed (relaxation), Aitken (dynamic "
                      "relaxation) or IQN-ILS (interface quasi-Newton, least-squares Jacobian).",
                      Patterns::Selection("fixed|Aitken|IQN-ILS"));
    prm.add_parameter("Relaxation", relaxation,
                      "omega of fixed relaxation (Eq. 31), also of the fixed iterations that start "
                      "every time step of Aitken and IQN-ILS.",
                      Patterns::Double(0, 1));
    prm.add_parameter("Fixed iterations", fixed_iterations,
                      "Aitken and IQN-ILS: fixed-relaxation iterations at the start of every time "
                      "step (the paper uses 2; IQN-ILS needs at least 1).",
                      Patterns::Integer(1));
    prm.add_parameter("Tolerance", tolerance,
                      "A time step has converged when |d~ - d|_2 <= this x |d~|_2 over the "
                      "interface vertices (Eq. 30).",
                      Patterns::Double(0));
    prm.add_parameter("Max iterations", max_iterations,
                      "Coupling iterations per time step before the run stops with an error.",
                      Patterns::Integer(1));
    prm.add_parameter("Reuse time steps", reuse_time_steps,
                      "IQN-ILS: also use the columns of this many earlier time steps (0: none).",
                      Patterns::Integer(0, 20));
    prm.leave_subsection();
  }

  CouplingAcceleration::CouplingAcceleration(const CouplingParameters& parameters)
    : prm(parameters)
    , omega(parameters.relaxation)
  {
  }

  void CouplingAcceleration::new_time_step()
  {
    ++time_step;
    iteration = 0;
    omega = prm.relaxation;
    previous_r.clear();
    previous_d_tilde.clear();
    // Drop IQN-ILS columns older than the reuse window.
    while (!column_step.empty() && column_step.back() + prm.reuse_time_steps < time_step)
    {
      V.pop_back();
      W.pop_back();
      column_step.pop_back();
    }
  }

  std::vector<double> CouplingAcceleration::next(const std::vector<double>& d,
                                                 const std::vector<double>& d_tilde)
  {
    ++iteration;
    const std::vector<double> r = difference(d_tilde, d);
    last_relative_residual = std::sqrt(dot(r, r)) / std::max(std::sqrt(dot(d_tilde, d_tilde)), 1e-300);

    std::vector<double> result;
    if (prm.method == "IQN-ILS")
    {
      if (!previous_r.empty())
      {
        V.push_front(difference(r, previous_r));
        W.push_front(difference(d_tilde, previous_d_tilde));
        column_step.push_front(time_step);
      }
      // Columns kept from earlier time steps already model the Jacobian: no fixed start then.
      const bool reused = !column_step.empty() && column_step.back() < time_step;
      if ((iteration > prm.fixed_iterations || reused) && !V.empty())
        result = iqn_ils(d_tilde, r);
    }
    else if (prm.method == "Aitken" && iteration > prm.fixed_iterations && !previous_r.empty())
    {
      const std::vector<double> dr = difference(r, previous_r);
      const double dr2 = dot(dr, dr);
      if (dr2 > 0)
        omega = -omega * dot(previous_r, dr) / dr2;
    }
    if (result.empty())
    {
      const double w = prm.method == "Aitken" ? omega : prm.relaxation;
      result = d;
      for (unsigned int i = 0; i < d.size(); ++i)
        result[i] += w * r[i];
    }
    previous_r = r;
    previous_d_tilde = d_tilde;
    return result;
  }

  std::vector<double> CouplingAcceleration::iqn_ils(const std::vector<double>& d_tilde,
                                                    const std::vector<double>& r)
  {
    // Least squares V c = -r by modified Gram-Schmidt (V = Q R), newest columns first; a column
    // that is (nearly) a combination of newer ones is left out.
    const unsigned int n = r.size();
    std::vector<std::vector<double>> Q;
    std::vector<unsigned int> kept;
    std::vector<std::vector<double>> R; // R[i][j], j >= i, over kept columns
    for (unsigned int k = 0; k < V.size(); ++k)
    {
      std::vector<double> q = V[k];
      const double norm0 = std::sqrt(dot(q, q));
      std::vector<double> column(Q.size() + 1, 0.0);
      for (unsigned int i = 0; i < Q.size(); ++i)
      {
        column[i] = dot(Q[i], q);
        for (unsigned int l = 0; l < n; ++l)
          q[l] -= column[i] * Q[i][l];
      }
      const double norm = std::sqrt(dot(q, q));
      if (norm <= 1e-2 * norm0 || norm0 == 0)
        continue;
      for (double& x : q)
        x /= norm;
      column.back() = norm;
      Q.push_back(q);
      R.push_back(column);
      kept.push_back(k);
    }
    if (Q.empty())
      return {};
    // c = R^-1 Q^T (-r), back substitution (R stored by columns).
    const unsigned int m = Q.size();
    std::vector<double> c(m);
    for (unsigned int i = 0; i < m; ++i)
      c[i] = -dot(Q[i], r);
    for (int i = m - 1; i >= 0; --i)
    {
      for (unsigned int j = i + 1; j < m; ++j)
        c[i] -= R[j][i] * c[j];
      c[i] /= R[i][i];
    }
    std::vector<double> result = d_tilde;
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int l = 0; l < n; ++l)
        result[l] += c[j] * W[kept[j]][l];
    return result;
  }
} // namespace fvfsi
