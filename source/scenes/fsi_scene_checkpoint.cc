// The FSI scene's checkpoints and the start of each time step kept in memory (io/checkpoint.h):
// what is saved, in which order, and how the scene returns to it. The rest of the scene is in
// fsi_scene.cc.
#include <fvfsi/scenes/fsi_scene.h>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  template <class Archive>
  void FsiScene<dim>::global_state(Archive& archive)
  {
    archive& clock;
    coupling->checkpoint(archive);
    archive& result& volume_ratio;
    bool has_force = last_force.has_value();
    Tensor<1, dim> force = last_force.value_or(Tensor<1, dim>());
    archive& has_force& force;
    if (has_force)
      last_force = force;
  }

  template <int dim>
  void FsiScene<dim>::write_checkpoint()
  {
    TimerOutput::Scope scope(timer, "checkpoint");
    const CheckpointFiles files(output_directory);
    files.begin_writing(comm);
    // The same calls in the same order as restore_checkpoint()'s.
    save_mesh<dim>(files, "fluid_mesh", *fluid_fv, fluid_reference_fv->vertices(),
                   [this](MeshArchive<dim>& archive) { fluid_state(archive); });
    save_mesh<dim>(files, "solid_mesh", *solid_fv, solid_fv->vertices(),
                   [this](MeshArchive<dim>& archive) { solid->checkpoint(archive); });
    {
      GlobalArchive global(files.path("state", true), false, comm);
      global_state(global);
    }
    save_output_state(
      files, {history->length(), {fluid_output->written(), solid_output->written()}}, comm);
    files.finish_writing(comm);
    pcout << "fvfsi: checkpoint at " << clock.step_name() << " in " << files.directory << "\n";
  }

  template <int dim>
  void FsiScene<dim>::fluid_state(MeshArchive<dim>& archive)
  {
    fluid->checkpoint(archive);
    motion->checkpoint(archive);
  }

  template <int dim>
  void FsiScene<dim>::capture_step_start()
  {
    TimerOutput::Scope scope(timer, "step start copy");
    capture_mesh<dim>(step_start_fluid, *fluid_fv, fluid_reference_fv->vertices(),
                      [this](MeshArchive<dim>& a) { fluid_state(a); });
    capture_mesh<dim>(step_start_solid, *solid_fv, solid_fv->vertices(),
                      [this](MeshArchive<dim>& a) { solid->checkpoint(a); });
    GlobalArchive global(step_start_global, false);
    global_state(global);
  }

  template <int dim>
  void FsiScene<dim>::return_to_step_start()
  {
    // The fluid mesh back to where the step started (geometry, triangulation, the fluid's
    // operators), then the states as captured.
    const std::vector<Point<dim>> x = rewind_mesh(*step_start_fluid, *fluid_fv),
                                  now = fluid_fv->vertices();
    move_mesh(*fluid_fv, fluid_tria, now, x);
    fluid->move_mesh(std::vector<double>(fluid_fv->faces.size(), 0.0));
    fluid_state(*step_start_fluid);
    rewind_mesh(*step_start_solid, *solid_fv);
    solid->checkpoint(*step_start_solid);
    GlobalArchive global(step_start_global, true);
    global_state(global);
  }

  template <int dim>
  void FsiScene<dim>::restore_checkpoint()
  {
    // The fluid mesh moves from its reference positions to the saved ones (its geometry, the
    // triangulation, and the fluid's operators with it), then every state is read in the order
    // write_checkpoint() wrote it.
    const CheckpointFiles files(checkpoints.restart_from);
    const std::vector<Point<dim>> reference = fluid_fv->vertices();
    move_mesh(*fluid_fv, fluid_tria, reference, restart_vertices);
    fluid->move_mesh(std::vector<double>(fluid_fv->faces.size(), 0.0));
    fluid_restart->set_geometry(*fluid_fv);
    fluid_state(*fluid_restart);
    solid_restart->set_geometry(*solid_fv);
    solid->checkpoint(*solid_restart);
    fluid_restart.reset();
    solid_restart.reset();
    GlobalArchive global(files.path("state"), true, comm);
    global_state(global);
    pcout << "fvfsi: FSI restarted from " << files.directory << " at " << clock.step_name() << "\n";
  }

  // The members defined here (the class itself is instantiated in fsi_scene.cc).
  template void FsiScene<2>::write_checkpoint();
  template void FsiScene<2>::fluid_state(MeshArchive<2>&);
  template void FsiScene<2>::capture_step_start();
  template void FsiScene<2>::return_to_step_start();
  template void FsiScene<2>::restore_checkpoint();
  template void FsiScene<3>::write_checkpoint();
  template void FsiScene<3>::fluid_state(MeshArchive<3>&);
  template void FsiScene<3>::capture_step_start();
  template void FsiScene<3>::return_to_step_start();
  template void FsiScene<3>::restore_checkpoint();
} // namespace fvfsi
