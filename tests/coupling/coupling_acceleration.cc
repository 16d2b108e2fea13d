// The coupling iteration's update rules (CouplingMethod: fixed relaxation, Aitken, IQN-ILS)
// on a model of a strongly coupled interface: the linear map d~ = A d + b with n = 20 unknowns and
// A symmetric with eigenvalues spread over [-3, 0.5]. Eigenvalues below -1 are what strong added
// mass does to a Dirichlet-Neumann iteration: plain Gauss-Seidel (omega = 1) diverges, and fixed
// relaxation converges only with omega < 0.5, slowly (best rate 0.78 per iteration).
// Asserted, for a relative residual |d~ - d| / |d~| <= 1e-10:
//   - fixed relaxation with omega = 1 diverges; with omega = 0.4 it converges;
//   - Aitken converges in fewer iterations than the fixed omega = 0.4;
//   - IQN-ILS converges in at most n + 3 iterations (for a linear map its least-squares Jacobian
//     is exact once it has n independent columns), in fewer than Aitken;
//   - IQN-ILS reusing the columns of the previous time step converges on a second time step
//     (new b) in at most 4 iterations.
// Iteration counts are printed: integers, the same on every machine up to round-off in the
// last iterations (numdiff compares them exactly; a change means the algorithm changed).
#include "../test_utilities.h"
#include "linear_interface_model.h"

using namespace fvfsi_test;

constexpr unsigned int n = 20;

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const LinearInterfaceModel model(n);
  std::vector<double> b1(n), b2(n);
  for (unsigned int i = 0; i < n; ++i)
  {
    b1[i] = 1e-3 * std::cos(0.7 * i);
    b2[i] = 1e-3 * std::cos(0.5 * i + 1);
  }
  const auto iterations = [&](const std::string& method, const double omega,
                              const unsigned int reuse, const bool second_step)
  {
    fvfsi::CouplingParameters p;
    p.method = method;
    p.tolerance = 1e-10;
    p.relaxation = omega;
    p.reuse_time_steps = reuse;
    const auto coupling_method = fvfsi::CouplingMethod::create(p);
    fvfsi::CouplingMethod& acceleration = *coupling_method;
    std::vector<double> d(n, 0.0);
    const unsigned int k1 = solve(acceleration, model, b1, d);
    return second_step ? solve(acceleration, model, b2, d) : k1;
  };
  const unsigned int gauss_seidel = iterations("fixed", 1.0, 0, false),
                     fixed = iterations("fixed", 0.4, 0, false),
                     aitken = iterations("Aitken", 0.4, 0, false),
                     iqn = iterations("IQN-ILS", 0.4, 0, false),
                     iqn_reuse = iterations("IQN-ILS", 0.4, 1, true);
  out << "iterations to 1e-10 (0: none): fixed omega = 1: " << gauss_seidel
      << ", fixed 0.4: " << fixed << ", Aitken: " << aitken << ", IQN-ILS: " << iqn
      << ", IQN-ILS second step reusing one step: " << iqn_reuse << "\n";
  out << "fixed omega = 1 diverges: " << yes_no(gauss_seidel == 0) << "\n";
  out << "fixed 0.4 converges: " << yes_no(fixed > 0) << "\n";
  out << "Aitken faster than fixed 0.4: " << yes_no(aitken > 0 && aitken < fixed) << "\n";
  out << "IQN-ILS within n + 3 and faster than Aitken: "
      << yes_no(iqn > 0 && iqn <= n + 3 && iqn < aitken) << "\n";
  out << "IQN-ILS with reuse: second step within 4: " << yes_no(iqn_reuse > 0 && iqn_reuse <= 4)
      << "\n";
}
