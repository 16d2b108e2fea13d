#pragma once
// Boundary conditions: of a cell-centred scalar field, per patch (boundary id), with one value per
// boundary face (ScalarBoundaryConditions); and a solver's conditions as a .prm file gives them,
// a type and an expression per patch, looked up per boundary face (FaceConditions).

#include <deal.II/base/function_parser.h>

#include <fvfsi/base/parsed_function.h>
#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_parameters.h>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace fvfsi
{
  enum class BoundaryType
  {
    dirichlet, ///< phi_b given (Eq. 23)
    neumann    ///< n . grad phi given, n pointing out of the domain
  };

  template <int dim>
  struct ScalarBoundaryConditions
  {
    /// Type of every boundary patch of the mesh.
    std::map<unsigned int, BoundaryType> patch_type;
    /// Per face (indexed like FVGeometry::faces): phi_b on Dirichlet faces, n . grad phi on
    /// Neumann faces; unused on interior faces.
    FaceVector value;

    BoundaryType type(const FaceGeometry<dim>& face) const
    {
      const auto it = patch_type.find(face.patch);
      if (it == patch_type.end())
        throw std::runtime_error("no boundary condition for patch id " +
                                 std::to_string(face.patch));
      return it->second;
    }
  };

  /**
   * A solver's boundary conditions per boundary face (boundary and ghost_boundary faces): the type
   * of the face's patch and its expression, parsed once. `Condition` has members `patch`, `type`
   * and `expression` (the patch list of a .prm entry, e.g. FluidBoundaryCondition).
   */
  template <int dim, typename Type>
  class FaceConditions
  {
  public:
    FaceConditions() = default;

    /// `n_components(type)`: components of a type's expression. `solver` ("Fluid", "Solid")
    /// and `hint` (what to add) make the message of a patch without a condition.
    template <typename Condition, typename ComponentCount>
    FaceConditions(const FVGeometry<dim>& geometry, const MeshParameters& mesh,
                   const std::vector<Condition>& conditions, const ComponentCount& n_components,
                   const std::string& solver, const std::string& hint)
        : face(geometry.faces.size())
    {
      std::map<unsigned int, Entry> by_patch;
      for (const auto& c : conditions)
      {
        Entry entry{c.type, -1};
        if (!c.expression.empty())
        {
          functions.push_back(std::make_unique<dealii::FunctionParser<dim>>(n_components(c.type)));
          names.push_back(c.parameter + " on patch `" + c.patch + "`");
          initialize_function(*functions.back(), c.expression, names.back());
          entry.function = functions.size() - 1;
        }
        by_patch[mesh.patch_id(c.patch, c.parameter)] = entry;
      }
      for (unsigned int f = 0; f < geometry.faces.size(); ++f)
        if (geometry.faces[f].N == invalid_cell)
        {
          const auto it = by_patch.find(geometry.faces[f].patch);
          if (it == by_patch.end())
            throw std::runtime_error(
              solver + ": patch `" + mesh.patch_name(geometry.faces[f].patch) +
              "` has no boundary condition (" + hint + "; the patches are named by " +
              mesh.section + "/Patch names)");
          face[f] = it->second;
        }
    }

    /// The type of boundary face f.
    Type type(const unsigned int f) const { return face[f].type; }
    /// The expression of boundary face f's patch (throws if it has none).
    const dealii::FunctionParser<dim>& function(const unsigned int f) const
    {
      if (face[f].function < 0)
        throw std::logic_error("FaceConditions: a boundary condition without an expression");
      return *functions[face[f].function];
    }
    /// Component `component` of boundary face f's expression at `point`; a value that is not
    /// finite or too large (checked_value) stops the run with the .prm entry and patch named.
    double value(const unsigned int f, const dealii::Point<dim>& point,
                 const unsigned int component = 0) const
    {
      return checked_value(function(f), point, component, names[face[f].function]);
    }

    /// Evaluate the expressions at time t [s] from now on.
    void set_time(const double t)
    {
      for (auto& fn : functions)
        fn->set_time(t);
    }

  private:
    struct Entry
    {
      Type type{};
      int function = -1; ///< index into `functions`, -1 for none
    };
    std::vector<Entry> face;
    std::vector<std::unique_ptr<dealii::FunctionParser<dim>>> functions;
    std::vector<std::string> names; ///< per function: "Fluid/Velocity inlet on patch `inlet`"
  };
} // namespace fvfsi
