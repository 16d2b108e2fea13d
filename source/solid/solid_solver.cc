#include <deal.II/base/mpi.h>

#include <fvfsi/base/parsed_function.h>
#include <fvfsi/fv/divergence_guard.h>
#include <fvfsi/solid/solid_solver.h>

#include "solid_coupled.templates.h"
#include "solid_face_forces.templates.h"
#include "solid_gradients.templates.h"
#include "solid_jacobian_free.templates.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  SolidSolver<dim>::SolidSolver(const FVGeometry<dim>& geometry,
                                const MeshParameters& mesh_parameters,
                                const SolidParameters& parameters, const TimeControl& clock)
      : geometry(geometry), parameters(parameters), clock(clock),
        pcout(std::cout, Utilities::MPI::this_mpi_process(geometry.comm()) == 0),
        vertex_interpolation(geometry), least_squares(geometry), gauss_green(geometry),
        laplacian(geometry), body_force(dim), acceleration(/*filter=*/1e-5)
  {
    const double E = parameters.E, nu = parameters.nu;
    lame.mu = E / (2 * (1 + nu));
    lame.lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    if (dim == 2 && parameters.plane == SolidParameters::Plane::stress)
      lame.lambda = 2 * lame.mu * lame.lambda / (lame.lambda + 2 * lame.mu);
    lame.nonlinear = parameters.model == SolidParameters::Model::st_venant_kirchhoff;
    initialize_function(body_force, parameters.body_force, "Solid/Body force");
    for (auto& b : body_force_value)
      b.assign(geometry.n_owned_cells(), 0.0);
    setup_boundary_conditions(mesh_parameters);
    find_constrained_vertices();
    evaluate_given_tractions();
    if (parameters.variant == Variant::present && parameters.hessian_correction)
      setup_hessian_correction();

    v = u = CellVectorField<dim>(geometry);
    u_levels.start(u);
    v_levels.start(v);
    for (auto& g : grad_u)
      g = CellGradient<dim>(geometry);
    for (auto& values : vertex_u)
      values.assign(geometry.vertices().size(), 0.0);
    boundary_u.assign(geometry.faces.size(), Tensor<1, dim>());
    boundary_G.assign(geometry.faces.size(), Tensor<2, dim>());
    external_traction.assign(geometry.faces.size(), Tensor<1, dim>());
    // The outer iteration's work vectors, made once on the cells' partitioner and never given
    // ghost values. deal.II's distributed vectors exchange ghost values after a copy from a
    // vector whose ghosts are set and after every operation on a vector whose own ghosts are
    // set, and a copy into a vector made on another partitioner object makes the ranks agree
    // on the layout (an MPI min): made per iteration and copied as whole vectors, these took
    // some 40 meetings of the ranks per outer iteration that carried nothing
    // (doc/results/performance.md, section 8). Copies from u and du take the owned entries
    // only (copy_locally_owned_data_from).
    for (auto* x : {&f, &g, &f_previous, &g_previous, &correction})
    {
      x->reinit(dim);
      for (unsigned int j = 0; j < dim; ++j)
        x->block(j).reinit(geometry.partitioner());
      x->collect_sizes();
    }
    for (unsigned int j = 0; j < dim; ++j)
    {
      residual[j].reinit(geometry.partitioner());
      du[j].reinit(geometry.partitioner());
      laplacian.reinit_matrix(matrix[j]);
      linear_solver[j] = std::make_unique<LinearSolver>(parameters.solver);
    }
    if (parameters.algorithm == SolidParameters::Algorithm::coupled)
      setup_coupled();
  }

  template <int dim>
  void SolidSolver<dim>::setup_hessian_correction()
  {
    // The data of the fit (see solid_gradients.templates.h): mirror images across symmetry planes, the given
    // displacements, and the normal derivative of Eq. 24 at traction faces.
    QuadraticFitData data;
    data.weight_exponent = 2;
    data.value_faces_touch_P = false;
    data.undetermined_is_error = false;
    data.rank_tolerance = 1e-10;
    data.mirror_faces.assign(geometry.faces.size(), false);
    data.value_faces = data.normal_derivative_faces = data.mirror_faces;
    for (const unsigned int f : geometry.all_boundary_faces())
    {
      data.mirror_faces[f] = conditions.type(f) == Type::symmetry;
      data.value_faces[f] = conditions.type(f) == Type::fixed_displacement;
      data.normal_derivative_faces[f] = takes_traction(conditions.type(f));
    }
    cell_hessian = std::make_unique<QuadraticFit<dim>>(geometry, data);
    const unsigned int n_undetermined =
      Utilities::MPI::sum(cell_hessian->n_undetermined(), geometry.comm());
    if (n_undetermined > 0)
      pcout << "fvfsi: Solid/Hessian correction: in " << n_undetermined
            << " cells the neighbourhood does not determine a quadratic; they keep the paper's "
               "first-order terms (H = 0)\n";
    for (auto& H : hessian)
      H = CellHessian<dim>(geometry);
    boundary_g_n.assign(geometry.faces.size(), Tensor<1, dim>());
    boundary_quadratic_term.assign(geometry.faces.size(), Tensor<1, dim>());
    for (auto& term : vertex_quadratic_term)
      term.assign(geometry.vertices().size(), 0.0);
  }

  template <int dim>
  void SolidSolver<dim>::setup_boundary_conditions(const MeshParameters& mesh_parameters)
  {
    conditions = FaceConditions<dim, Type>(
      geometry, mesh_parameters, parameters.boundary_conditions(),
      [](const Type t) { return t == Type::pressure ? 1u : static_cast<unsigned int>(dim); },
      "Solid",
      "Solid/Fixed displacement, Traction, Pressure, Symmetry or External traction; a free "
      "surface: a Traction of 0");
  }

  template <int dim>
  void SolidSolver<dim>::assemble_matrices(const double mass_coefficient)
  {
    // A_j: the orthogonal part of Eq. 19 with K = 2 mu + lambda (Eqs 26-27), Dirichlet faces
    // (fixed displacement; symmetry for the normal component, weight n_j^2) and the mass term.
    ScalarBoundaryConditions<dim> bc;
    for (const unsigned int f : geometry.all_boundary_faces())
      bc.patch_type[geometry.faces[f].patch] =
        takes_traction(conditions.type(f)) ? BoundaryType::neumann : BoundaryType::dirichlet;
    bc.value.assign(geometry.faces.size(), 0.0);
    CellVector unused_rhs = geometry.make_cell_vector();
    for (unsigned int j = 0; j < dim; ++j)
    {
      FaceVector gamma(geometry.faces.size(), lame.K());
      for (const unsigned int f : geometry.all_boundary_faces())
        if (conditions.type(f) == Type::symmetry)
          gamma[f] *= geometry.faces[f].n[j] * geometry.faces[f].n[j];
      matrix[j] = 0;
      laplacian.assemble(gamma, bc, matrix[j], unused_rhs);
      for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
        matrix[j].add(geometry.global_index(c), geometry.global_index(c),
                      parameters.rho * geometry.cell_volume[c] * mass_coefficient);
      matrix[j].compress(VectorOperation::add);
      linear_solver[j]->initialize(matrix[j]);
    }
    assembled_mass_coefficient = mass_coefficient;
  }

  template <int dim>
  std::pair<unsigned long, unsigned long> SolidSolver<dim>::linear_solves_and_iterations() const
  {
    std::pair<unsigned long, unsigned long> n{0, 0};
    for (const auto& solver : linear_solver)
      if (solver)
      {
        n.first += solver->n_solves();
        n.second += solver->n_iterations();
      }
    return n;
  }

  template <int dim>
  void SolidSolver<dim>::shift_time_levels()
  {
    // v^[m-1] from the step just finished (BDF2 or, after the first step, backward Euler):
    // v = c0 u - c1 u^o + c2 u^oo.
    // On the owned and the ghost cells alike (the ghosts' old levels are read by the faces).
    const BdfCoefficients bdf = clock.bdf();
    for (unsigned int c = 0; c < geometry.n_relevant_cells(); ++c)
      v.set(c, u_levels.derivative(bdf, u[c], c));
    v_levels.shift(v);
    u_levels.shift(u);
  }

  template <int dim>
  void SolidSolver<dim>::begin_time_step()
  {
    const double t = clock.time();
    body_force.set_time(t);
    for (unsigned int j = 0; j < dim; ++j) // b at the cell centres, once per time step
      for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
        body_force_value[j][c] =
          checked_value(body_force, geometry.centroid[c], j, "Solid/Body force");
    conditions.set_time(t);
    evaluate_given_tractions();
    // The inertia term rho V a, a = c0 v - c1 v^o + c2 v^oo with v = c0 u - c1 u^o + c2 u^oo
    // (Eqs 17-18): its implicit part is rho V c0^2 u.
    const double c0 = parameters.transient ? clock.bdf().c0 : 0;
    if (c0 * c0 != assembled_mass_coefficient &&
        parameters.algorithm == SolidParameters::Algorithm::segregated)
      assemble_matrices(c0 * c0);
    if (cell_hessian)
      update_boundary_values(); // this time's fixed displacements, also on ghost_boundary faces
  }

  template <int dim>
  void SolidSolver<dim>::end_time_step()
  {
    if (parameters.transient)
      shift_time_levels();
  }

  template <int dim>
  void SolidSolver<dim>::solve_current_step()
  {
    if (parameters.algorithm == SolidParameters::Algorithm::coupled)
    {
      solve_coupled();
      check_stretch();
      check_bounded_displacement();
      return;
    }
    // Outer iterations: the fixed point u = u + A^-1 R(u), accelerated by Anderson mixing.
    acceleration.clear();
    double change = 0;
    for (unsigned int k = 1; k <= parameters.max_outer_iterations; ++k)
    {
      change = outer_iteration(k);
      if (k % 500 == 0)
        pcout << "fvfsi: solid " << clock.step_name() << ", outer iteration " << k
              << ": relative change " << change << " (tolerance " << parameters.outer_tolerance
              << ")\n";
      if (!std::isfinite(change))
        throw std::runtime_error("Solid: displacement is not finite at " + clock.step_name() +
                                 ", outer iteration " + std::to_string(k));
      if (change < parameters.outer_tolerance ||
          (!parameters.transient && clock.step_limit_reached(k)))
      {
        update_gradients();
        last_outer_iterations = k;
        check_stretch();
        check_bounded_displacement();
        return;
      }
    }
    throw std::runtime_error("Solid: outer iterations did not converge at " + clock.step_name() +
                             ": relative change " + Utilities::to_string(change) + " after " +
                             std::to_string(parameters.max_outer_iterations) +
                             " iterations (raise Solid/Max outer iterations, or reduce the load or "
                             "time step)");
  }

  template <int dim>
  void SolidSolver<dim>::check_bounded_displacement()
  {
    if (body_size == 0)
      body_size = domain_diameter(geometry);
    double given = 0;
    for (const unsigned int f : geometry.boundary_faces())
      if (conditions.type(f) == Type::fixed_displacement)
        given = std::max(given, boundary_u[f].norm());
    given_displacement = std::max(given_displacement, Utilities::MPI::max(given, geometry.comm()));
    const double scale = body_size + given_displacement;
    const CellMaximum<dim> largest =
      cell_maximum<dim>(geometry, [this](const unsigned int c) { return u[c].norm(); });
    largest_displacement_ratio_seen =
      std::max(largest_displacement_ratio_seen, largest.value / scale);
    check_bounded(largest, parameters.displacement_bound * scale, "Solid", clock.step_name(),
                  "max |u|", "m",
                  Utilities::to_string(parameters.displacement_bound) +
                    " x (the body's diameter + the largest given displacement) = " +
                    Utilities::to_string(parameters.displacement_bound) + " x " +
                    Utilities::to_string(scale) + " m; Solid/Displacement bound",
                  "check the loads (Solid/Traction, Solid/Pressure, Solid/Body force, "
                  "Solid/Fixed displacement) and Time/Time step");
  }

  template <int dim>
  void SolidSolver<dim>::check_stretch()
  {
    // St. Venant-Kirchhoff's stress does not grow without bound in compression: in uniaxial
    // stress, P = E lambda (lambda^2 - 1) / 2 is most compressive at the stretch lambda =
    // 1/sqrt(3) and shrinks again below it. Past that limit point the discrete equations can
    // have more than one solution; the segregated boundary iteration (Eqs 23-24) has been seen to
    // settle on a second one at a clamped corner (doc/results/cavity.md). Say so once.
    if (!lame.nonlinear)
      return;
    const double stretch = smallest_stretch(), limit = 1 / std::sqrt(3.0);
    if (stretch < limit && least_stretch_seen >= limit)
      pcout << "fvfsi: warning: at " << clock.step_name()
            << " the solid's smallest principal stretch is " << stretch
            << ", below 1/sqrt(3) = " << limit
            << " where the St. Venant-Kirchhoff model's compressive stress is largest: "
            << "past it the discrete solution need not be unique. Compare with "
            << "Solid/Algorithm = coupled (Newton from the unloaded state) or more "
            << "Solid/Boundary sweeps.\n";
    least_stretch_seen = std::min(least_stretch_seen, stretch);
  }

  template <int dim>
  double SolidSolver<dim>::outer_iteration(const unsigned int k)
  {
    update_gradients();
    compute_residual(residual);
    for (unsigned int j = 0; j < dim; ++j)
      try
      {
        du[j] = 0; // the linear solve's start value
        linear_solver[j]->solve(matrix[j], du[j], residual[j],
                                "solid displacement component " + std::to_string(j));
      }
      catch (const std::exception& e)
      {
        throw std::runtime_error("Solid: at " + clock.step_name() + ", outer iteration " +
                                 std::to_string(k) + ": " + e.what() + divergence_hint());
      }
    // The fixed-point image g = u + du and its residual f = du; with acceleration u <- g + the
    // least-squares correction of the model built from the last iterations' differences.
    for (unsigned int j = 0; j < dim; ++j)
    {
      f.block(j).copy_locally_owned_data_from(du[j]);
      g.block(j).copy_locally_owned_data_from(u.components[j]);
      g.block(j) += du[j];
    }
    const double max_du = f.linfty_norm();
    if (parameters.acceleration_depth > 0)
    {
      if (k > 1)
      {
        f_previous.sadd(-1, 1, f); // f - f_previous
        g_previous.sadd(-1, 1, g);
        acceleration.add_column(f_previous, g_previous);
        if (acceleration.size() > parameters.acceleration_depth)
          acceleration.drop_oldest();
      }
      f_previous = f;
      g_previous = g;
      if (acceleration.correction(f, correction))
        g += correction;
    }
    for (unsigned int j = 0; j < dim; ++j)
      u.components[j].copy_locally_owned_data_from(g.block(j));
    u.update_ghost_values();
    const double max_u = g.linfty_norm();
    if (!std::isfinite(max_u) || !std::isfinite(max_du))
      return std::numeric_limits<double>::quiet_NaN();
    return max_u == 0 ? 0 : max_du / max_u;
  }

  template <int dim>
  std::string SolidSolver<dim>::divergence_hint() const
  {
    // |grad u| = 1e3 is a stretch by a factor of a thousand: no solution the iteration is after.
    constexpr double beyond_any_strain = 1e3;
    double largest = 0, traction = 0;
    for (const unsigned int f : geometry.boundary_faces())
      if (takes_traction(conditions.type(f)) && f < boundary_G.size())
      {
        const double G = boundary_G[f].norm();
        if (!(G <= largest)) // NaN too
        {
          largest = std::isfinite(G) ? G : std::numeric_limits<double>::max();
          traction = boundary_traction(f, Tensor<2, dim>()).norm();
        }
      }
    const double global = Utilities::MPI::max(largest, geometry.comm());
    const double t = Utilities::MPI::max(largest == global ? traction : 0.0, geometry.comm());
    if (!(global > beyond_any_strain))
      return "";
    std::ostringstream hint;
    hint << "\n(on the faces of Solid/Traction, Pressure or External traction the displacement "
            "gradient has reached "
         << global << " (traction up to " << t << " Pa against Young's modulus " << parameters.E
         << " Pa): the load is too large for the traction boundary condition's iteration (Eq. "
            "24) to converge from this state; lower it, or ramp it up over time)";
    return hint.str();
  }

  template <int dim>
  Tensor<2, dim> SolidSolver<dim>::cell_gradient(const unsigned int c) const
  {
    Tensor<2, dim> G;
    for (unsigned int j = 0; j < dim; ++j)
    {
      const Tensor<1, dim> g = grad_u[j][c];
      for (unsigned int i = 0; i < dim; ++i)
        G[i][j] = g[i];
    }
    return G;
  }

  template <int dim>
  Tensor<2, dim> SolidSolver<dim>::cell_stress(const unsigned int c) const
  {
    return cauchy_stress(cell_gradient(c), lame);
  }

  template <int dim>
  Tensor<2, dim> SolidSolver<dim>::face_stress(const unsigned int f) const
  {
    return cauchy_stress(face_gradient(f), lame);
  }

  template <int dim>
  std::vector<Tensor<1, dim>> SolidSolver<dim>::vertex_displacements() const
  {
    std::vector<Tensor<1, dim>> d(geometry.vertices().size());
    std::vector<double> values;
    for (unsigned int j = 0; j < dim; ++j)
    {
      const std::vector<double>* v = &vertex_u[j];
      if (parameters.variant != Variant::present)
      {
        // The other variants do not use vertex values: reconstruct them (App. B) for the caller.
        FaceVector boundary_values(geometry.faces.size());
        std::transform(boundary_u.begin(), boundary_u.end(), boundary_values.begin(),
                       [j](const Tensor<1, dim>& u_b) { return u_b[j]; });
        vertex_interpolation.interpolate(u.components[j], boundary_values, values);
        v = &values;
      }
      for (unsigned int i = 0; i < d.size() && i < v->size(); ++i)
        d[i][j] = (*v)[i];
    }
    return d;
  }

  template <int dim>
  void SolidSolver<dim>::set_external_traction(const std::vector<Tensor<1, dim>>& traction)
  {
    external_traction = traction;
  }

  template <int dim>
  Tensor<1, dim> SolidSolver<dim>::probe_displacement(const PointProbes<dim>& probes,
                                                      const unsigned int i) const
  {
    return probes.template evaluate<Tensor<1, dim>>(
      i, [this](const unsigned int c, const Tensor<1, dim>& dx)
      { return u[c] + dx * cell_gradient(c); });
  }

  template <int dim>
  void SolidSolver<dim>::checkpoint(MeshArchive<dim>& archive)
  {
    // Everything the next step's first outer iteration reads: u and the levels of u and v; the
    // boundary values, vertex values and gradients of u (iterated, not functions of u alone); the
    // Hessians and their terms (present variant with the Hessian correction).
    for (auto* field : {&u, &u_levels.o, &u_levels.oo, &v_levels.o, &v_levels.oo})
      for (auto& component : field->components)
        archive.cells(component);
    for (unsigned int j = 0; j < dim; ++j)
    {
      for (auto& component : grad_u[j].components)
        archive.cells(component);
      archive.vertices(vertex_u[j]);
    }
    archive.faces(boundary_u, Parity::even);
    archive.faces(boundary_G, Parity::even);
    if (cell_hessian)
    {
      archive.faces(boundary_g_n, Parity::odd);
      for (unsigned int j = 0; j < dim; ++j)
      {
        for (auto& component : hessian[j].components)
          archive.cells(component);
        archive.vertices(vertex_quadratic_term[j]);
      }
      archive.faces(boundary_quadratic_term, Parity::even);
    }
    if (archive.loading())
    {
      for (auto* field : {&u, &u_levels.o, &u_levels.oo, &v_levels.o, &v_levels.oo})
        field->update_ghost_values();
      for (unsigned int j = 0; j < dim; ++j)
      {
        grad_u[j].update_ghost_values();
        if (cell_hessian)
          hessian[j].update_ghost_values();
      }
    }
  }

  template <int dim>
  void SolidSolver<dim>::add_output_fields(OutputFields<dim>& fields) const
  {
    fields.add_vector("u", [this](const unsigned int c) { return u[c]; });
    const char* axis[] = {"x", "y", "z"};
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        fields.add(std::string("sigma_") + axis[i] + axis[j],
                   [&](const unsigned int c) { return cell_stress(c)[i][j]; });
    fields.add("von_Mises",
               [this](const unsigned int c)
               {
                 const Tensor<2, dim> s = cell_stress(c);
                 const Tensor<2, dim> dev = s - trace(s) / 3.0 * unit_symmetric_tensor<dim>();
                 return std::sqrt(1.5 * scalar_product(dev, dev));
               });
  }

  template class SolidSolver<2>;
  template class SolidSolver<3>;
} // namespace fvfsi
