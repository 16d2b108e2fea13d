// The transient FSI run's time loop: one solve_time_step() (Algorithm 1) per step, a failed step
// tried again with half the time step (Time/Time step control) or the last converged state
// written before the run stops, the results counted, a progress line every Fluid scene/Progress
// interval steps, and the VTU output and checkpoints. run() and the rest of the scene are in
// fsi_scene.cc.
#include <fvfsi/io/progress.h>
#include <fvfsi/scenes/fsi_scene.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <iomanip>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  void FsiScene<dim>::run_transient()
  {
    unsigned int total = clock.last_step();
    Progress progress;
    if (result.n_coupled_steps > 0) // restarted in the coupled phase
      progress.new_phase(clock.step());
    unsigned int halvings = 0; // of the present time step
    while (!clock.at_end())
    {
      const unsigned int step = clock.step() + 1;
      capture_step_start();
      unsigned int iterations = 0;
      Timer step_timer;
      try
      {
        iterations = solve_time_step();
      }
      catch (const std::exception& e)
      {
        if (halve_time_step(step, halvings, e))
          continue;
        throw;
      }
      halvings = 0;
      count_time_step(step, iterations, step_timer.wall_time(), progress);
      // Adaptive steps (Time/Adaptive): the next one from this one's Courant number or error
      // estimate.
      clock.adapt_time_step(fluid->courant_number(), fluid->step_error());
      total = clock.last_step(); // the steps to the end time at the present dt
      if (step % fluid_scene_parameters.progress_interval == 0 || clock.at_end())
        print_progress(step, total, iterations, last_fluid_alone_step(total), progress);
      if (fluid_scene_parameters.output_interval > 0 &&
          step % fluid_scene_parameters.output_interval == 0)
        output_results();
      if (checkpoints.interval > 0 && step % checkpoints.interval == 0)
        write_checkpoint();
    }
    if (fluid_scene_parameters.output_interval == 0)
      output_results();
  }

  template <int dim>
  bool FsiScene<dim>::halve_time_step(const unsigned int step, unsigned int& halvings,
                                      const std::exception& failure)
  {
    // Back to the last converged state: tried again with half the time step, or written.
    const double dt = clock.time_step();
    return_to_step_start();
    if (halvings < max_halvings)
    {
      ++halvings;
      clock.set_time_step(dt / 2);
      pcout << "fvfsi: FSI time step " << step << " with dt = " << dt << " s failed ("
            << failure.what() << ")\nfvfsi: trying it again with dt = " << dt / 2
            << " s (Time/Time step control: halving " << halvings << " of " << max_halvings
            << ")\n";
      return true;
    }
    output_results();
    write_checkpoint();
    pcout << "fvfsi: FSI run stopped at time step " << step << "; written: the last converged "
          << "state (t = " << clock.time() << " s) as VTU and a checkpoint (continue with "
          << "Restart from = " << output_directory << "); fsi_history.txt holds every "
          << "converged time step\n";
    return false;
  }

  template <int dim>
  void FsiScene<dim>::count_time_step(const unsigned int step, const unsigned int iterations,
                                      const double wall_seconds, Progress& progress)
  {
    result.n_time_steps = step;
    if (iterations > 0)
      result.coupled_wall_seconds += wall_seconds;
    if (iterations > 0 && result.n_coupled_steps == 0)
      progress.new_phase(step); // coupled steps cost more: estimate from them alone
    result.n_coupled_steps += iterations > 0;
    result.total_coupling_iterations += iterations;
    result.max_coupling_iterations = std::max(result.max_coupling_iterations, iterations);
  }

  template <int dim>
  unsigned int FsiScene<dim>::last_fluid_alone_step(const unsigned int total) const
  {
    // The step that reaches Coupling/Start time at the present dt (adaptive steps change it).
    const double left = std::max(prm.coupling.start_time - clock.time(), 0.0);
    return std::min<unsigned int>(
      total, clock.step() + static_cast<unsigned int>(std::floor(left / clock.time_step() + 1e-9)));
  }

  template <int dim>
  void FsiScene<dim>::print_progress(const unsigned int step, const unsigned int total,
                                     const unsigned int iterations,
                                     const unsigned int last_fluid_alone_step,
                                     const Progress& progress) const
  {
    pcout << "fvfsi: FSI step " << step << "/" << total << ", t = " << clock.time() << " s, ";
    if (iterations > 0)
      pcout << iterations << " coupling iterations (mean " << std::setprecision(3)
            << result.mean_coupling_iterations() << "), " << progress.elapsed_and_left(step, total);
    else
      pcout << "fluid alone (before Coupling/Start time), "
            << progress.elapsed_and_until(step, last_fluid_alone_step) << " (coupled steps "
            << "cost more: the time left follows from them)";
    pcout << "\n" << std::setprecision(6);
  }

  // The members defined here (the class itself is instantiated in fsi_scene.cc).
  template void FsiScene<2>::run_transient();
  template bool FsiScene<2>::halve_time_step(unsigned int, unsigned int&, const std::exception&);
  template void FsiScene<2>::count_time_step(unsigned int, unsigned int, double, Progress&);
  template unsigned int FsiScene<2>::last_fluid_alone_step(unsigned int) const;
  template void FsiScene<2>::print_progress(unsigned int, unsigned int, unsigned int, unsigned int,
                                            const Progress&) const;
  template void FsiScene<3>::run_transient();
  template bool FsiScene<3>::halve_time_step(unsigned int, unsigned int&, const std::exception&);
  template void FsiScene<3>::count_time_step(unsigned int, unsigned int, double, Progress&);
  template unsigned int FsiScene<3>::last_fluid_alone_step(unsigned int) const;
  template void FsiScene<3>::print_progress(unsigned int, unsigned int, unsigned int, unsigned int,
                                            const Progress&) const;
} // namespace fvfsi
