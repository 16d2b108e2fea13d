#include <deal.II/base/utilities.h>

#include <fvfsi/app/embedded_files.h>
#include <fvfsi/app/parameters.h>
#include <fvfsi/app/steady_settings.h>
#include <fvfsi/base/exceptions.h>

#include <fstream>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

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

  const SelectionNames<RunParameters::Scene> RunParameters::scene_names = {
    {"poisson", Scene::poisson},
    {"solid", Scene::solid},
    {"fluid", Scene::fluid},
    {"fsi", Scene::fsi}};

  void RunParameters::declare(ParameterHandler& prm)
  {
    prm.add_parameter("Dimension", dim, "Space dimension of the scene: 2 (true 2D) or 3.",
                      Patterns::Integer(2, 3));
    add_selection(prm, "Scene", scene, scene_names,
                  "What to run: poisson (the FV core verification problem), solid (the solid "
                  "solver alone), fluid (the flow solver alone, on a fixed or moving mesh) or "
                  "fsi (fluid and solid coupled; the fluid mesh is `Mesh`, the solid's `Solid "
                  "mesh`).");
    prm.add_parameter(
      "Output directory", output_directory,
      "Directory for VTU/PVTU/PVD files, tables and summary.json (created if needed).");
    prm.add_parameter("Checkpoint interval", checkpoint.interval,
                      "Write a checkpoint every this many time steps (0: none) into "
                      "`<Output directory>/checkpoint`, replacing the previous one: the meshes "
                      "with their vertex positions, every field and old time level, the coupling "
                      "state and the history files' lengths. Transient fluid, solid and FSI "
                      "scenes.");
    prm.add_parameter("Restart from", checkpoint.restart_from,
                      "The Output directory of an earlier run of this .prm file: continue from "
                      "its checkpoint (on any number of ranks) to this file's End time; the "
                      "history files and the .pvd record continue the earlier ones. Empty: start "
                      "from the beginning.");
    prm.add_parameter(
      "Initial state from", checkpoint.initial_state_from,
      "Steady FSI: the Output directory of an earlier steady FSI run, on any mesh (e.g. one "
      "twice as coarse): start from its final state (its fluid_state.txt and "
      "interface_state.txt, written at the end of every steady FSI run), each value taken "
      "from the nearest samples at the reference positions; the solid starts from rest. Mesh "
      "sequencing: the converged answer does not depend on the start, the cost does. Empty: "
      "start from rest.");
    prm.add_parameter("Plot history", plot_history,
                      "true: at the end of the run, plot every *history.txt table of the output "
                      "directory as NAME.png (one panel per column over time), with the script "
                      "plot_history.py written next to it (needs python3 with matplotlib).");
  }

  AllParameters::AllParameters()
  {
    run.declare(prm);
    time.declare(prm);
    mesh.patch_names = {{0, "left"}, {1, "right"}, {2, "bottom"},
                        {3, "top"},  {4, "back"},  {5, "front"}};
    // No refinement and no distortion unless asked for: a generator's mesh as it is drawn (the
    // Poisson defaults 5 and 0.25 made a benchmark mesh refine five times, unasked).
    mesh.distortion = 0;
    mesh.n_global_refinements = 0;
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
    if (file.empty())
      parameters.prm.parse_input_from_string(embedded::default_scene_prm, "", false);
    else
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
    parameters.steady_settings = apply_steady_settings(parameters);
  }

} // namespace fvfsi
