#pragma once
// The `subsection Mesh` of a .prm file: where the mesh comes from and what is done to it.

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <vector>

namespace fvfsi
{
  struct MeshParameters
  {
    /// `GridGenerator` function name (e.g. hyper_cube, hyper_shell, plate_with_a_hole), or `file`.
    std::string generator = "hyper_cube";
    /// Arguments of the generator, as `GridGenerator::generate_from_name_and_arguments` reads them.
    std::string generator_arguments = "0: 1: true";
    /// Mesh file (Gmsh .msh, UCD .inp, VTK .vtk) used when generator = file; relative to the .prm.
    std::string file_name = "";
    /// Number of global refinements after the coarse mesh is built.
    unsigned int n_global_refinements = 3;
    /// Random shift of interior vertices, as a fraction of the shortest adjacent edge (0 = none).
    double distortion = 0.0;
    /// Distort the coarse mesh (then refine it: every mesh of a refinement sweep is a subdivision of
    /// the same distorted mesh) instead of the refined one (a new random mesh on every level).
    bool distort_coarse_mesh = false;
    /// Seed of the distortion's random numbers.
    unsigned int distortion_seed = 1;
    /// Names of boundary ids (patches), e.g. `0: left, 1: right`. Ids without a name are `patch_<id>`.
    std::map<unsigned int, std::string> patch_names;
    /// The .prm subsection these parameters live in (`Mesh`; an FSI scene's solid: `Solid mesh`).
    std::string section = "Mesh";

    /// Declare the parameters in subsection `section` (and remember it for messages).
    void declare(dealii::ParameterHandler& prm, const std::string& section = "Mesh");
    /// Name of the patch with boundary id `id`.
    std::string patch_name(unsigned int id) const;
    /// Boundary id of the patch called `name`, which `parameter` (e.g. `Fluid/Wall`) names;
    /// throws a message naming both if there is no such patch.
    unsigned int patch_id(const std::string& name, const std::string& parameter) const;
    /// The boundary ids of `names`, which `parameter` lists.
    std::vector<unsigned int> patch_ids(const std::vector<std::string>& names,
                                        const std::string& parameter) const;
  };
} // namespace fvfsi
