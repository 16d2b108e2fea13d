// The default scene (issue 15, item 3): `fvfsi` without a parameter file runs the built-in FSI
// demo (prm/fsi_demo.prm: the Turek-Hron FSI1 flag on coarse meshes, 300 time steps to a state at
// rest), prints progress and its result, writes VTU/PVD fields, fsi_history.txt and the PNG plot
// of the history, and says where. Run in-process (fvfsi::run_application, what main() calls).
// Asserted against the FSI1 reference (doc/reference/benchmarks.md, section 2: u(A) =
// (2.27e-5, 8.209e-4) m, drag 14.295 N/m, lift 0.7638 N/m) with bounds that hold on these coarse
// meshes (3 393 fluid and 328 solid cells; measured -2.9%, -2.2%, -0.5%, +0.04%): u_x(A) and
// u_y(A) within 4%, drag and lift within 1.5%. np = 1 and np = 2 print the same verdicts.
#include <fvfsi/app/application.h>

#include <boost/property_tree/json_parser.hpp>

#include "../test_utilities.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

using namespace fvfsi_test;

bool within(const double x, const double reference, const double tolerance)
{
  return std::abs(x - reference) <= tolerance * std::abs(reference);
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  std::ofstream out = open_output();
  // The scene's own lines go to std::cout (ConditionalOStream): collect them with the rest.
  std::ostringstream log, errors;
  std::streambuf* const console = std::cout.rdbuf(log.rdbuf());
  const int code = fvfsi::run_application({}, log, errors);
  std::cout.rdbuf(console);
  if (root)
    std::cout << log.str() << errors.str();
  // summary.json by Boost.PropertyTree (NaN where a value is missing: the verdicts say NO).
  const double nan = std::nan("");
  std::string status;
  std::vector<double> u(2, nan);
  double drag = nan, lift = nan;
  try
  {
    boost::property_tree::ptree summary;
    boost::property_tree::read_json("output-demo/summary.json", summary);
    status = summary.get<std::string>("status");
    drag = summary.get<double>("results.drag");
    lift = summary.get<double>("results.lift");
    u.clear();
    for (const auto& component : summary.get_child("results.point_A_displacement"))
      u.push_back(component.second.get_value<double>());
  }
  catch (const std::exception& e)
  {
    std::cout << "summary.json: " << e.what() << "\n";
  }
  const std::string text = log.str();
  std::ifstream history("output-demo/fsi_history.txt");
  unsigned int lines = 0;
  for (std::string line; std::getline(history, line);)
    lines += !line.empty() && line[0] != '#';

  out << "exit code " << code << ", status completed: " << yes_no(status == "completed") << "\n";
  out << "an FSI scene of 300 time steps with progress lines: "
      << yes_no(lines == 300 && (!root || text.find("FSI step 300/300") != std::string::npos))
      << "\n";
  out << "u_x(A), u_y(A) within 4% of FSI1: "
      << yes_no(u.size() == 2 && within(u[0], 2.27e-5, 0.04) && within(u[1], 8.209e-4, 0.04))
      << "\n";
  out << "drag, lift within 1.5% of FSI1: "
      << yes_no(within(drag, 14.295, 0.015) && within(lift, 0.7638, 0.015)) << "\n";
  out << "says where: fields (pvd), history plot: "
      << yes_no(root ? text.find("output-demo/fluid.pvd") != std::string::npos &&
                         text.find("output-demo/fsi_history.png") != std::string::npos
                     : true)
      << "\n";
  out << "the files exist: "
      << yes_no(std::filesystem::exists("output-demo/fluid.pvd") &&
                std::filesystem::exists("output-demo/solid.pvd") &&
                std::filesystem::exists("output-demo/fsi_history.png"))
      << "\n";
}
