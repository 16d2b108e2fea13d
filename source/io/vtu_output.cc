#include <deal.II/numerics/data_out.h>

#include <fvfsi/io/vtu_output.h>

#include <filesystem>
#include <fstream>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  VtuOutput<dim>::VtuOutput(const FVGeometry<dim>& geometry, const std::string& directory,
                            const std::string& base_name)
      : geometry(geometry), directory(directory), base_name(base_name)
  {
  }

  template <int dim>
  void VtuOutput<dim>::write(const OutputFields<dim>& fields, const unsigned int step,
                             const double time)
  {
    DataOut<dim> data_out;
    data_out.attach_dof_handler(geometry.dof_handler());
    for (const auto& [name, vector] : fields.fields)
      data_out.add_data_vector(vector, name, DataOut<dim>::type_dof_data);
    Vector<float> subdomain(geometry.triangulation().n_active_cells());
    subdomain = Utilities::MPI::this_mpi_process(geometry.comm());
    data_out.add_data_vector(subdomain, "rank", DataOut<dim>::type_cell_data);
    data_out.build_patches();
    // zlib's fastest level: the default (best compression) took about a tenth of a steady solid
    // run (plate with a hole, 64 082 cells) for a file 17 % smaller (3.6 instead of 4.3 MB).
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    const std::string pvtu =
      data_out.write_vtu_with_pvtu_record(directory + "/", base_name, step, geometry.comm(), 4);
    records.emplace_back(time, pvtu);
    if (Utilities::MPI::this_mpi_process(geometry.comm()) == 0)
    {
      std::ofstream pvd(directory + "/" + base_name + ".pvd");
      DataOutBase::write_pvd_record(pvd, records);
    }
  }

  template <int dim>
  void VtuOutput<dim>::continue_from(const std::vector<std::pair<double, std::string>>& earlier,
                                     const std::string& earlier_directory)
  {
    records.clear();
    for (const auto& [time, file] : earlier)
      records.emplace_back(
        time, std::filesystem::absolute(earlier_directory + "/" + file)
                .lexically_normal()
                .lexically_relative(std::filesystem::absolute(directory).lexically_normal())
                .string());
  }

  template class VtuOutput<2>;
  template class VtuOutput<3>;
} // namespace fvfsi
