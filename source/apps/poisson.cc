#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <fvfsi/apps/poisson.h>
#include <fvfsi/base/exceptions.h>
#include <fvfsi/io/vtu_output.h>
#include <fvfsi/mesh/mesh_builder.h>

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
    prm.add_parameter("Exact solution", exact_solution,
                      "phi(x, y[, z]) (FunctionParser syntax, constant pi): the Dirichlet values and "
                      "the reference of the error norms.");
    prm.add_parameter("Exact gradient", exact_gradient,
                      "grad phi, dim expressions separated by `;`: the Neumann values and the "
                      "reference of the face-gradient error.");
    prm.add_parameter("Source", source, "s(x, y[, z]) = -div(Gamma grad phi).");
    prm.add_parameter("Neumann patches", neumann_patches,
                      "Patches (Mesh/Patch names) with the normal gradient of the exact solution "
                      "prescribed; all other patches are Dirichlet.");
    prm.add_parameter("Face gradient", face_gradient,
                      "Face normal gradient of the Laplacian: `linear` is Eq. 19 with vertex-based "
                      "Gauss-Green cell gradients (exact for linear fields; its max error falls only "
                      "as O(h) on faces between unlike cells of a distorted mesh); `quadratic` adds "
                      "the Hessian terms and uses the gradient and Hessian of a quadratic "
                      "least-squares fit over the vertex-neighbour cells (exact for quadratic "
                      "fields: its max error is second order on distorted meshes too; costs "
                      "0.4 kB (2D) or 2 kB (3D) more memory per cell).",
                      Patterns::Selection("linear|quadratic"));
    prm.add_parameter("Max correction iterations", max_correction_iterations,
                      "Limit of the deferred non-orthogonal correction iterations.",
                      Patterns::Integer(1));
    prm.add_parameter("Correction tolerance", correction_tolerance,
                      "Stop the correction iterations when max |phi change| / max |phi| is below this.",
                      Patterns::Double(0));
    prm.leave_subsection();
    solver.declare(prm, "Poisson linear solver");
  }

  template <int dim>
  void initialize_function(FunctionParser<dim>& f, const std::string& expression,
                           const std::string& parameter_name)
  {
    try
    {
      f.initialize(dim == 2 ? "x,y,t" : "x,y,z,t", expression, {{"pi", numbers::PI}}, true);
      // muparser parses on first use: evaluate once so that a syntax error shows up here.
      for (unsigned int c = 0; c < f.n_components; ++c)
        f.value(Point<dim>(), c);
    }
    catch (const std::exception& e)
    {
      throw std::runtime_error(parameter_name + " = `" + expression + "` is not a valid expression " +
                               "of " + (dim == 2 ? "x, y, t" : "x, y, z, t") + ": " + concise_message(e));
    }
  }

  template <int dim>
  PoissonProblem<dim>::PoissonProblem(const MeshParameters& mesh_parameters,
                                      const PoissonParameters& parameters, MPI_Comm comm,
                                      const std::string& prm_directory)
    : comm(comm)
    , mesh_parameters(mesh_parameters)
    , parameters(parameters)
    , prm_directory(prm_directory)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , triangulation(comm)
    , exact(1)
    , exact_gradient(dim)
    , source(1)
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
    const FaceGradient face_gradient = face_gradient_from_string(parameters.face_gradient);
    if (face_gradient == FaceGradient::quadratic)
      quadratic_reconstruction = std::make_unique<QuadraticReconstruction<dim>>(*fv);
    else
      vertex_interpolation = std::make_unique<VertexInterpolation<dim>>(*fv);
    laplacian = std::make_unique<Laplacian<dim>>(*fv, face_gradient);
  }

  template <int dim>
  void PoissonProblem<dim>::setup_system()
  {
    // Boundary conditions: Neumann on the listed patches, Dirichlet elsewhere; values per face.
    for (const auto id : triangulation.get_boundary_ids())
      bc.patch_type[id] = BoundaryType::dirichlet;
    for (const auto& name : parameters.neumann_patches)
      bc.patch_type[mesh_parameters.patch_id(name)] = BoundaryType::neumann;
    bc.value.assign(fv->faces.size(), 0.0);
    for (unsigned int f = 0; f < fv->faces.size(); ++f)
    {
      const auto& face = fv->faces[f];
      if (face.N != invalid_cell)
        continue;
      if (bc.type(face) == BoundaryType::dirichlet)
        bc.value[f] = exact.value(face.centre);
      else
      {
        Tensor<1, dim> g;
        for (unsigned int d = 0; d < dim; ++d)
          g[d] = exact_gradient.value(face.centre, d);
        bc.value[f] = face.n * g;
      }
    }
    gamma.assign(fv->faces.size(), parameters.diffusivity);
    phi = fv->make_cell_vector();
    rhs_fixed = fv->make_cell_vector();
    grad = CellGradient<dim>(*fv);
    if (quadratic_reconstruction)
      hessian = CellHessian<dim>(*fv);
    laplacian->reinit_matrix(matrix);
  }

  template <int dim>
  void PoissonProblem<dim>::assemble_system()
  {
    // The midpoint rule: s_P V_P.
    for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
      rhs_fixed.local_element(c) = source.value(fv->centroid[c]) * fv->cell_volume[c];
    laplacian->assemble(gamma, bc, matrix, rhs_fixed);
    matrix.compress(VectorOperation::add);
  }

  template <int dim>
  void PoissonProblem<dim>::solve()
  {
    LinearSolver solver(parameters.solver);
    solver.initialize(matrix);
    CellVector rhs = fv->make_cell_vector(), phi_old = fv->make_cell_vector();
    result.linear_iterations = 0;
    for (unsigned int k = 1; k <= parameters.max_correction_iterations; ++k)
    {
      // Right-hand side with the explicit correction from the current gradient, then solve.
      rhs = rhs_fixed;
      add_correction(rhs);
      phi_old = phi;
      result.linear_iterations += solver.solve(matrix, phi, rhs, "Poisson phi");
      update_gradients();

      double max_change = 0, max_phi = 0;
      for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
      {
        max_change = std::max(max_change, std::abs(phi.local_element(c) - phi_old.local_element(c)));
        max_phi = std::max(max_phi, std::abs(phi.local_element(c)));
      }
      const double change =
        Utilities::MPI::max(max_change, comm) / std::max(Utilities::MPI::max(max_phi, comm), 1e-300);
      if (!std::isfinite(change))
        throw std::runtime_error("Poisson: phi is not finite after correction iteration " +
                                 std::to_string(k));
      result.correction_iterations = k;
      if (change < parameters.correction_tolerance)
        return;
    }
    pcout << "fvfsi: warning: Poisson correction iterations did not reach the tolerance "
          << parameters.correction_tolerance << " in " << parameters.max_correction_iterations
          << " iterations\n";
  }

  template <int dim>
  void PoissonProblem<dim>::add_correction(CellVector& rhs) const
  {
    if (quadratic_reconstruction)
      laplacian->add_correction(gamma, bc, grad, hessian, rhs);
    else
      laplacian->add_correction(gamma, bc, grad, rhs);
  }

  template <int dim>
  void PoissonProblem<dim>::update_gradients()
  {
    if (quadratic_reconstruction)
    {
      // g and H of the quadratic fit through the cell values and the boundary-face values (those of
      // Neumann faces from the previous g and H).
      quadratic_reconstruction->compute(phi, laplacian->boundary_values(phi, grad, hessian, bc),
                                        grad, hessian);
      return;
    }
    // New vertex values (boundary faces included) and vertex-based Gauss-Green gradient.
    vertex_interpolation->interpolate(phi, laplacian->boundary_values(phi, grad, bc), vertex_phi);
    gauss_green_gradient(*fv, vertex_phi, grad);
  }

  template <int dim>
  double PoissonProblem<dim>::normal_gradient(const unsigned int f) const
  {
    return quadratic_reconstruction ? laplacian->normal_gradient(f, phi, grad, hessian, bc)
                                    : laplacian->normal_gradient(f, phi, grad, bc);
  }

  template <int dim>
  void PoissonProblem<dim>::compute_errors()
  {
    double max_error = 0, l2 = 0, l2_gradient = 0, max_boundary_gradient_error = 0, max_gradient_error = 0, volume = 0;
    for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
    {
      const double e = phi.local_element(c) - exact.value(fv->centroid[c]);
      max_error = std::max(max_error, std::abs(e));
      l2 += e * e * fv->cell_volume[c];
      volume += fv->cell_volume[c];
    }
    for (unsigned int f = 0; f < fv->faces.size(); ++f)
    {
      const auto& face = fv->faces[f];
      if (face.kind == FaceKind::ghost_boundary)
        continue;
      Tensor<1, dim> g;
      for (unsigned int d = 0; d < dim; ++d)
        g[d] = exact_gradient.value(face.centre, d);
      const double e = normal_gradient(f) - face.n * g;
      double& max = face.N != invalid_cell ? max_gradient_error : max_boundary_gradient_error;
      max = std::max(max, std::abs(e));
      if (face.N != invalid_cell && face.counted_here)
        l2_gradient += e * e * face.area * face.d_n; // weighted by the face's share of volume
    }
    result.n_cells = fv->n_global_cells();
    result.h = std::pow(Utilities::MPI::sum(volume, comm) / result.n_cells, 1.0 / dim);
    result.max_cell_error = Utilities::MPI::max(max_error, comm);
    result.l2_cell_error = std::sqrt(Utilities::MPI::sum(l2, comm));
    result.max_face_gradient_error = Utilities::MPI::max(max_gradient_error, comm);
    result.l2_face_gradient_error = std::sqrt(Utilities::MPI::sum(l2_gradient, comm));
    result.max_boundary_face_gradient_error = Utilities::MPI::max(max_boundary_gradient_error, comm);
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
    CellVector exact_values = fv->make_cell_vector(), error = fv->make_cell_vector();
    for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
    {
      exact_values.local_element(c) = exact.value(fv->centroid[c]);
      error.local_element(c) = phi.local_element(c) - exact_values.local_element(c);
    }
    exact_values.update_ghost_values();
    error.update_ghost_values();
    VtuOutput<dim>(*fv, directory, "poisson").write({{"phi", &phi}, {"phi_exact", &exact_values},
                                                     {"error", &error}},
                                                    0, 0.0);
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
  template void initialize_function(FunctionParser<2>&, const std::string&, const std::string&);
  template void initialize_function(FunctionParser<3>&, const std::string&, const std::string&);
} // namespace fvfsi
