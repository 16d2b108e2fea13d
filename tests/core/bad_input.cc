// Bad input gives a non-zero exit code and a message that names what is wrong: an unknown key
// (with file and line), a value that does not match its pattern, a missing parameter file, a
// missing mesh file, a bad --set override, a bad expression. Each case writes a small .prm file,
// runs the fvfsi command line in-process (fvfsi::run_application, what the executable's main()
// calls) and prints the exit code and the message.
#include <fvfsi/app/application.h>

#include "../test_utilities.h"

#include <sstream>

using namespace fvfsi_test;

void run(std::ofstream& out, const std::string& title, const std::string& prm_text,
         std::vector<std::string> args)
{
  if (!prm_text.empty())
    std::ofstream(args[0]) << prm_text;
  std::ostringstream stdout_text, stderr_text;
  const int code = fvfsi::run_application(args, stdout_text, stderr_text);
  out << "* " << title << "\n  exit code " << code << "\n  " << stderr_text.str() << "\n";
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  run(out, "unknown key", "set Dimension = 2\nsubsection Mesh\n  set Global refinment = 3\nend\n",
      {"unknown_key.prm"});
  run(out, "unknown section", "subsection Meshes\n  set Global refinements = 3\nend\n",
      {"unknown_section.prm"});
  run(out, "bad value", "set Dimension = 4\n", {"bad_value.prm"});
  run(out, "bad value type", "subsection Mesh\n  set Distortion = lots\nend\n", {"bad_type.prm"});
  run(out, "missing parameter file", "", {"no_such_file.prm"});
  run(out, "missing mesh file",
      "set Output directory = bad_input_out\nsubsection Mesh\n  set Generator = file\n"
      "  set File name = no_such_mesh.msh\nend\n",
      {"missing_mesh.prm"});
  run(
    out, "unknown generator",
    "set Output directory = bad_input_out\nsubsection Mesh\n  set Generator = hyper_cheese\nend\n",
    {"bad_generator.prm"});
  run(out, "bad --set key", "", {"--set", "Mesh/Refinements=3"});
  run(out, "bad --set value", "", {"--set", "Mesh/Global refinements=-1"});
  run(out, "bad expression",
      "set Output directory = bad_input_out\nsubsection Poisson\n  set Source = sin(x\nend\n",
      {"bad_expression.prm"});
  run(out, "unknown patch",
      "set Output directory = bad_input_out\nsubsection Poisson\n  set Neumann patches = "
      "outlet\nend\n",
      {"bad_patch.prm"});
  run(out, "unknown option", "", {"--frobnicate"});
  run(out, "bad --steps", "", {"--steps", "two"});
}
