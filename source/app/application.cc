#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <fvfsi/app/application.h>
#include <fvfsi/app/parameters.h>
#include <fvfsi/base/exceptions.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    const char* usage =
      "usage: fvfsi [CASE.prm] [--set \"Section/Sub/Key=value\"]...\n"
      "       fvfsi --print-parameters [CASE.prm]\n"
      "       fvfsi --help\n"
      "\n"
      "Runs the scene that CASE.prm describes (without a file: the built-in default scene, a 2D\n"
      "FV Poisson problem with a manufactured solution on a distorted mesh). `--set` overrides "
      "one\n"
      "parameter after the file is read and may be repeated, e.g.\n"
      "  fvfsi case.prm --set \"Mesh/Global refinements=5\" --set \"Output directory=/tmp/run5\"\n"
      "`--print-parameters` prints every parameter with its value (default or from CASE.prm) and\n"
      "its documentation. Run in parallel with `mpirun -np N fvfsi CASE.prm`.\n"
      "Output: VTU/PVTU (+ .pvd) fields, text tables and summary.json in `Output directory`.\n";

    template <int dim>
    void run_scene(const AllParameters& p, const std::string& prm_directory, Summary& summary)
    {
      const std::string& out = p.run.output_directory;
      const auto run = [&summary](auto&& scene)
      {
        scene.run();
        scene.write_summary(summary);
      };
      switch (p.run.scene)
      {
        case RunParameters::Scene::poisson:
        {
          PoissonProblem<dim> problem(p.mesh, p.poisson, MPI_COMM_WORLD, prm_directory);
          problem.run();
          summary.set("n_cells", problem.results().n_cells);
          problem.output_results(out, summary);
          break;
        }
        case RunParameters::Scene::solid:
          run(SolidScene<dim>(p.mesh, p.solid, p.solid_scene, p.time, MPI_COMM_WORLD, prm_directory,
                              out));
          break;
        case RunParameters::Scene::fluid:
          run(FluidScene<dim>(p.mesh, p.fluid, p.fluid_scene, p.time, MPI_COMM_WORLD, prm_directory,
                              out));
          break;
        case RunParameters::Scene::fsi:
          run(FsiScene<dim>(p.fsi_input(), MPI_COMM_WORLD, prm_directory, out));
          break;
      }
    }

    /// What the command line asks for.
    struct CommandLine
    {
      bool help = false, print = false;
      std::string file;
      std::vector<std::string> overrides;
    };

    CommandLine parse_command_line(const std::vector<std::string>& args)
    {
      CommandLine c;
      for (unsigned int i = 0; i < args.size(); ++i)
        if (args[i] == "--help" || args[i] == "-h")
          c.help = true;
        else if (args[i] == "--print-parameters")
          c.print = true;
        else if (args[i] == "--set")
        {
          if (i + 1 == args.size())
            throw std::runtime_error("--set needs an argument \"Section/Key=value\"");
          c.overrides.push_back(args[++i]);
        }
        else if (args[i].rfind("-", 0) == 0)
          throw std::runtime_error("unknown option `" + args[i] + "` (see fvfsi --help)");
        else if (c.file.empty())
          c.file = args[i];
        else
          throw std::runtime_error("more than one parameter file given: `" + c.file + "`, `" +
                                   args[i] + "`");
      return c;
    }

    /// Run the scene of `parameters` and write its summary.json; `file` is the .prm file (its
    /// directory resolves relative mesh file names).
    void run(const AllParameters& parameters, const std::string& file, std::ostream& out)
    {
      const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      Timer timer;
      const std::string& dir = parameters.run.output_directory;
      // summary.json is only ever this run's: one left by an earlier run in the same directory
      // would pass for this run's result if this one fails.
      if (root)
      {
        std::filesystem::create_directories(dir);
        std::filesystem::remove(dir + "/summary.json");
      }
      MPI_Barrier(MPI_COMM_WORLD);
      std::string prm_directory = std::filesystem::path(file).parent_path().string();
      if (prm_directory.empty())
        prm_directory = ".";
      Summary summary;
      summary.set("scene", selection_name(RunParameters::scene_names, parameters.run.scene));
      summary.set("dim", parameters.run.dim);
      summary.set("n_mpi_ranks", Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
      try
      {
        if (parameters.run.dim == 2)
          run_scene<2>(parameters, prm_directory, summary);
        else
          run_scene<3>(parameters, prm_directory, summary);
      }
      catch (const std::exception& e)
      {
        // A failed run says so in its summary (status "failed" and the message; no results), so
        // that a script collecting summaries cannot take it for a finished one (written by rank 0
        // when the error reaches it; the solvers' errors are collective).
        if (root)
        {
          Summary failed;
          failed.set("status", std::string("failed"));
          failed.set("error", concise_message(e));
          failed.set("wall_seconds", timer.wall_time());
          failed.write(dir + "/summary.json");
        }
        throw;
      }
      summary.set("status", std::string("completed"));
      summary.set("wall_seconds", Utilities::MPI::max(timer.wall_time(), MPI_COMM_WORLD));
      // Peak resident memory of the largest rank [MB] (VmHWM: libraries included, so memory per
      // cell is the slope between two mesh sizes, not this over n_cells).
      Utilities::System::MemoryStats memory;
      Utilities::System::get_memory_stats(memory);
      summary.set("peak_memory_mb", Utilities::MPI::max(memory.VmHWM / 1024.0, MPI_COMM_WORLD));
      if (root)
      {
        summary.write(dir + "/summary.json");
        out << "fvfsi: wrote " << dir << "/summary.json\n";
      }
    }
  } // namespace

  int run_application(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
  {
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    try
    {
      const CommandLine command = parse_command_line(args);
      if (command.help)
      {
        if (root)
          out << usage;
        return 0;
      }
      AllParameters parameters;
      read_parameters(parameters, command.file, command.overrides);
      if (command.print)
      {
        if (root)
          parameters.prm.print_parameters(out, ParameterHandler::PRM |
                                                 ParameterHandler::KeepDeclarationOrder);
        return 0;
      }
      run(parameters, command.file, out);
      return 0;
    }
    catch (const std::exception& e)
    {
      if (root)
        err << "fvfsi: error: " << concise_message(e) << "\n";
      return 1;
    }
  }
} // namespace fvfsi
