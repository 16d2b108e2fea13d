/* ---------------------------------------------------------------------
 * step-5: an FSI case of your own, from a .prm file
 *
 * Steps 1-4 open the library up; this one stays outside it, where a user of fvfsi works: a
 * parameter file (flap_in_channel.prm), two meshes made by a script of one's own (make_meshes.py writes
 * them as UCD files), and the fvfsi executable. The program calls fvfsi exactly as the command
 * line does (fvfsi::run_application, the whole of the executable's main()) and then reads what a
 * run leaves behind, as a user's own script would:
 *
 *   1. the run:        fvfsi flap_in_channel.prm --set "Output directory=run"
 *                      -> run/fsi_history.txt (a line per time step), run/summary.json (the
 *                         results, the cost, the status), run/fluid.pvd, run/solid.pvd (ParaView);
 *   2. a study:        the same file with `--set` changing one setting per run (here the
 *                      coupling method: Aitken against IQN-ILS over the first 0.3 s);
 *   3. a restart:      the first half with `Checkpoint interval`, the second half with
 *                      `Restart from`; it must end where the run of 1. ends;
 *   4. a run that stops: Gauss-Seidel coupling (fixed relaxation with omega = 1), which the added
 *                      mass of this flap makes diverge: fvfsi exits with code 1, says why and
 *                      what to change, marks summary.json as failed, and keeps the last
 *                      converged state.
 *
 * Everything here can be typed in a shell instead; README.md shows those commands.
 * --------------------------------------------------------------------- */

