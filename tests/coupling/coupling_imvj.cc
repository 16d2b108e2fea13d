// IQN-IMVJ, the QR filter and the residual-reduction criterion on the linear interface model
// (linear_interface_model.h: d~ = A d + b, n = 60, A symmetric with its eigenvalues spread over
// [-3, 0.5], strongly coupled), over 8 time steps with slowly changing right-hand sides b_s, each
// step starting from the last one's solution; relaxation 0.4, |r| <= 1e-10 |d~|.
// Asserted:
//   - IQN-IMVJ (dense J) converges on every step, on the first in as many iterations as IQN-ILS
//     (J_prev = 0: the same method), on every later one in fewer than IQN-ILS without reuse, and
//     ends at the exact solution of the last step (as IQN-ILS does) to 1e-8; in total it takes
//     fewer iterations than IQN-ILS reusing 3 time steps (printed per step: not on every one);
//   - the implicit J (IMVJ dense limit = 0) with a window of 8 >= the steps run is the dense J
//     up to round-off: iteration counts within 1 per step; with a window of 2 it still
//     converges on every step, in fewer iterations in total than IQN-ILS without reuse;
//   - Residual reduction = 1e-6 with Tolerance = 0 ends every step; with both set (Tolerance
//     3e-7) a step ends exactly when either is met (checked at every iteration against |r|,
//     |d~| and the step's largest |r| computed by the test), and some steps end by each alone;
//   - the QR filter, on a case with nearly dependent, inconsistent columns: IQN-ILS reusing the
//     columns of 8 time steps while A drifts (A_s = (1 + 0.1 s) A, added mass growing) and the
//     solid answers with an error of 1e-8 |d~| (solved to a tolerance), |r| <= 1e-6 |d~|: with
//     the default filter 1e-2 every step converges, in fewer iterations in total than without
//     a filter (0); IQN-IMVJ on the same case converges with the filter in no more iterations
//     than without.
// Iteration counts are printed (numdiff compares them exactly: a change means the algorithm
// changed).
#include "../test_utilities.h"
#include "linear_interface_model.h"

#include <algorithm>
#include <random>

using namespace fvfsi_test;

constexpr unsigned int size = 60, steps = 8;

/// The model with a drifting A (A_s = (1 + drift s) A) and an inexact solid: d~ carries a
/// pseudo-random error of eta x its rms (mt19937's raw numbers: the same on every machine).
struct DriftingModel : LinearInterfaceModel
{
  double eta, drift;
  mutable std::mt19937 random{42};
  mutable double scale = 1;
  DriftingModel(const double eta, const double drift)
      : LinearInterfaceModel(size), eta(eta), drift(drift)
  {
  }
  void set_step(const unsigned int s) const { scale = 1 + drift * s; }
  std::vector<double> solid_answer(const std::vector<double>& d, const std::vector<double>& b) const
  {
    std::vector<double> scaled = d;
    for (double& v : scaled)
      v *= scale;
    std::vector<double> y = LinearInterfaceModel::solid_answer(scaled, b);
    double rms = 0;
    for (const double v : y)
      rms += v * v / y.size();
    for (double& v : y)
      v += eta * std::sqrt(rms) * (random() / 4294967296.0 - 0.5);
    return y;
  }
};

std::vector<double> rhs(const unsigned int step)
{
  std::vector<double> b(size);
  for (unsigned int i = 0; i < size; ++i)
    b[i] = 1e-3 * std::cos(0.7 * i + 0.05 * step) + 2e-4 * std::sin(0.3 * i * (1 + 0.02 * step));
  return b;
}

struct Run
{
  std::vector<unsigned int> iterations; ///< per time step (0: did not converge)
  std::vector<double> d;                ///< the last step's solution
  bool converged() const { return std::count(iterations.begin(), iterations.end(), 0u) == 0; }
  unsigned int total() const
  {
    unsigned int t = 0;
    for (const unsigned int k : iterations)
      t += k;
    return t;
  }
  std::string counts() const
  {
    std::string s;
    for (const unsigned int k : iterations)
      s += std::to_string(k) + " ";
    return s + "(total " + std::to_string(total()) + ")";
  }
};

