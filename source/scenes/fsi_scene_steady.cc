// The steady FSI path of the scene: its run, its solve, its history line per coupling iteration,
// and its state files (io/point_values.h), written at the end of a steady run and read by a run on
// another mesh as its start (`Initial state from`, mesh sequencing). The rest of the scene is in
// fsi_scene.cc.
#include <fvfsi/io/point_values.h>
#include <fvfsi/scenes/fsi_scene.h>

#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  namespace
  {
    /// The fluid state's columns: ux uy [uz] p (kinematic pressure p / rho [m^2/s^2]).
    template <int dim>
    std::vector<std::string> fluid_columns()
    {
      auto columns = vector_columns<dim>("u", "");
      columns.push_back("p");
      return columns;
    }

    template <int dim>
    Tensor<1, dim> first_components(const std::vector<double>& values)
    {
      Tensor<1, dim> t;
      for (unsigned int d = 0; d < dim; ++d)
        t[d] = values[d];
      return t;
    }
  } // namespace

  template <int dim>
  void FsiScene<dim>::run_steady()
  {
    if (checkpoints.interval > 0 || !checkpoints.restart_from.empty())
      throw std::runtime_error("FSI: Checkpoint interval and Restart from apply to transient "
                               "runs; a steady run (Fluid/Transient = false) has no time steps");
    if (!checkpoints.initial_state_from.empty())
      start_from_state(checkpoints.initial_state_from);
    result.total_coupling_iterations = result.max_coupling_iterations = solve_steady();
    pcout << "fvfsi: FSI steady state after " << result.total_coupling_iterations
          << " coupling iterations, " << fluid->pseudo_steps() << " fluid pseudo steps, "
          << result.solid_outer_iterations << " solid outer iterations\n";
    output_results();
    write_state();
  }

  template <int dim>
  unsigned int FsiScene<dim>::solve_steady()
  {
    // Algorithm 1 without time: one "step" whose coupling iterations converge the steady coupled
    // state. Each iteration moves the mesh, converges the steady fluid on it (pseudo time steps,
    // warm-started from the last iteration's flow) and the static solid under its tractions
    // (warm-started from the last displacement); no predictor, d starts from the reference (or
    // from an earlier run's state, start_from_state()).
    fluid->begin_time_step();
    solid->begin_time_step();
    vertices_old = fluid_fv->vertices();
    const unsigned int k = converge_interface();
    fluid->end_time_step();
    solid->end_time_step();
    return k;
  }

  template <int dim>
  void FsiScene<dim>::record_steady_iteration(const unsigned int k, const double residual)
  {
    const Tensor<1, dim> force = fluid_force();
    std::vector<double> line = {
      double(k), residual, double(fluid->pseudo_steps()), double(result.solid_outer_iterations),
      force[0],  force[1]};
    for (unsigned int i = 0; i < probes.size(); ++i)
      append(line, solid_probe(i));
    line.push_back(volume_ratio);
    history->write_line(line);
    last_force = force;
    pcout << "fvfsi: FSI steady coupling iteration " << k << ": relative interface residual "
          << residual << " (tolerance " << prm.coupling.tolerance << "), fluid pseudo steps "
          << fluid->pseudo_steps() << ", solid outer iterations " << result.solid_outer_iterations
          << "\n";
  }

  template <int dim>
  void FsiScene<dim>::write_state() const
  {
    // fluid_state.txt: u and p at the reference cell centres (the mesh before its motion, the
    // positions a run on another mesh can find them at); interface_state.txt: d at the fluid
    // interface points (reference positions).
    std::vector<Point<dim>> centres;
    std::vector<std::vector<double>> rows;
    for (unsigned int c = 0; c < fluid_fv->n_owned_cells(); ++c)
    {
      centres.push_back(fluid_reference_fv->centroid[c]);
      std::vector<double> row;
      for (unsigned int j = 0; j < dim; ++j)
        row.push_back(fluid->velocity().components[j].local_element(c));
      row.push_back(fluid->kinematic_pressure().local_element(c));
      rows.push_back(row);
    }
    write_point_values<dim>(output_directory + "/fluid_state.txt", fluid_columns<dim>(), centres,
                            rows, comm);
    rows.clear();
    if (Utilities::MPI::this_mpi_process(comm) == 0) // d is whole on every rank
      for (unsigned int i = 0; i < interface->fluid_side().n_points(); ++i)
        rows.emplace_back(coupling->displacement().begin() + i * dim,
                          coupling->displacement().begin() + (i + 1) * dim);
    write_point_values<dim>(
      output_directory + "/interface_state.txt", vector_columns<dim>("d", ""),
      rows.empty() ? std::vector<Point<dim>>() : interface->fluid_side().points, rows, comm);
  }

  template <int dim>
  void FsiScene<dim>::start_from_state(const std::string& directory)
  {
    // The fluid's u and p and the interface displacement d, each from the nearest samples of the
    // earlier run at the reference positions (the fluid mesh is at its reference positions now;
    // the first coupling iteration moves it to d). The solid starts from rest: its static solve
    // is cheap beside the fluid's, and it meets the transferred tractions in the first iteration.
    const std::string parameter = "Initial state from";
    const PointValues<dim> fluid_state(directory + "/fluid_state.txt", fluid_columns<dim>(),
                                       parameter);
    fluid->set_state([&fluid_state](const Point<dim>& x)
                     { return first_components<dim>(fluid_state.value(x)); },
                     [&fluid_state](const Point<dim>& x) { return fluid_state.value(x)[dim]; });
    const PointValues<dim> interface_state(directory + "/interface_state.txt",
                                           vector_columns<dim>("d", ""), parameter);
    InterfaceVector d = coupling->displacement();
    for (unsigned int i = 0; i < interface->fluid_side().n_points(); ++i)
    {
      const auto value = interface_state.value(interface->fluid_side().points[i]);
      for (unsigned int j = 0; j < dim; ++j)
        d[i * dim + j] = value[j];
    }
    coupling->set_displacement(d);
    pcout << "fvfsi: starting from the state of " << directory << " (" << fluid_state.size()
          << " fluid cells, " << interface_state.size() << " interface points)\n";
  }

  // The members defined here (the class itself is instantiated in fsi_scene.cc).
  template void FsiScene<2>::run_steady();
  template unsigned int FsiScene<2>::solve_steady();
  template void FsiScene<2>::record_steady_iteration(unsigned int, double);
  template void FsiScene<2>::write_state() const;
  template void FsiScene<2>::start_from_state(const std::string&);
  template void FsiScene<3>::run_steady();
  template unsigned int FsiScene<3>::solve_steady();
  template void FsiScene<3>::record_steady_iteration(unsigned int, double);
  template void FsiScene<3>::write_state() const;
  template void FsiScene<3>::start_from_state(const std::string&);
} // namespace fvfsi
