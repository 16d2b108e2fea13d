#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <fvfsi/base/parsed_function.h>
#include <fvfsi/base/selection.h>
#include <fvfsi/fv/deferred_correction.h>
#include <fvfsi/fv/face_loop.h>
#include <fvfsi/mesh/mesh_builder.h>
#include <fvfsi/scenes/poisson.h>

#include <cmath>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  void PoissonParameters::declare(ParameterHandler& prm)
  {
    prm.enter_subsection("Poisson");
    prm.add_parameter("Diffusivity", diffusivity, "Gamma in -div(Gamma grad phi) = s [m^2/s].",
                      Patterns::Double(0));
    prm.add_parameter(
      "Exact solution", exact_solution,
      "phi(x, y[, z]) (FunctionParser syntax, constant pi): the Dirichlet values and "
      "the reference of the error norms.");
    prm.add_parameter("Exact gradient", exact_gradient,
                      "grad phi, dim expressions separated by `;`: the Neumann values and the "
                      "reference of the face-gradient error.");
    prm.add_parameter("Source", source, "s(x, y[, z]) = -div(Gamma grad phi).");
    prm.add_parameter("Neumann patches", neumann_patches,
                      "Patches (Mesh/Patch names) with the normal gradient of the exact solution "
                      "prescribed; all other patches are Dirichlet.");
    add_selection(prm, "Face gradient", face_gradient,
                  {{"linear", FaceGradient::linear}, {"quadratic", FaceGradient::quadratic}},
                  "Face normal gradient of the Laplacian: `linear` is Eq. 19 with vertex-based "
                  "Gauss-Green cell gradients (exact for linear fields; its max error falls only "
                  "as O(h) on faces between unlike cells of a distorted mesh); `quadratic` adds "
                  "the Hessian terms and uses the gradient and Hessian of a quadratic "
                  "least-squares fit over the vertex-neighbour cells (exact for quadratic "
                  "fields: its max error is second order on distorted meshes too; costs "
                  "0.4 kB (2D) or 2 kB (3D) more memory per cell).");
    prm.add_parameter("Max correction iterations", max_correction_iterations,
                      "Limit of the deferred non-orthogonal correction iterations.",
                      Patterns::Integer(1));
    prm.add_parameter(
      "Correction tolerance", correction_tolerance,
      "Stop the correction iterations when max |phi change| / max |phi| is below this.",
      Patterns::Double(0));
    prm.leave_subsection();
    solver.declare(prm, "Poisson linear solver");
  }

  template <int dim>
  PoissonProblem<dim>::PoissonProblem(const MeshParameters& mesh_parameters,
                                      const PoissonParameters& parameters, MPI_Comm comm,
                                      const std::string& prm_directory)
      : comm(comm), mesh_parameters(mesh_parameters), parameters(parameters),
        prm_directory(prm_directory), pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0),
        triangulation(comm), exact(1), exact_gradient(dim), source(1)
  {
    initialize_function(exact, parameters.exact_solution, "Poisson/Exact solution");
    initialize_function(exact_gradient, parameters.exact_gradient, "Poisson/Exact gradient");
    initialize_function(source, parameters.source, "Poisson/Source");
  }

  template <int dim>
  void PoissonProblem<dim>::make_grid()
  {
    make_mesh(mesh_parameters, triangulation, prm_directory);
    fv = std::make_unique<FVGeometry<dim>>(triangulation);
    if (parameters.face_gradient == PoissonParameters::FaceGradient::quadratic)
    {
      // The fit over the vertex neighbours and the boundary faces that touch the cell, with the
      // weights (L / |s|)^6 (see quadratic_fit.h).
      QuadraticFitData data;
      data.weight_exponent = 6;
      data.value_faces.assign(fv->faces.size(), false);
      for (const unsigned int f : fv->all_boundary_faces())
        data.value_faces[f] = true;
      quadratic_fit = std::make_unique<QuadraticFit<dim>>(*fv, data);
    }
    else
    {
      vertex_interpolation = std::make_unique<VertexInterpolation<dim>>(*fv);
      gauss_green = std::make_unique<GaussGreenGradient<dim>>(*fv);
    }
    laplacian = std::make_unique<Laplacian<dim>>(*fv);
  }

  template <int dim>
  void PoissonProblem<dim>::setup_system()
  {
    // Boundary conditions: Neumann on the listed patches, Dirichlet elsewhere; values per face.
    for (const auto id : triangulation.get_boundary_ids())
      bc.patch_type[id] = BoundaryType::dirichlet;
    for (const auto& name : parameters.neumann_patches)
      bc.patch_type[mesh_parameters.patch_id(name, "Poisson/Neumann patches")] =
        BoundaryType::neumann;
    bc.value.assign(fv->faces.size(), 0.0);
    for_each_stored_boundary_face(
      *fv,
      [this](const unsigned int f, const FaceGeometry<dim>& face)
      {
        if (bc.type(face) == BoundaryType::dirichlet)
          bc.value[f] = checked_value(exact, face.centre, 0, "Poisson/Exact solution");
        else
        {
          Tensor<1, dim> g;
          for (unsigned int d = 0; d < dim; ++d)
            g[d] = checked_value(exact_gradient, face.centre, d, "Poisson/Exact gradient");
          bc.value[f] = face.n * g;
        }
      });
    gamma.assign(fv->faces.size(), parameters.diffusivity);
    phi = fv->make_cell_vector();
    rhs_fixed = fv->make_cell_vector();
    grad = CellGradient<dim>(*fv);
    if (quadratic_fit)
      hessian = CellHessian<dim>(*fv);
    laplacian->reinit_matrix(matrix);
  }

  template <int dim>
  void PoissonProblem<dim>::assemble_system()
  {
    // The midpoint rule: s_P V_P.
    for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
      rhs_fixed.local_element(c) =
        checked_value(source, fv->centroid[c], 0, "Poisson/Source") * fv->cell_volume[c];
    laplacian->assemble(gamma, bc, matrix, rhs_fixed);
    matrix.compress(VectorOperation::add);
  }

  template <int dim>
  void PoissonProblem<dim>::solve()
  {
    LinearSolver solver(parameters.solver);
    solver.initialize(matrix);
    DeferredCorrection control;
    control.max_iterations = parameters.max_correction_iterations;
    control.tolerance = parameters.correction_tolerance;
    const auto r = solve_deferred_correction(
      control, solver, matrix, rhs_fixed, phi,
      [this](CellVector& rhs)
      { laplacian->add_correction(gamma, bc, grad, rhs, hessian_or_null()); },
      [this]() { update_gradients(); }, "Poisson phi");
    result.correction_iterations = r.iterations;
    result.linear_iterations = r.linear_iterations;
    if (!r.converged)
      pcout << "fvfsi: warning: Poisson correction iterations did not reach the tolerance "
            << parameters.correction_tolerance << " in " << parameters.max_correction_iterations
            << " iterations\n";
  }

  template <int dim>
  void PoissonProblem<dim>::update_gradients()
  {
    // Boundary values (those of Neumann faces from the current grad and hessian), then the
    // gradient (and Hessian) of the new phi: of the quadratic fit through the cell and boundary
    // values, or by vertex values (App. B) and Gauss-Green (Eq. 37).
    const FaceVector boundary_values = laplacian->boundary_values(phi, grad, bc, hessian_or_null());
    if (quadratic_fit)
    {
      quadratic_fit->compute(phi, boundary_values, FaceVector(), grad, hessian);
      return;
    }
    vertex_interpolation->interpolate(phi, boundary_values, vertex_phi);
    gauss_green->compute(vertex_phi, grad);
  }

  template <int dim>
  void PoissonProblem<dim>::compute_errors()
  {
    double max_error = 0, l2 = 0, l2_gradient = 0, max_boundary_gradient_error = 0,
           max_gradient_error = 0, volume = 0;
    for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
    {
      const double e = phi.local_element(c) - exact.value(fv->centroid[c]);
      max_error = std::max(max_error, std::abs(e));
      l2 += e * e * fv->cell_volume[c];
      volume += fv->cell_volume[c];
    }
    for_each_face(*fv,
                  [&](const unsigned int f, const FaceGeometry<dim>& face)
                  {
                    Tensor<1, dim> g;
                    for (unsigned int d = 0; d < dim; ++d)
                      g[d] = exact_gradient.value(face.centre, d);
                    const double e =
                      laplacian->normal_gradient(f, phi, grad, bc, hessian_or_null()) - face.n * g;
                    double& max =
                      face.N != invalid_cell ? max_gradient_error : max_boundary_gradient_error;
                    max = std::max(max, std::abs(e));
                    if (face.N != invalid_cell && face.counted_here) // the face's share of volume
                      l2_gradient += e * e * face.area * face.d_n;
                  });
    result.n_cells = fv->n_global_cells();
    result.h = std::pow(Utilities::MPI::sum(volume, comm) / result.n_cells, 1.0 / dim);
    result.max_cell_error = Utilities::MPI::max(max_error, comm);
    result.l2_cell_error = std::sqrt(Utilities::MPI::sum(l2, comm));
    result.max_face_gradient_error = Utilities::MPI::max(max_gradient_error, comm);
    result.l2_face_gradient_error = std::sqrt(Utilities::MPI::sum(l2_gradient, comm));
    result.max_boundary_face_gradient_error =
      Utilities::MPI::max(max_boundary_gradient_error, comm);
  }

  template <int dim>
  void PoissonProblem<dim>::run()
  {
    make_grid();
    setup_system();
    assemble_system();
    solve();
    compute_errors();
    pcout << "fvfsi: Poisson " << dim << "D, " << result.n_cells << " cells: max error "
          << result.max_cell_error << ", face-gradient error " << result.max_face_gradient_error
          << ", " << result.correction_iterations << " correction iterations, "
          << result.linear_iterations << " linear iterations\n";
  }

  template <int dim>
  void PoissonProblem<dim>::output_results(const std::string& directory, Summary& summary) const
  {
    OutputFields<dim> fields(*fv);
    fields.add("phi", [&](const unsigned int c) { return phi.local_element(c); });
    fields.add("phi_exact", [&](const unsigned int c) { return exact.value(fv->centroid[c]); });
    fields.add("error", [&](const unsigned int c)
               { return phi.local_element(c) - exact.value(fv->centroid[c]); });
    VtuOutput<dim>(*fv, directory, "poisson").write(fields, 0, 0.0);
    summary.set_result("max_cell_error", result.max_cell_error);
    summary.set_result("l2_cell_error", result.l2_cell_error);
    summary.set_result("max_face_gradient_error", result.max_face_gradient_error);
    summary.set_result("l2_face_gradient_error", result.l2_face_gradient_error);
    summary.set_result("max_boundary_face_gradient_error", result.max_boundary_face_gradient_error);
    summary.set_result("h", result.h);
    summary.set_result("correction_iterations", result.correction_iterations);
    summary.set_result("linear_iterations", result.linear_iterations);
  }

  template class PoissonProblem<2>;
  template class PoissonProblem<3>;
} // namespace fvfsi
