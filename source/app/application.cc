#include <deal.II/base/mpi.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <fvfsi/app/application.h>
#include <fvfsi/app/embedded_files.h>
#include <fvfsi/app/parameters.h>
#include <fvfsi/base/exceptions.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    /// `Plot history`: each *history.txt table of `dir` as a PNG beside it (FSI: fsi_history.png),
    /// by the built-in plot_history.py, written to `dir` so that it can be run again by hand.
    void plot_histories(const std::string& dir, std::ostream& out)
    {
      std::vector<std::filesystem::path> tables;
      for (const auto& entry : std::filesystem::directory_iterator(dir))
      {
        const std::string name = entry.path().filename().string();
        if (name.size() >= 11 && name.compare(name.size() - 11, 11, "history.txt") == 0)
          tables.push_back(entry.path());
      }
      if (tables.empty())
        return;
      const std::string script = dir + "/plot_history.py";
      std::ofstream(script) << embedded::plot_history_py;
      // Debian's /usr/bin/python3 has matplotlib from python3-matplotlib; a python3 found
      // earlier on the PATH (pyenv, conda) may not.
      std::string python;
      for (const std::string candidate : {"python3", "/usr/bin/python3"})
        if (std::system((candidate + " -c 'import matplotlib' > /dev/null 2>&1").c_str()) == 0)
        {
          python = candidate;
          break;
        }
      if (python.empty())
      {
        out << "fvfsi: no plot of the history: python3 with matplotlib is needed (Debian: "
               "apt-get install python3-matplotlib), then: python3 "
            << script << " TABLE.txt TABLE.png\n";
        return;
      }
      for (const auto& table : tables)
      {
        const std::string png = std::filesystem::path(table).replace_extension(".png").string();
        const std::string command =
          python + " '" + script + "' '" + table.string() + "' '" + png + "'";
        if (std::system(command.c_str()) == 0)
          out << "fvfsi: plotted the history: " << png << "\n";
        else
          out << "fvfsi: plotting the history failed: " << command << "\n";
      }
    }

    /// "fvfsi: fields for ParaView: DIR/fluid.pvd, DIR/solid.pvd".
    void name_field_files(const std::string& dir, std::ostream& out)
    {
      std::vector<std::string> pvd;
      for (const auto& entry : std::filesystem::directory_iterator(dir))
        if (entry.path().extension() == ".pvd")
          pvd.push_back(entry.path().string());
      std::sort(pvd.begin(), pvd.end());
      if (pvd.empty())
        return;
      out << "fvfsi: fields for ParaView:";
      for (unsigned int i = 0; i < pvd.size(); ++i)
        out << (i ? ", " : " ") << pvd[i];
      out << "\n";
    }

    /// True if every rank of `comm` calls this within `seconds` (a non-blocking barrier).
    bool all_ranks_arrive(const MPI_Comm comm, const double seconds)
    {
      if (Utilities::MPI::n_mpi_processes(comm) == 1)
        return true;
      MPI_Request request;
      MPI_Ibarrier(comm, &request);
      Timer waited;
      for (int done = 0;;)
      {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done)
          return true;
        if (waited.wall_time() > seconds)
          return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
    }

    const char* usage =
      "usage: fvfsi [CASE.prm] [--set \"Section/Sub/Key=value\"]... [--steps N]\n"
      "       fvfsi --print-parameters [CASE.prm]\n"
      "       fvfsi --help\n"
      "\n"
      "Runs the scene that CASE.prm describes. Without a file: the built-in default scene\n"
      "(prm/fsi_demo.prm), a 2D FSI demo: the Turek-Hron FSI1 flag behind a cylinder on coarse\n"
      "meshes, about 12 s on one core, written to output-demo/ with a PNG plot of its history.\n"
      "`--set` overrides one parameter after the file is read and may be repeated, e.g.\n"
      "  fvfsi case.prm --set \"Mesh/Global refinements=5\" --set \"Output directory=/tmp/run5\"\n"
      "`--steps N` stops after N time steps (a steady run: after N iterations of each of its\n"
      "loops) as if the run had ended there: for trying a case.\n"
      "`--print-parameters` prints every parameter with its value (default or from CASE.prm) and\n"
      "its documentation. Run in parallel with `mpirun -np N fvfsi CASE.prm`.\n"
      "Output: VTU/PVTU (+ .pvd) fields, text tables and summary.json in `Output directory`.\n";

    template <int dim>
    void run_scene(const AllParameters& p, const std::string& prm_directory, Summary& summary)
    {
      const std::string& out = p.run.output_directory;
      const auto run = [&summary, &p](auto&& scene)
      {
        scene.set_checkpoints(p.run.checkpoint);
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
      unsigned int steps = 0; ///< --steps N (0: none)
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
        else if (args[i] == "--steps")
        {
          const std::string n = i + 1 < args.size() ? args[++i] : std::string();
          if (!Patterns::Integer(1).match(n))
            throw std::runtime_error("--steps needs a positive whole number, not `" + n + "`");
          c.steps = Utilities::string_to_int(n);
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
      if (parameters.time.step_limit > 0) // --steps: the results are those of a shortened run
        summary.set("step_limit", parameters.time.step_limit);
      std::string steady_settings; // the steady settings taken (app/steady_settings.h)
      for (const std::string& setting : parameters.steady_settings)
      {
        if (root)
          out << "fvfsi: steady run, not in the file: " << setting << "\n";
        steady_settings += (steady_settings.empty() ? "" : "; ") + setting;
      }
      if (!steady_settings.empty())
        summary.set("steady_settings", steady_settings);
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
        name_field_files(dir, out);
        if (parameters.run.plot_history)
          plot_histories(dir, out);
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
      parameters.time.step_limit = command.steps;
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
      // The solvers' errors are collective: every rank gets here, and rank 0 says why. An error
      // only some ranks found (an expression that is not finite on a patch only they have) would
      // leave the others waiting in a collective call for ever: then this rank says why and
      // stops the whole run.
      if (!all_ranks_arrive(MPI_COMM_WORLD, 10.0))
      {
        std::cerr << "fvfsi: error on rank " << Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)
                  << " (not on every rank; the run is aborted): " << concise_message(e)
                  << std::endl;
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
      if (root)
        err << "fvfsi: error: " << concise_message(e) << "\n";
      return 1;
    }
  }
} // namespace fvfsi
