#include <fvfsi/mesh/mesh_parameters.h>

#include <stdexcept>

namespace fvfsi
{
  void MeshParameters::declare(dealii::ParameterHandler& prm, const std::string& section)
  {
    this->section = section;
    prm.enter_subsection(section);
    prm.add_parameter(
      "Generator", generator,
      "Name of a deal.II GridGenerator function (hyper_cube, subdivided_hyper_rectangle, "
      "hyper_shell, plate_with_a_hole, channel_with_cylinder, ...), one of fvfsi's benchmark "
      "meshes (fvfsi_turek_hron_channel, fvfsi_cavity_channel, fvfsi_tube_fluid, "
      "fvfsi_thick_plate_channel, ...: include/fvfsi/mesh/benchmark_meshes.h), or `file` to "
      "read `File name`.");
    prm.add_parameter(
      "Generator arguments", generator_arguments,
      "Arguments of the GridGenerator function, separated by `:` (points as `x, y`), "
      "as GridGenerator::generate_from_name_and_arguments reads them.");
    prm.add_parameter(
      "File name", file_name,
      "Mesh file read when Generator = file: Gmsh .msh, UCD .inp or VTK .vtk. A relative "
      "name is taken relative to the directory of the .prm file.");
    prm.add_parameter(
      "Global refinements", n_global_refinements,
      "Number of uniform refinements of the coarse mesh (curved manifolds are kept).",
      dealii::Patterns::Integer(0, 12));
    prm.add_parameter(
      "Distortion", distortion,
      "Random shift of every interior vertex, as a fraction of its shortest adjacent edge "
      "(for tests on irregular meshes; 0 = none, keep below 0.4).",
      dealii::Patterns::Double(0., 0.45));
    prm.add_parameter(
      "Distort coarse mesh", distort_coarse_mesh,
      "true: distort the coarse mesh (GridTools::distort_random) and refine it, so "
      "that the meshes of a refinement sweep are subdivisions of one distorted mesh; "
      "false: distort the refined mesh, a new random mesh on every level.");
    prm.add_parameter("Distortion seed", distortion_seed,
                      "Seed of the distortion's random numbers.");
    prm.add_parameter(
      "Patch names", patch_names,
      "Names of the boundary ids, e.g. `0: left, 1: right`; boundary conditions refer to "
      "patches by these names. An id without a name is called patch_<id>.");
    prm.leave_subsection();
  }

  std::string MeshParameters::patch_name(const unsigned int id) const
  {
    const auto it = patch_names.find(id);
    return it != patch_names.end() ? it->second : "patch_" + std::to_string(id);
  }

  unsigned int MeshParameters::patch_id(const std::string& name, const std::string& parameter) const
  {
    for (const auto& [id, n] : patch_names)
      if (n == name)
        return id;
    const std::string digits = name.rfind("patch_", 0) == 0 ? name.substr(6) : "";
    if (!digits.empty() && digits.size() < 6 &&
        digits.find_first_not_of("0123456789") == std::string::npos)
      return std::stoul(digits);
    std::string known;
    for (const auto& [id, n] : patch_names)
      known += " " + n;
    throw std::runtime_error(parameter + ": unknown patch `" + name + "` (" + section +
                             "/Patch names has:" + known + ")");
  }

  std::vector<unsigned int> MeshParameters::patch_ids(const std::vector<std::string>& names,
                                                      const std::string& parameter) const
  {
    std::vector<unsigned int> ids;
    for (const auto& name : names)
      ids.push_back(patch_id(name, parameter));
    return ids;
  }
} // namespace fvfsi
