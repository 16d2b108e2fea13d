#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <fvfsi/base/application.h>
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
      "FV Poisson problem with a manufactured solution on a distorted mesh). `--set` overrides one\n"
      "parameter after the file is read and may be repeated, e.g.\n"
      "  fvfsi case.prm --set \"Mesh/Global refinements=5\" --set \"Output directory=/tmp/run5\"\n"
      "`--print-parameters` prints every parameter with its value (default or from CASE.prm) and\n"
      "its documentation. Run in parallel with `mpirun -np N fvfsi CASE.prm`.\n"
      "Output: VTU/PVTU (+ .pvd) fields, text tables and summary.json in `Output directory`.\n";

    void apply_override(ParameterHandler& prm, const std::string& assignment)
    {
      const auto eq = assignment.find('=');
      if (eq == std::string::npos)
        throw std::runtime_error("--set \"" + assignment + "\": expected \"Section/Key=value\"");
      std::string path = Utilities::trim(assignment.substr(0, eq));
      const std::string value = Utilities::trim(assignment.substr(eq + 1));
      std::vector<std::string> sections;
      for (auto slash = path.find('/'); slash != std::string::npos; slash = path.find('/'))
      {
        sections.push_back(Utilities::trim(path.substr(0, slash)));
        path = path.substr(slash + 1);
      }
      for (const auto& s : sections)
        prm.enter_subsection(s);
      try
      {
        prm.set(Utilities::trim(path), value);
      }
      catch (const std::exception& e)
      {
        for (unsigned int i = 0; i < sections.size(); ++i)
          prm.leave_subsection();
        throw std::runtime_error("--set \"" + assignment + "\": " + concise_message(e));
      }
      for (unsigned int i = 0; i < sections.size(); ++i)
        prm.leave_subsection();
    }

    template <int dim>
    void run_scene(const AllParameters& p, const std::string& prm_directory, Summary& summary,
                   std::ostream& out)
    {
      if (p.run.scene == "poisson")
      {
        PoissonProblem<dim> problem(p.mesh, p.poisson, MPI_COMM_WORLD, prm_directory);
        problem.run();
        summary.set("n_cells", problem.results().n_cells);
        problem.output_results(p.run.output_directory, summary);
      }
      else if (p.run.scene == "solid")
      {
        SolidScene<dim> scene(p.mesh, p.solid, p.solid_scene, MPI_COMM_WORLD, prm_directory,
                              p.run.output_directory);
        scene.run();
        scene.write_summary(summary);
      }
      else if (p.run.scene == "fluid")
      {
        FluidScene<dim> scene(p.mesh, p.fluid, p.fluid_scene, MPI_COMM_WORLD, prm_directory,
                              p.run.output_directory);
        scene.run();
        scene.write_summary(summary);
      }
      else if (p.run.scene == "fsi")
      {
        FsiScene<dim> scene(p.mesh, p.fluid, p.fluid_scene, p.solid_mesh, p.solid, p.solid_scene,
                            p.fsi, MPI_COMM_WORLD, prm_directory, p.run.output_directory);
        scene.run();
        scene.write_summary(summary);
      }
      (void)out;
    }
  } // namespace

  void RunParameters::declare(ParameterHandler& prm)
  {
    prm.add_parameter("Dimension", dim, "Space dimension of the scene: 2 (true 2D) or 3.",
                      Patterns::Integer(2, 3));
    prm.add_parameter("Scene", scene,
                      "What to run: poisson (the FV core verification problem), solid (the solid "
                      "solver alone), fluid (the flow solver alone, on a fixed or moving mesh) or "
                      "fsi (fluid and solid coupled; the fluid mesh is `Mesh`, the solid's `Solid "
                      "mesh`).",
                      Patterns::Selection("poisson|solid|fluid|fsi"));
    prm.add_parameter("Output directory", output_directory,
                      "Directory for VTU/PVTU/PVD files, tables and summary.json (created if needed).");
  }

  AllParameters::AllParameters()
  {
    run.declare(prm);
    mesh.patch_names = {{0, "left"}, {1, "right"}, {2, "bottom"}, {3, "top"}, {4, "back"}, {5, "front"}};
    mesh.distortion = 0.25;
    mesh.n_global_refinements = 5;
    mesh.declare(prm);
    poisson.declare(prm);
    solid.declare(prm);
    solid_scene.declare(prm);
    fluid.declare(prm);
    fluid_scene.declare(prm);
    solid_mesh.declare(prm, "Solid mesh");
    fsi.declare(prm);
  }

  void read_parameters(AllParameters& parameters, const std::string& file,
                       const std::vector<std::string>& overrides)
  {
    if (!file.empty())
    {
      if (!std::ifstream(file))
        throw std::runtime_error("cannot open parameter file `" + file + "`");
      try
      {
        parameters.prm.parse_input(file, "", false, false);
      }
      catch (const std::exception& e)
      {
        throw std::runtime_error("in parameter file `" + file + "`: " + concise_message(e));
      }
    }
    for (const auto& o : overrides)
      apply_override(parameters.prm, o);
  }

  int run_application(const std::vector<std::string>& args, std::ostream& out, std::ostream& err)
  {
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    try
    {
      std::string file;
      std::vector<std::string> overrides;
      bool print = false;
      for (unsigned int i = 0; i < args.size(); ++i)
      {
        if (args[i] == "--help" || args[i] == "-h")
        {
          if (root)
            out << usage;
          return 0;
        }
        else if (args[i] == "--print-parameters")
          print = true;
        else if (args[i] == "--set")
        {
          if (i + 1 == args.size())
            throw std::runtime_error("--set needs an argument \"Section/Key=value\"");
          overrides.push_back(args[++i]);
        }
        else if (args[i].rfind("-", 0) == 0)
          throw std::runtime_error("unknown option `" + args[i] + "` (see fvfsi --help)");
        else if (file.empty())
          file = args[i];
        else
          throw std::runtime_error("more than one parameter file given: `" + file + "`, `" + args[i] + "`");
      }

      AllParameters parameters;
      read_parameters(parameters, file, overrides);
      if (print)
      {
        if (root)
          parameters.prm.print_parameters(out, ParameterHandler::PRM | ParameterHandler::KeepDeclarationOrder);
        return 0;
      }

      Timer timer;
      const std::string& dir = parameters.run.output_directory;
      if (root)
        std::filesystem::create_directories(dir);
      MPI_Barrier(MPI_COMM_WORLD);
      const std::string prm_directory =
        file.empty() ? "." : std::filesystem::path(file).parent_path().string();
      Summary summary;
      summary.set("scene", parameters.run.scene);
      summary.set("dim", parameters.run.dim);
      summary.set("n_mpi_ranks", Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
      if (parameters.run.dim == 2)
        run_scene<2>(parameters, prm_directory.empty() ? "." : prm_directory, summary, out);
      else
        run_scene<3>(parameters, prm_directory.empty() ? "." : prm_directory, summary, out);
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