// @sect3{Include files}
// The executable's entry point, and Boost's JSON reader for summary.json.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include "../tutorial.h"
#include <fvfsi/app/application.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace Step5
{
const std::string case_file =
  std::string(FVFSI_SOURCE_DIR) + "/doc/tutorials/step-5/flap_in_channel.prm";

// @sect3{Running fvfsi}
// `fvfsi flap_in_channel.prm --set A --set B ...`: the arguments as the shell would pass them. Returns
// the exit code; what fvfsi writes to stderr (its error message) goes into `error`.
int fvfsi(const std::vector<std::string>& settings, std::string& error)
{
  std::vector<std::string> args = {case_file};
  for (const std::string& s : settings)
  {
    args.push_back("--set");
    args.push_back(s);
  }
  std::ostringstream err;
  const int code = fvfsi::run_application(args, std::cout, err);
  error = err.str();
  return code;
}

// @sect3{Reading what a run leaves}
// fsi_history.txt: a header line `# t coupling_iterations ...` and one line of numbers per time
// step (the columns are listed in README.md). A dozen lines of C++, or one of numpy:
//   numpy.genfromtxt("run/fsi_history.txt", names=True)
struct History
{
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  double last(const std::string& column) const
  {
    for (unsigned int j = 0; j < columns.size(); ++j)
      if (columns[j] == column)
        return rows.back()[j];
    throw std::runtime_error("no column " + column);
  }
  double mean(const std::string& column, const double from_time) const
  {
    double sum = 0;
    unsigned int n = 0;
    for (unsigned int j = 0; j < columns.size(); ++j)
      if (columns[j] == column)
        for (const auto& row : rows)
          if (row[0] > from_time)
          {
            sum += row[j];
            ++n;
          }
    return n > 0 ? sum / n : 0;
  }
};

History read_history(const std::string& file)
{
  std::ifstream in(file);
  if (!in)
    throw std::runtime_error("cannot read " + file);
  History h;
  std::string line, word;
  std::getline(in, line);
  std::istringstream header(line.substr(1)); // after the '#'
  while (header >> word)
    h.columns.push_back(word);
  while (std::getline(in, line))
  {
    std::istringstream values(line);
    std::vector<double> row;
    double x;
    while (values >> x)
      row.push_back(x);
    if (row.size() == h.columns.size())
      h.rows.push_back(row);
  }
  return h;
}

// summary.json: {"status": ..., "wall_seconds": ..., "results": {...}, "timing": {...}}.
boost::property_tree::ptree read_summary(const std::string& file)
{
  boost::property_tree::ptree summary;
  boost::property_tree::read_json(file, summary);
  return summary;
}

// Line n (from 0) of a message.
std::string line_of(const std::string& text, const unsigned int n)
{
  std::istringstream lines(text);
  std::string line;
  for (unsigned int i = 0; i <= n; ++i)
    if (!std::getline(lines, line))
      return "";
  return line;
}

// printf into a std::string.
template <typename... Args>
std::string format(const char* pattern, const Args&... args)
{
  char buffer[512];
  std::snprintf(buffer, sizeof(buffer), pattern, args...);
  return buffer;
}

std::string yes_no(const bool b)
{
  return b ? "yes" : "NO";
}

// @sect3{The four runs}
// The numbers printed are those a user reads: the tip displacement, the drag, the coupling
// iterations. The test compares them with step-5.output by numdiff (-a 1e-6 -r 1e-8, deal.II's
// defaults): the displacement in mm and the drag to 4 significant digits, iteration counts as
// integers (each step's residual crosses the tolerance by a factor, not at round-off). What
// must hold is a verdict line with its tolerance written out.
void run()
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  std::ostringstream text;
  std::string error;

  // 1. The run, as shipped.
  const int code = fvfsi({"Output directory=run"}, error);
  const History run = read_history("run/fsi_history.txt");
  const auto summary = read_summary("run/summary.json");
  // The probe `tip` (the flap's top centre) gives the columns ux_tip and uy_tip [m].
  const double ux = run.last("ux_tip"), drag = run.last("drag");
  text << "1. fvfsi flap_in_channel.prm: exit code " << code << ", status "
       << summary.get<std::string>("status") << ", " << run.rows.size() << " time steps, "
       << summary.get<unsigned int>("results.coupling_iterations") << " coupling iterations\n"
       << format("   at t = %.2f s: tip u_x = %.4f mm, drag = %.4g N/m\n", run.last("t"), 1e3 * ux,
                 drag);

  // 2. A study: Aitken against IQN-ILS over the first 0.3 s (30 steps).
  text << "2. --set \"Coupling/Method=...\", to t = 0.3 s: coupling iterations per step\n";
  std::vector<double> iterations;
  for (const std::string method : {"Aitken", "IQN-ILS"})
  {
    fvfsi({"Output directory=study-" + method, "Coupling/Method=" + method, "Time/End time=0.3"},
          error);
    const History h = read_history("study-" + method + "/fsi_history.txt");
    iterations.push_back(h.mean("coupling_iterations", 0));
    text << format("   %-8s %.2f\n", method.c_str(), iterations.back());
  }

  // 3. A restart: the first 50 steps with a checkpoint, then the rest from it.
  fvfsi({"Output directory=first-half", "Time/End time=0.5", "Checkpoint interval=50"}, error);
  fvfsi({"Output directory=second-half", "Restart from=first-half"}, error);
  const History second = read_history("second-half/fsi_history.txt");
  const double restart_difference = std::abs(second.last("ux_tip") - ux);
  text << "3. restarted at t = 0.5 s from first-half/checkpoint: "
       << format("tip u_x = %.4f mm at t = %.2f s\n", 1e3 * second.last("ux_tip"),
                 second.last("t"));

  // 4. A run that stops: Gauss-Seidel coupling diverges on this flap (rho_s = rho_f).
  const int failed_code = fvfsi({"Output directory=stopped", "Coupling/Method=fixed",
                                 "Coupling/Relaxation=1", "Coupling/Max iterations=20"},
                                error);
  const auto failed = read_summary("stopped/summary.json");
  const History stopped = read_history("stopped/fsi_history.txt");
  text << "4. Coupling/Method = fixed, Relaxation = 1: exit code " << failed_code << ", status "
       << failed.get<std::string>("status") << ", " << stopped.rows.size()
       << " converged time steps kept in stopped/fsi_history.txt\n"
       << "   " << line_of(failed.get<std::string>("error"), 1) << "\n\n";

  // The verdicts.
  text << "The run completed and the flap bends downstream by 1-20 mm: "
       << yes_no(code == 0 && summary.get<std::string>("status") == "completed" &&
                 run.last("ux_tip") > 1e-3 && run.last("ux_tip") < 2e-2)
       << "\nIQN-ILS needs fewer coupling iterations than Aitken: "
       << yes_no(iterations[1] < iterations[0])
       << "\nThe restarted run ends where the straight run does (tip u_x within 1e-12 m): "
       << yes_no(restart_difference <= 1e-12 && std::abs(second.last("t") - run.last("t")) < 1e-9)
       << "\nThe Gauss-Seidel run stops with exit code 1 and a failed summary: "
       << yes_no(failed_code == 1 && failed.get<std::string>("status") == "failed") << "\n";

  if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
  {
    std::cout << '\n' << text.str();
    std::ofstream("output") << text.str(); // the file the test suite compares
  }
}
} // namespace Step5

int main(int argc, char** argv)
{
  return fvfsi_tutorial::main_program(argc, argv, "step-5", Step5::run);
}
