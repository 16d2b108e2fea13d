#include <deal.II/base/mpi.templates.h>

#include <fvfsi/io/point_values.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;
  namespace bgi = boost::geometry::index;

  template <int dim>
  void write_point_values(const std::string& file, const std::vector<std::string>& columns,
                          const std::vector<Point<dim>>& points,
                          const std::vector<std::vector<double>>& rows, const MPI_Comm comm)
  {
    // Each rank's rows as one flat vector (coordinates, then the values), gathered on rank 0.
    std::vector<double> local;
    for (unsigned int i = 0; i < points.size(); ++i)
    {
      for (unsigned int d = 0; d < dim; ++d)
        local.push_back(points[i][d]);
      local.insert(local.end(), rows[i].begin(), rows[i].end());
    }
    const auto all = Utilities::MPI::gather(comm, local, 0);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::ofstream out(file);
    if (!out)
      throw std::runtime_error("cannot write `" + file + "`");
    const char* axis[] = {"x", "y", "z"};
    out << "#";
    for (unsigned int d = 0; d < dim; ++d)
      out << " " << axis[d];
    for (const auto& c : columns)
      out << " " << c;
    out << "\n" << std::setprecision(17);
    const unsigned int width = dim + columns.size();
    for (const auto& rank_rows : all)
      for (unsigned int k = 0; k < rank_rows.size(); ++k)
        out << rank_rows[k] << ((k + 1) % width == 0 ? "\n" : " ");
    if (!out)
      throw std::runtime_error("writing `" + file + "` failed");
  }

  template <int dim>
  PointValues<dim>::PointValues(const std::string& file, const std::vector<std::string>& columns,
                                const std::string& parameter)
  {
    const auto fail = [&](const std::string& why)
    { throw std::runtime_error(parameter + ": `" + file + "` " + why); };
    std::ifstream in(file);
    if (!in)
      fail("cannot be read (a steady run writes it at its end)");
    std::string line;
    std::getline(in, line);
    std::istringstream header(line);
    std::string word;
    header >> word;
    std::vector<std::string> names;
    while (header >> word)
      names.push_back(word);
    if (word.empty() || names.size() < dim)
      fail("has no header line `# x y ...`");
    std::vector<unsigned int> column_of; // the file's column of each asked-for column
    for (const auto& c : columns)
    {
      const auto it = std::find(names.begin() + dim, names.end(), c);
      if (it == names.end())
        fail("has no column `" + c + "`");
      column_of.push_back(it - names.begin());
    }
    std::vector<double> row(names.size());
    for (unsigned int n = 2; std::getline(in, line); ++n)
    {
      std::istringstream numbers(line);
      for (double& x : row)
        if (!(numbers >> x))
          fail("line " + std::to_string(n) + ": expected " + std::to_string(names.size()) +
               " numbers");
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = row[d];
      points.push_back(x);
      std::vector<double> v;
      for (const unsigned int k : column_of)
        v.push_back(row[k]);
      values.push_back(v);
    }
    if (points.empty())
      fail("has no rows");
    std::vector<std::pair<Point<dim>, unsigned int>> leaves;
    for (unsigned int k = 0; k < points.size(); ++k)
      leaves.emplace_back(points[k], k);
    tree = pack_rtree(leaves);
  }

  template <int dim>
  std::vector<double> PointValues<dim>::value(const Point<dim>& x) const
  {
    std::vector<unsigned int> nearest;
    for (const auto& leaf : tree | bgi::adaptors::queried(bgi::nearest(x, 1u << dim)))
      nearest.push_back(leaf.second);
    std::sort(nearest.begin(), nearest.end()); // a fixed summation order
    std::vector<double> sum(values[0].size(), 0.0);
    double weight_sum = 0;
    for (const unsigned int k : nearest)
    {
      const double distance_squared = x.distance_square(points[k]);
      if (distance_squared == 0)
        return values[k];
      const double weight = 1 / distance_squared;
      for (unsigned int j = 0; j < sum.size(); ++j)
        sum[j] += weight * values[k][j];
      weight_sum += weight;
    }
    for (double& s : sum)
      s /= weight_sum;
    return sum;
  }

  template void write_point_values(const std::string&, const std::vector<std::string>&,
                                   const std::vector<Point<2>>&,
                                   const std::vector<std::vector<double>>&, MPI_Comm);
  template void write_point_values(const std::string&, const std::vector<std::string>&,
                                   const std::vector<Point<3>>&,
                                   const std::vector<std::vector<double>>&, MPI_Comm);
  template class PointValues<2>;
  template class PointValues<3>;
} // namespace fvfsi
