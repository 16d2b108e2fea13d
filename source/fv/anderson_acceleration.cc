#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fvfsi/fv/anderson_acceleration.h>

namespace fvfsi
{
  using namespace dealii;

  AndersonAcceleration::AndersonAcceleration(MPI_Comm comm, const unsigned int depth)
    : comm(comm), depth(depth)
  {
  }

  void AndersonAcceleration::reset()
  {
    previous_f.clear();
    previous_g.clear();
    dF.clear();
    dG.clear();
  }

  double AndersonAcceleration::dot(const std::vector<double>& a, const std::vector<double>& b) const
  {
    double s = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      s += a[i] * b[i];
    return Utilities::MPI::sum(s, comm);
  }

  void AndersonAcceleration::step(const std::vector<double>& x, std::vector<double>& g)
  {
    const unsigned int n = x.size();
    std::vector<double> f(n);
    for (unsigned int i = 0; i < n; ++i)
      f[i] = g[i] - x[i];
    if (!previous_f.empty() && depth > 0)
    {
      std::vector<double> df(n), dg(n);
      for (unsigned int i = 0; i < n; ++i)
      {
        df[i] = f[i] - previous_f[i];
        dg[i] = g[i] - previous_g[i];
      }
      dF.push_back(std::move(df));
      dG.push_back(std::move(dg));
      if (dF.size() > depth)
      {
        dF.pop_front();
        dG.pop_front();
      }
    }
    previous_f = f;
    previous_g = g;
    const unsigned int m = dF.size();
    if (m == 0)
      return;
    // Normal equations of the small least-squares problem, with a relative Tikhonov shift that
    // keeps them solvable when columns become nearly dependent.
    FullMatrix<double> M(m, m);
    Vector<double> rhs(m), gamma(m);
    for (unsigned int a = 0; a < m; ++a)
    {
      for (unsigned int b = 0; b <= a; ++b)
        M(a, b) = M(b, a) = dot(dF[a], dF[b]);
      rhs(a) = dot(dF[a], f);
    }
    for (unsigned int a = 0; a < m; ++a)
      M(a, a) *= 1 + 1e-10;
    M.gauss_jordan();
    M.vmult(gamma, rhs);
    for (unsigned int a = 0; a < m; ++a)
      for (unsigned int i = 0; i < n; ++i)
        g[i] -= gamma(a) * dG[a][i];
  }
} // namespace fvfsi
