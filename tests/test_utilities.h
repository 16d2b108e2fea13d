#pragma once
// Small helpers shared by fvfsi's tests: the deal.II test convention is that a test writes its
// results to a file called `output` in its working directory (rank 0 only), which is then compared
// with NAME.output by numdiff.

#include <deal.II/base/mpi.h>

#include <fvfsi/scenes/poisson.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace fvfsi_test
{
  /// The `output` file on rank 0, a null stream elsewhere.
  inline std::ofstream open_output()
  {
    std::ofstream out;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      out.open("output");
    return out;
  }

  /// The numbers of a history table (fsi_history.txt, ...), line by line, without the `#` header.
  inline std::vector<std::vector<double>> read_table(const std::string& file)
  {
    std::ifstream in(file);
    std::string line;
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line))
    {
      if (line.empty() || line[0] == '#')
        continue;
      std::istringstream s(line);
      std::vector<double> row;
      for (double x; s >> x;)
        row.push_back(x);
      rows.push_back(row);
    }
    return rows;
  }

  /// Column `name` of a history table (its `# t drag ...` header names the columns).
  inline std::vector<double> history_column(const std::string& file, const std::string& name)
  {
    std::ifstream in(file);
    std::string header;
    std::getline(in, header);
    std::istringstream names(header.substr(1));
    unsigned int index = 0;
    for (std::string n; names >> n && n != name;)
      ++index;
    std::vector<double> values;
    for (const auto& row : read_table(file))
      values.push_back(row.at(index));
    return values;
  }

  /// Two history tables (read_table) line by line: the largest |a - b| of the vector made of
  /// `columns` (e.g. drag and lift), relative to the largest |b| of that vector; 1 if the tables
  /// differ in length or are empty.
  inline double vector_difference(const std::vector<std::vector<double>>& a,
                                  const std::vector<std::vector<double>>& b,
                                  const std::vector<unsigned int>& columns)
  {
    if (a.size() != b.size() || a.empty())
      return 1;
    double scale = 1e-300, difference = 0;
    for (unsigned int i = 0; i < b.size(); ++i)
    {
      double norm = 0, d = 0;
      for (const unsigned int c : columns)
      {
        norm += b[i][c] * b[i][c];
        d += (a[i][c] - b[i][c]) * (a[i][c] - b[i][c]);
      }
      scale = std::max(scale, std::sqrt(norm));
      difference = std::max(difference, std::sqrt(d));
    }
    return difference / scale;
  }

  inline std::string yes_no(const bool b)
  {
    return b ? "yes" : "NO";
  }

  /// printf-style formatting into a std::string.
  template <typename... Args>
  std::string format(const char* fmt, Args... args)
  {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, fmt, args...);
    return buffer;
  }

  /// A manufactured, non-polynomial Poisson problem on the unit square / cube, with Dirichlet
  /// boundaries except a Neumann patch at x = 1.
  template <int dim>
  fvfsi::PoissonParameters manufactured_poisson()
  {
    fvfsi::PoissonParameters p;
    if (dim == 3)
    {
      p.exact_solution = "exp(x)*sin(pi*y)*cos(pi*z)";
      p.exact_gradient = "exp(x)*sin(pi*y)*cos(pi*z); pi*exp(x)*cos(pi*y)*cos(pi*z); "
                         "-pi*exp(x)*sin(pi*y)*sin(pi*z)";
      p.source = "(2*pi^2 - 1)*exp(x)*sin(pi*y)*cos(pi*z)";
    }
    p.neumann_patches = {"patch_1"};
    return p;
  }
} // namespace fvfsi_test

#include <fvfsi/app/parameters.h>

namespace fvfsi_test
{
  /// The parameters of a shipped .prm file (prm/NAME.prm) with overrides, as fvfsi would read them.
  inline std::unique_ptr<fvfsi::AllParameters>
  shipped_case(const std::string& name, const std::vector<std::string>& overrides)
  {
    auto p = std::make_unique<fvfsi::AllParameters>();
    fvfsi::read_parameters(*p, std::string(FVFSI_SOURCE_DIR) + "/prm/" + name + ".prm", overrides);
    return p;
  }
} // namespace fvfsi_test

#include <filesystem>

namespace fvfsi_test
{
  /// The fluid scene of prm/NAME.prm with Time/Time step = dt and the `extra` overrides, run
  /// (writing to out/).
  inline std::unique_ptr<fvfsi::FluidScene<2>>
  run_fluid_case(const std::string& name, const double dt, const std::vector<std::string>& extra)
  {
    std::vector<std::string> overrides = {"Time/Time step=" + format("%.17g", dt),
                                          "Output directory=out"};
    overrides.insert(overrides.end(), extra.begin(), extra.end());
    const auto p = shipped_case(name, overrides);
    std::filesystem::create_directories("out");
    auto scene = std::make_unique<fvfsi::FluidScene<2>>(p->mesh, p->fluid, p->fluid_scene, p->time,
                                                        MPI_COMM_WORLD, ".", "out");
    scene->run();
    return scene;
  }
} // namespace fvfsi_test
