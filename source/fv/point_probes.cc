#include <deal.II/base/utilities.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>

#include <fvfsi/base/patch_list.h>
#include <fvfsi/fv/point_probes.h>

#include <sstream>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  PointProbes<dim>::PointProbes(const std::string& list, const std::string& parameter)
      : parameter(parameter)
  {
    for (const auto& [name, value] : parse_named_values(list, parameter))
    {
      const auto coordinates = Utilities::split_string_list(value, ',');
      if (coordinates.size() != dim)
        throw std::runtime_error(parameter + ": `" + name + ": " + value + "` is not `name: x, y" +
                                 (dim == 3 ? ", z`" : "`"));
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        try
        {
          p[d] = Utilities::string_to_double(coordinates[d]);
        }
        catch (...)
        {
          throw std::runtime_error(parameter + ": `" + coordinates[d] + "` in `" + name + ": " +
                                   value + "` is not a number");
        }
      names.push_back(name);
      points.push_back(p);
    }
  }

  template <int dim>
  void PointProbes<dim>::locate(const FVGeometry<dim>& geometry)
  {
    this->geometry = &geometry;
    cell.assign(points.size(), numbers::invalid_unsigned_int);
    n_found.assign(points.size(), 0);
    for (unsigned int i = 0; i < points.size(); ++i)
    {
      try
      {
        // A tolerance, so that points on the boundary count as inside.
        const auto found = GridTools::find_active_cell_around_point(
          StaticMappingQ1<dim>::mapping, geometry.triangulation(), points[i], std::vector<bool>(),
          1e-10);
        if (found.first.state() == IteratorState::valid && found.first->is_locally_owned())
        {
          const typename DoFHandler<dim>::active_cell_iterator dof_cell(
            &geometry.triangulation(), found.first->level(), found.first->index(),
            &geometry.dof_handler());
          cell[i] = geometry.partitioner()->global_to_local(dof_cell->dof_index(0));
        }
      }
      catch (const std::exception&)
      {
        // the point is not in this rank's part of the mesh
      }
      n_found[i] =
        Utilities::MPI::sum(cell[i] != numbers::invalid_unsigned_int ? 1. : 0., geometry.comm());
      if (n_found[i] == 0)
      {
        std::ostringstream where;
        for (unsigned int d = 0; d < dim; ++d)
          where << (d > 0 ? ", " : "") << points[i][d];
        throw std::runtime_error(parameter + ": probe `" + names[i] + "` at (" + where.str() +
                                 ") lies outside the mesh");
      }
    }
  }

  template class PointProbes<2>;
  template class PointProbes<3>;
} // namespace fvfsi