Run run(const DriftingModel& model, const fvfsi::CouplingParameters& p)
{
  const auto coupling_method = fvfsi::CouplingMethod::create(p);
  fvfsi::CouplingMethod& acceleration = *coupling_method;
  Run result;
  result.d.assign(size, 0.0);
  for (unsigned int s = 0; s < steps; ++s)
  {
    model.set_step(s);
    result.iterations.push_back(solve(acceleration, model, rhs(s), result.d));
  }
  return result;
}

fvfsi::CouplingParameters parameters(const std::string& method, const unsigned int reuse = 0,
                                     const unsigned int dense_limit = 2000,
                                     const unsigned int window = 8)
{
  fvfsi::CouplingParameters p;
  p.method = method;
  p.relaxation = 0.4;
  p.tolerance = 1e-10;
  p.reuse_time_steps = reuse;
  p.imvj_dense_limit = dense_limit;
  p.imvj_time_steps = window;
  return p;
}

double relative_error(const std::vector<double>& a, const std::vector<double>& b)
{
  double e = 0, nb = 0;
  for (unsigned int i = 0; i < a.size(); ++i)
  {
    e += (a[i] - b[i]) * (a[i] - b[i]);
    nb += b[i] * b[i];
  }
  return std::sqrt(e / nb);
}

/// Whether every step of `a` took fewer iterations than the same step of `b`, from step `first`.
bool fewer_on_each(const Run& a, const Run& b, const unsigned int first)
{
  for (unsigned int s = first; s < steps; ++s)
    if (!(a.iterations[s] > 0 && a.iterations[s] < b.iterations[s]))
      return false;
  return true;
}

void imvj_against_ils(std::ostream& out)
{
  const DriftingModel model(0, 0);
  const Run ils = run(model, parameters("IQN-ILS")), ils3 = run(model, parameters("IQN-ILS", 3)),
            dense = run(model, parameters("IQN-IMVJ")),
            implicit8 = run(model, parameters("IQN-IMVJ", 0, 0, 8)),
            implicit2 = run(model, parameters("IQN-IMVJ", 0, 0, 2));
  out << "iterations per time step, tolerance 1e-10:\n"
      << "  IQN-ILS:                          " << ils.counts() << "\n"
      << "  IQN-ILS reusing 3 time steps:     " << ils3.counts() << "\n"
      << "  IQN-IMVJ, dense J:                " << dense.counts() << "\n"
      << "  IQN-IMVJ, implicit J, 8 steps:    " << implicit8.counts() << "\n"
      << "  IQN-IMVJ, implicit J, 2 steps:    " << implicit2.counts() << "\n";
  const std::vector<double> exact = model.solution(rhs(steps - 1));
  out << "IQN-IMVJ converges on every step, the first as IQN-ILS, the later ones in fewer "
         "iterations than IQN-ILS: "
      << yes_no(dense.converged() && dense.iterations[0] == ils.iterations[0] &&
                fewer_on_each(dense, ils, 1))
      << "\n";
  out << "IQN-IMVJ and IQN-ILS end at the exact solution to 1e-8: "
      << yes_no(relative_error(dense.d, exact) < 1e-8 && relative_error(ils.d, exact) < 1e-8)
      << "\n";
  out << "IQN-IMVJ: fewer iterations in total than IQN-ILS reusing 3 time steps: "
      << yes_no(dense.total() < ils3.total()) << "\n";
  bool same = implicit8.converged();
  for (unsigned int s = 0; s < steps; ++s)
    same = same && std::abs(int(implicit8.iterations[s]) - int(dense.iterations[s])) <= 1;
  out << "implicit J over 8 steps: the dense J's iterations within 1 per step: " << yes_no(same)
      << "\n";
  out << "implicit J over 2 steps: converges, fewer iterations in total than IQN-ILS: "
      << yes_no(implicit2.converged() && implicit2.total() < ils.total() &&
                relative_error(implicit2.d, exact) < 1e-8)
      << "\n";
}

