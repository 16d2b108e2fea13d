#pragma once
// Anderson acceleration of a fixed-point iteration x <- G(x) on distributed vectors (the owned
// entries of each rank, concatenated). With the residual f = G(x) - x, it keeps the last m
// differences dF, dG and returns
//
//   x_new = G(x) - dG gamma,   gamma = argmin |f - dF gamma|_2,
//
// the same least-squares model as the IQN-ILS coupling of Degroote et al. (the paper's ref [43]).
// Used for the solid's outer iterations, whose plain fixed-point form converges linearly.

#include <deal.II/base/mpi.h>

#include <deque>
#include <vector>

namespace fvfsi
{
  class AndersonAcceleration
  {
  public:
    AndersonAcceleration(MPI_Comm comm, unsigned int depth);

    /// Forget the history (e.g. at a new time step, or when the problem changes).
    void reset();

    /// Given x and g = G(x), overwrite g with the accelerated next iterate.
    void step(const std::vector<double>& x, std::vector<double>& g);

  private:
    double dot(const std::vector<double>& a, const std::vector<double>& b) const;

    MPI_Comm comm;
    unsigned int depth;
    std::vector<double> previous_f, previous_g;
    std::deque<std::vector<double>> dF, dG;
  };
} // namespace fvfsi
