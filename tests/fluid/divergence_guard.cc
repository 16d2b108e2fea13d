// No silent divergence (the hard-case issue, item 1). The rigid plate in a channel of
// prm/wall_plate_channel.prm (25 110 cells, dt = 2.5 ms, largest Courant number about 4.3 at the
// plate's corners) run by the fvfsi executable's own entry point with the PISO correctors held at
// two (Fluid/Max pressure correctors = 2, the count fvfsi used before the self-converging
// correctors): the flow starts to oscillate near step 20 (Courant 4.2 -> 8 in five steps) and
// would blow up to a drag of -3e43 by t = 0.5 s. Asserted:
//   (a) the run stops at a step between 20 and 30 (measured: 25) with an exit code that is not
//       0, a message naming the time step, the quantity (max |u|), the position of the cell and
//       the bound with the parameter that sets it (Fluid/Velocity bound);
//   (b) summary.json says "failed" with that message and has no results;
//   (c) the last good state is written: the history holds every step before the one that
//       failed, and a checkpoint of it is there to continue from;
//   (d) the solid's guard: prm/turek_hron_csm3.prm on a 20 x 2 flag with Solid/Displacement
//       bound = 1e-4 (max |u| may not exceed 1e-4 x the flag's diameter) stops at time step 1
//       with its message.
// np = 1 and np = 2 print the same (the failing step's number, not the diverging values).
#include <fvfsi/app/application.h>

#include <boost/property_tree/json_parser.hpp>

#include "../test_utilities.h"

#include <filesystem>
#include <iostream>
#include <regex>
#include <sstream>

using namespace fvfsi_test;

struct Run
{
  int code = 0;
  std::string errors;
};

Run run(const std::string& prm, const std::vector<std::string>& settings)
{
  std::vector<std::string> args = {std::string(FVFSI_SOURCE_DIR) + "/prm/" + prm + ".prm"};
  for (const auto& s : settings)
  {
    args.push_back("--set");
    args.push_back(s);
  }
  std::ostringstream log, errors;
  std::streambuf* const console = std::cout.rdbuf(log.rdbuf());
  Run r;
  r.code = fvfsi::run_application(args, log, errors);
  std::cout.rdbuf(console);
  r.errors = errors.str();
  return r;
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();

  const Run fluid = run("wall_plate_channel", {"Fluid/Max pressure correctors=2",
                                               "Time/End time=0.1", "Output directory=plate"});
  std::smatch m;
  const bool named = std::regex_search(
    fluid.errors, m,
    std::regex("Fluid: the solution diverges at time step ([0-9]+) \\(t = [0-9.e-]+ s\\): max "
               "\\|u\\| = [0-9.e+]+ m/s in the cell at \\([-0-9.e]+, [-0-9.e]+\\), above the "
               "bound 100 m/s \\(10 x the velocity scale U = 10 m/s.*Fluid/Velocity bound\\)"));
  const unsigned int step = named ? std::stoul(m[1]) : 0;
  out << "(a) exit code not 0: " << yes_no(fluid.code != 0) << "\n"
      << "(a) message names the step, max |u|, the cell and Fluid/Velocity bound: " << yes_no(named)
      << "\n"
      << "(a) stopped at time step " << step
      << " (between 20 and 30: " << yes_no(step >= 20 && step <= 30) << ")\n";
  std::string status, error;
  bool results = true;
  try
  {
    boost::property_tree::ptree summary;
    boost::property_tree::read_json("plate/summary.json", summary);
    status = summary.get<std::string>("status");
    error = summary.get<std::string>("error", "");
    const auto r = summary.get_child_optional("results");
    results = r.has_value() && !r->empty();
  }
  catch (const std::exception& e)
  {
    out << "summary.json: " << e.what() << "\n";
  }
  out << "(b) summary.json status: " << status << ", its error is the message: "
      << yes_no(error.find("diverges at time step") == 0 ||
                error.find("Fluid: the solution diverges") == 0)
      << ", no results: " << yes_no(!results) << "\n";
  const auto history = read_table("plate/fluid_history.txt");
  out << "(c) history lines: " << history.size()
      << " (the steps before the failed one: " << yes_no(step > 0 && history.size() == step - 1)
      << "), checkpoint written: " << yes_no(std::filesystem::exists("plate/checkpoint/state"))
      << "\n";

  const Run solid =
    run("turek_hron_csm3", {"Mesh/Generator arguments=20: 2", "Time/End time=0.05",
                            "Solid/Displacement bound=1e-4", "Output directory=csm3"});
  out << "(d) solid: exit code not 0: " << yes_no(solid.code != 0) << ", message: "
      << yes_no(std::regex_search(solid.errors,
                                  std::regex("Solid: the solution diverges at time step 1 .*max "
                                             "\\|u\\| = .* m in the cell at .*Solid/"
                                             "Displacement bound")))
      << "\n";
}