/// The runs of `p` over the steps, checking at every iteration that converged() says
/// |r| <= tolerance |d~| or |r| <= reduction x max |r| of the step (r and d~ computed here);
/// `agrees` false if it ever does not.
Run reduction_run(const fvfsi::CouplingParameters& p, bool& agrees, unsigned int (&ended_by)[3])
{
  const DriftingModel model(0, 0);
  const auto coupling_method = fvfsi::CouplingMethod::create(p);
  fvfsi::CouplingMethod& acceleration = *coupling_method;
  Run result;
  std::vector<double> d(size, 0.0);
  for (unsigned int s = 0; s < steps; ++s)
  {
    acceleration.new_time_step();
    double largest = 0;
    unsigned int k = 1;
    for (; k <= 400; ++k)
    {
      const fvfsi::InterfaceVector d_k(d.begin(), d.end());
      const std::vector<double> answer = model.solid_answer(d, rhs(s));
      const fvfsi::InterfaceVector d_tilde(answer.begin(), answer.end());
      fvfsi::InterfaceVector r = d_tilde;
      r -= d_k;
      largest = std::max(largest, r.l2_norm());
      const bool tolerance_met = r.l2_norm() <= p.tolerance * d_tilde.l2_norm(),
                 reduction_met = r.l2_norm() <= p.residual_reduction * largest,
                 expected = tolerance_met || reduction_met;
      const fvfsi::InterfaceVector next = acceleration.next(d_k, d_tilde);
      d.assign(next.begin(), next.end());
      agrees = agrees && acceleration.converged() == expected;
      if (acceleration.converged())
      {
        ++ended_by[tolerance_met && reduction_met ? 2 : tolerance_met ? 0 : 1];
        break;
      }
    }
    result.iterations.push_back(k <= 400 ? k : 0);
  }
  return result;
}

void residual_reduction(std::ostream& out)
{
  fvfsi::CouplingParameters tolerance = parameters("IQN-IMVJ"), reduction = tolerance,
                            both = tolerance;
  reduction.tolerance = 0;
  reduction.residual_reduction = 1e-6;
  both.residual_reduction = 1e-6;
  both.tolerance = 3e-7;
  bool agrees = true;
  unsigned int unused[3] = {0, 0, 0}, ended_by[3] = {0, 0, 0};
  const Run t = reduction_run(tolerance, agrees, unused),
            r = reduction_run(reduction, agrees, unused), b = reduction_run(both, agrees, ended_by);
  out << "IQN-IMVJ, Tolerance 1e-10:                      " << t.counts()
      << "\n  Residual reduction 1e-6 (Tolerance 0):        " << r.counts()
      << "\n  Residual reduction 1e-6 and Tolerance " << both.tolerance << ": " << b.counts()
      << "\n    steps ended by Tolerance alone: " << ended_by[0]
      << ", by Residual reduction alone: " << ended_by[1] << ", by both: " << ended_by[2] << "\n";
  out << "Residual reduction alone ends every step; at every iteration a step ends exactly when "
         "either criterion holds: "
      << yes_no(r.converged() && b.converged() && agrees) << "\n";
  out << "with both set, steps ended by each criterion alone: "
      << yes_no(ended_by[0] > 0 && ended_by[1] > 0) << "\n";
}

void qr_filter(std::ostream& out)
{
  const auto drifting = [](const std::string& method, const unsigned int reuse, const double filter)
  {
    const DriftingModel model(1e-8, 0.1);
    fvfsi::CouplingParameters p = parameters(method, reuse);
    p.tolerance = 1e-6;
    p.qr_filter = filter;
    return run(model, p);
  };
  const Run ils_on = drifting("IQN-ILS", 8, 1e-2), ils_off = drifting("IQN-ILS", 8, 0),
            imvj_on = drifting("IQN-IMVJ", 0, 1e-2), imvj_off = drifting("IQN-IMVJ", 0, 0);
  out << "drifting A, inexact solid, tolerance 1e-6:\n"
      << "  IQN-ILS reusing 8 time steps, QR filter 1e-2: " << ils_on.counts() << "\n"
      << "  IQN-ILS reusing 8 time steps, no QR filter:   " << ils_off.counts() << "\n"
      << "  IQN-IMVJ, QR filter 1e-2:                     " << imvj_on.counts() << "\n"
      << "  IQN-IMVJ, no QR filter:                       " << imvj_off.counts() << "\n";
  out << "IQN-ILS with reuse: filtered converges, in fewer iterations than unfiltered: "
      << yes_no(ils_on.converged() && ils_on.total() < ils_off.total()) << "\n";
  out << "IQN-IMVJ: filtered converges, in no more iterations than unfiltered: "
      << yes_no(imvj_on.converged() && imvj_on.total() <= imvj_off.total()) << "\n";
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  imvj_against_ils(out);
  residual_reduction(out);
  qr_filter(out);
}
