#include <deal.II/base/mpi.h>

#include <fvfsi/apps/poisson.h> // initialize_function
#include <fvfsi/fv/ghost_faces.h>
#include <fvfsi/solid/solid_solver.h>

#include <cmath>
#include <stdexcept>

namespace fvfsi
{
using namespace dealii;
using Type = SolidBoundaryCondition::Type;

namespace
{
bool takes_traction(const Type t)
{
  return t == Type::traction || t == Type::pressure || t == Type::external_traction;
}
} // namespace

template <int dim>
SolidSolver<dim>::SolidSolver(const FVGeometry<dim>& geometry,
                              const MeshParameters& mesh_parameters,
                              const SolidParameters& parameters)
    : geometry(geometry), parameters(parameters),
      pcout(std::cout, Utilities::MPI::this_mpi_process(geometry.comm()) == 0),
      vertex_interpolation(geometry), least_squares(geometry), gauss_green(geometry),
      laplacian(geometry), body_force(dim)
{
  const double E = parameters.E, nu = parameters.nu;
  lame.mu = E / (2 * (1 + nu));
  lame.lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  if (dim == 2 && parameters.plane == "plane stress")
    lame.lambda = 2 * lame.mu * lame.lambda / (lame.lambda + 2 * lame.mu);
  lame.nonlinear = parameters.model == "St. Venant-Kirchhoff";
  initialize_function(body_force, parameters.body_force, "Solid/Body force");
  for (auto& b : body_force_value)
    b.assign(geometry.n_owned_cells(), 0.0);
  present_variant = parameters.variant == "present";
  jasak_weller_variant = parameters.variant == "Jasak-Weller";
  setup_boundary_conditions(mesh_parameters);
  find_constrained_vertices();
  for (unsigned int f = 0; f < geometry.faces.size(); ++f)
  {
    if (geometry.faces[f].kind == FaceKind::boundary)
      boundary_faces.push_back(f);
    if (geometry.faces[f].N == invalid_cell)
      all_boundary_faces.push_back(f);
  }
  evaluate_given_tractions();
  if (present_variant && parameters.hessian_correction) // see update_hessians()
  {
    std::vector<bool> mirror(geometry.faces.size(), false), known_value(mirror),
        known_normal_derivative(mirror);
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
      if (geometry.faces[f].N == invalid_cell)
      {
        mirror[f] = face_condition[f].type == Type::symmetry;
        known_value[f] = face_condition[f].type == Type::fixed_displacement;
        known_normal_derivative[f] = takes_traction(face_condition[f].type);
      }
    cell_hessian =
        std::make_unique<DisplacementHessian<dim>>(geometry, mirror, known_value, known_normal_derivative);
    const unsigned int n_undetermined =
        Utilities::MPI::sum(cell_hessian->n_undetermined(), geometry.comm());
    if (n_undetermined > 0)
      pcout << "fvfsi: Solid/Hessian correction: in " << n_undetermined
            << " cells the neighbourhood does not determine a quadratic; they keep the paper's "
               "first-order terms (H = 0)\n";
    for (auto& H : hessian)
      for (auto& entry : H.entries)
      {
        entry = geometry.make_cell_vector();
        entry.update_ghost_values();
      }
    boundary_g_n.assign(geometry.faces.size(), Tensor<1, dim>());
    boundary_quadratic_term.assign(geometry.faces.size(), Tensor<1, dim>());
    for (auto& term : vertex_quadratic_term)
      term.assign(geometry.vertices().size(), 0.0);
  }

  for (auto* field : {&u, &u_old, &u_old2, &v_old, &v_old2})
    *field = CellVectorField<dim>(geometry);
  for (auto& g : grad_u)
    g = CellGradient<dim>(geometry);
  for (auto& v : vertex_u)
    v.assign(geometry.vertices().size(), 0.0);
  boundary_u.assign(geometry.faces.size(), Tensor<1, dim>());
  boundary_G.assign(geometry.faces.size(), Tensor<2, dim>());
  external_traction.assign(geometry.faces.size(), Tensor<1, dim>());
  if (parameters.acceleration_depth > 0)
    acceleration =
        std::make_unique<AndersonAcceleration>(geometry.comm(), parameters.acceleration_depth);
  for (unsigned int j = 0; j < dim; ++j)
  {
    laplacian.reinit_matrix(matrix[j]);
    linear_solver[j] = std::make_unique<LinearSolver>(parameters.solver);
  }
}

template <int dim>
void SolidSolver<dim>::setup_boundary_conditions(const MeshParameters& mesh_parameters)
{
  std::map<unsigned int, FaceCondition> by_patch;
  for (const auto& bc : parameters.boundary_conditions())
  {
    FaceCondition condition{bc.type, -1};
    if (!bc.expression.empty())
    {
      const unsigned int n_components = bc.type == Type::pressure ? 1 : dim;
      functions.push_back(std::make_unique<FunctionParser<dim>>(n_components));
      initialize_function(*functions.back(), bc.expression,
                          "Solid boundary condition on " + bc.patch);
      condition.expression = functions.size() - 1;
    }
    by_patch[mesh_parameters.patch_id(bc.patch)] = condition;
  }
  face_condition.resize(geometry.faces.size());
  for (unsigned int f = 0; f < geometry.faces.size(); ++f)
    if (geometry.faces[f].N == invalid_cell)
    {
      const auto it = by_patch.find(geometry.faces[f].patch);
      if (it == by_patch.end())
        throw std::runtime_error("Solid: patch `" +
                                 mesh_parameters.patch_name(geometry.faces[f].patch) +
                                 "` has no boundary condition (use a traction of 0; 0 for a free "
                                 "surface)");
      face_condition[f] = it->second;
    }
}

template <int dim>
void SolidSolver<dim>::assemble_matrices(const double mass_coefficient)
{
  // A_j: the orthogonal part of Eq. 19 with K = 2 mu + lambda (Eqs 26-27), Dirichlet faces
  // (fixed displacement; symmetry for the normal component, weight n_j^2) and the mass term.
  ScalarBoundaryConditions<dim> bc;
  for (unsigned int f = 0; f < geometry.faces.size(); ++f)
    if (geometry.faces[f].N == invalid_cell)
      bc.patch_type[geometry.faces[f].patch] =
          takes_traction(face_condition[f].type) ? BoundaryType::neumann : BoundaryType::dirichlet;
  bc.value.assign(geometry.faces.size(), 0.0);
  CellVector unused_rhs = geometry.make_cell_vector();
  for (unsigned int j = 0; j < dim; ++j)
  {
    FaceVector gamma(geometry.faces.size(), lame.K());
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
      if (geometry.faces[f].N == invalid_cell && face_condition[f].type == Type::symmetry)
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
Tensor<2, dim> SolidSolver<dim>::face_gradient(const unsigned int f) const
{
  const auto& face = geometry.faces[f];
  const bool boundary = face.N == invalid_cell;
  if (boundary && takes_traction(face_condition[f].type))
    return boundary_G[f]; // Eq. 24
  const Tensor<2, dim> G_P = cell_gradient(face.P);
  const Tensor<1, dim> u_P = u[face.P];
  // Normal derivative vector g_n = n . grad u: Eq. 19 inside, Eq. 23 on displacement faces.
  Tensor<1, dim> g_n;
  if (boundary)
    g_n = (boundary_u[f] - u_P - face.k_P * G_P) / face.d_n;
  else
  {
    const Tensor<2, dim> G_N = cell_gradient(face.N);
    g_n = (u[face.N] - u_P - face.k_N * G_N - face.k_P * G_P) / face.d_n;
  }
  if (present_variant)
  {
    // Tangential part from the vertex values (Eq. 39), also on boundary faces.
    Tensor<2, dim> G = outer_product(face.n, g_n);
    for (unsigned int j = 0; j < dim; ++j)
    {
      const Tensor<1, dim> t = tangential_gradient(face, vertex_u[j]);
      for (unsigned int i = 0; i < dim; ++i)
        G[i][j] += t[i];
    }
    return G;
  }
  // Demirdzic-Muzaferija and Jasak-Weller: the interpolated cell gradient (the cell's own at a
  // boundary), with its normal part replaced by g_n.
  const Tensor<2, dim> G_bar = boundary ? G_P : face.w * G_P + (1 - face.w) * cell_gradient(face.N);
  return G_bar + outer_product(face.n, g_n - face.n * G_bar);
}

template <int dim>
Tensor<1, dim> SolidSolver<dim>::boundary_traction(const unsigned int f,
                                                   const Tensor<2, dim>& G) const
{
  // The force per reference area of a Cauchy traction t: t S'/S (Eq. 24), S'/S from Nanson.
  const auto& face = geometry.faces[f];
  const auto& condition = face_condition[f];
  const Tensor<1, dim> area_ratio_n = deformed_area_vector(G, face.n, lame);
  if (condition.type == Type::external_traction)
    return area_ratio_n.norm() * external_traction[f];
  if (condition.type == Type::pressure)
    return -given_traction[f][0] * area_ratio_n;
  return area_ratio_n.norm() * given_traction[f];
}

template <int dim>
void SolidSolver<dim>::evaluate_given_tractions()
{
  given_traction.resize(geometry.faces.size());
  for (const unsigned int f : boundary_faces)
  {
    const auto& condition = face_condition[f];
    if (condition.type == Type::pressure)
      given_traction[f][0] = functions[condition.expression]->value(geometry.faces[f].centre);
    else if (condition.type == Type::traction)
      for (unsigned int d = 0; d < dim; ++d)
        given_traction[f][d] = functions[condition.expression]->value(geometry.faces[f].centre, d);
  }
}

template <int dim>
void SolidSolver<dim>::update_boundary_values()
{
  for (const unsigned int f : boundary_faces)
  {
    const auto& face = geometry.faces[f];
    const auto& condition = face_condition[f];
    const Tensor<2, dim> G_P = cell_gradient(face.P);
    const Tensor<1, dim> extrapolated = u[face.P] + face.k_P * G_P;
    switch (condition.type)
    {
    case Type::fixed_displacement:
    {
      const auto& fn = *functions[condition.expression];
      for (unsigned int d = 0; d < dim; ++d)
        boundary_u[f][d] = fn.value(face.centre, d);
      break;
    }
    case Type::symmetry:
    {
      Tensor<1, dim> e = extrapolated;
      if (cell_hessian)
        e += boundary_quadratic_term[f];
      boundary_u[f] = e - (e * face.n) * face.n;
      break;
    }
    default:
    {
      // Eq. 24: K g_n = t S'/S - n . q, with n . q = n.(Sigma.F^T) - K n . grad u at the
      // previous iterate; then u_b from Eq. 23.
      const Tensor<2, dim>& G_old = boundary_G[f];
      const Tensor<1, dim> n_q =
          first_piola_traction(G_old, face.n, lame) - lame.K() * (face.n * G_old);
      const Tensor<1, dim> g_n = (boundary_traction(f, G_old) - n_q) / lame.K();
      Tensor<2, dim> T; // tangential part
      if (present_variant)
        for (unsigned int j = 0; j < dim; ++j)
        {
          const Tensor<1, dim> t = tangential_gradient(face, vertex_u[j]);
          for (unsigned int i = 0; i < dim; ++i)
            T[i][j] = t[i];
        }
      else
        T = G_P - outer_product(face.n, face.n * G_P);
      boundary_G[f] = outer_product(face.n, g_n) + T;
      boundary_u[f] = extrapolated + face.d_n * g_n;
      if (cell_hessian)
        boundary_u[f] += boundary_quadratic_term[f];
    }
    }
  }
  update_ghost_boundary_faces(geometry, boundary_u);
}

template <int dim>
void SolidSolver<dim>::update_gradients()
{
  // Boundary values (Eqs 23-24), vertex values and gradients depend on each other; a few sweeps
  // make them (nearly) a function of u alone, so that the outer iteration is a fixed-point map
  // of u that Anderson acceleration can model.
  if (cell_hessian)
    update_hessians();
  FaceVector boundary_values(geometry.faces.size()); // only boundary entries are read
  for (unsigned int sweep = 0; sweep < parameters.boundary_sweeps; ++sweep)
  {
    update_boundary_values();
    for (unsigned int j = 0; j < dim; ++j)
    {
      for (const unsigned int f : all_boundary_faces)
        boundary_values[f] = boundary_u[f][j];
      const CellVector& u_j = u.components[j];
      if (present_variant)
      {
        vertex_interpolation.interpolate(u_j, boundary_values, vertex_u[j]);
        if (cell_hessian)
          for (const unsigned int v : vertex_interpolation.vertices())
            vertex_u[j][v] += vertex_quadratic_term[j][v];
      }
      else if (parameters.variant == "Demirdzic-Muzaferija")
        least_squares.compute(u_j, boundary_values, grad_u[j]);
      else
        gauss_linear_gradient(geometry, u_j, boundary_values, grad_u[j], /*skew_corrected=*/true);
    }
    if (present_variant)
    {
      impose_vertex_constraints();
      for (unsigned int j = 0; j < dim; ++j)
        gauss_green.compute(vertex_u[j], grad_u[j]);
    }
  }
}

// Hessian correction (Solid/Hessian correction, present variant): the paper's method plus an
// extension that makes the vertex values exact for quadratic fields.
//
// Why the paper's forms lose a log at a traction corner. The linear least-squares vertex fit
// (App. B) has the error sum_j a_j 1/2 s_j.H.s_j (s_j = r_j - x_v): O(h^2), with a coefficient set
// by the stencil's shape. Between interior vertices of a smooth mesh it varies smoothly, so the
// tangential gradient of Eq. 39 (a difference of neighbouring vertex values over a face) stays
// O(h^2), and what error the face forces carry cancels between the two faces of a cell. A
// boundary vertex has a one-sided stencil that includes the boundary-face values, and at a
// traction face these come from Eq. 23, u_b = u_P + k_P.grad u_P + d_n g_n, a first-order Taylor
// step with the error -1/2 (k_P.H.k_P - d_n^2 n.H.n). The vertex error at the boundary then has
// another O(1) coefficient than one vertex in; on the faces of the first cell row that end on the
// boundary the tangential gradient is O(h) wrong, an O(h^2) force per face. Along the row these
// forces cancel between neighbouring cells, except where the row ends: at a corner between two
// traction boundaries the neighbouring faces carry the exact traction, and the unbalanced O(h^2)
// force acts like a point load, whose displacement in 2D grows like log(1/r). The max
// displacement error converges like h^2 (a + b log(1/h)) there: plate with a hole, outer corner
// (2, 2), observed orders 1.96, 1.81, 1.85, 1.87 (up to 256k cells). With the exact displacement
// imposed on the two outer sides instead, the orders are 1.96 and 2.01.
//
// What the correction does, with Hessians H_P of each u_j per cell from a least-squares quadratic
// fit (DisplacementHessian: the cells sharing a vertex with P; at a traction face the normal derivative
// g_n of Eq. 24, which fixes the second normal derivative; mirror images across symmetry planes;
// given values on displacement faces):
//  - vertex values: phi_v = sum_j a_j (phi_j - 1/2 s_j.H_j.s_j), exact for quadratics, so the
//    vertex error is O(h^3) on the boundary and inside alike;
//  - boundary values extrapolated at traction and symmetry faces: Eq. 23 plus
//    1/2 (k_P.H.k_P - d_n^2 n.H.n), exact for quadratics (at a symmetry face for the tangential
//    components, with d_n n.grad u_t = 0).
// Both are needed: the second alone (vertex values still linear fits) lifts the finest-pair order
// to 2.04 but leaves 1.88 on the coarsest pair, and the first alone puts the O(h^2) error of the
// traction-face values into every boundary vertex (hole-stress orders 1.66, 1.51 even with the
// exact Hessian). With both the orders
// are 1.99, 2.00, 2.00 (displacement) and 1.97, 1.99, 1.99 (hole stress), and the max error moves
// from the corner to the hole. H is computed once per outer iteration, before the sweeps (from u
// and the g_n of the previous sweeps: consistent at convergence); the price is about 15 % more
// outer iterations at nu = 0.3. The explicitly treated Hessian terms couple more cells, and where
// the explicit part is strong already (nearly incompressible plane strain, lambda div u) the
// segregated iteration then contracts much more slowly: plate with a hole, 968 cells, 274 instead
// of 131 outer iterations at nu = 0.45, 4866 instead of 274 at nu = 0.49, no convergence in 5000
// at nu = 0.499 (updating H in every sweep or under-relaxing it helps only partly: 900-1500).
template <int dim>
void SolidSolver<dim>::update_hessians()
{
  for (const unsigned int f : boundary_faces)
    if (takes_traction(face_condition[f].type))
      boundary_g_n[f] = geometry.faces[f].n * boundary_G[f];
  cell_hessian->compute(u, boundary_u, boundary_g_n, hessian);
  // 1/2 (k_P.H.k_P - d_n^2 n.H.n) per extrapolated boundary face, and the vertex fit's terms:
  // fixed while the sweeps iterate the boundary and vertex values for this u.
  for (const unsigned int f : boundary_faces)
  {
    const auto& face = geometry.faces[f];
    if (face_condition[f].type == Type::fixed_displacement)
      continue;
    for (unsigned int j = 0; j < dim; ++j)
    {
      const Tensor<2, dim> H = hessian[j][face.P];
      boundary_quadratic_term[f][j] =
          0.5 * (face.k_P * H * face.k_P - face.d_n * face.d_n * (face.n * H * face.n));
    }
  }
  for (unsigned int j = 0; j < dim; ++j)
  {
    vertex_quadratic_term[j].assign(geometry.vertices().size(), 0.0);
    vertex_interpolation.subtract_quadratic_terms(hessian[j], vertex_quadratic_term[j]);
  }
}

template <int dim>
void SolidSolver<dim>::impose_vertex_constraints()
{
  // The least-squares fit of App. B does not know that a symmetry plane forces u . n = 0 and a
  // displacement boundary gives u exactly; a vertex on such a boundary takes that knowledge
  // (otherwise the fit's O(h^2) error differs between the corner vertices and their
  // neighbours, and the tangential gradient of Eq. 39 drops to first order there).
  for (const auto& [v, n] : symmetry_vertex_normals)
  {
    double u_n = 0;
    for (unsigned int j = 0; j < dim; ++j)
      u_n += vertex_u[j][v] * n[j];
    for (unsigned int j = 0; j < dim; ++j)
      vertex_u[j][v] -= u_n * n[j];
  }
  for (const auto& [v, fn] : fixed_vertex_function)
    for (unsigned int j = 0; j < dim; ++j)
      vertex_u[j][v] = fn->value(geometry.vertices()[v], j);
}

template <int dim>
void SolidSolver<dim>::find_constrained_vertices()
{
  for (unsigned int f = 0; f < geometry.faces.size(); ++f)
  {
    const auto& face = geometry.faces[f];
    if (face.N != invalid_cell)
      continue;
    for (const unsigned int v : face.vertices)
      if (face_condition[f].type == Type::symmetry)
      {
        // Each distinct plane once (two planes meet at a corner: project on both).
        bool known = false;
        for (const auto& [w, n] : symmetry_vertex_normals)
          known = known || (w == v && std::abs(n * face.n) > 1 - 1e-8);
        if (!known)
          symmetry_vertex_normals.emplace_back(v, face.n);
      }
      else if (face_condition[f].type == Type::fixed_displacement)
        fixed_vertex_function[v] = functions[face_condition[f].expression].get();
  }
}

template <int dim>
Tensor<1, dim> SolidSolver<dim>::face_force_density(const unsigned int f) const
{
  const auto& face = geometry.faces[f];
  if (face.N != invalid_cell)
  {
    if (!jasak_weller_variant)
      return first_piola_traction(face_gradient(f), face.n, lame);
    // Jasak-Weller: K n.grad u_f (Eq. 19 with interpolated gradients) + n.q of the
    // interpolated cell gradient, as solidDisplacementFoam's laplacian + div(sigmaExp).
    const Tensor<2, dim> G_f = face_gradient(f);
    const Tensor<2, dim> G_bar =
        face.w * cell_gradient(face.P) + (1 - face.w) * cell_gradient(face.N);
    return lame.K() * (face.n * G_f) + first_piola_traction(G_bar, face.n, lame) -
           lame.K() * (face.n * G_bar);
  }
  const auto type = face_condition[f].type;
  if (takes_traction(type))
    return boundary_traction(f, boundary_G[f]);
  const Tensor<1, dim> t = first_piola_traction(face_gradient(f), face.n, lame);
  return type == Type::symmetry ? (t * face.n) * face.n : t;
}

template <int dim>
void SolidSolver<dim>::compute_residual(std::array<CellVector, dim>& residual) const
{
  // R_P = sum_f S_f n.(Sigma.F^T)_f + rho V (b - a(u)), the residual of Eq. 16.
  for (auto& r : residual)
    r = 0;
  for (unsigned int f = 0; f < geometry.faces.size(); ++f)
  {
    const auto& face = geometry.faces[f];
    if (face.kind == FaceKind::ghost_boundary)
      continue;
    const Tensor<1, dim> force = face.area * face_force_density(f);
    for (unsigned int j = 0; j < dim; ++j)
    {
      residual[j].local_element(face.P) += force[j];
      if (face.kind == FaceKind::interior)
        residual[j].local_element(face.N) -= force[j];
    }
  }
  const double dt = parameters.time_step;
  for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
  {
    const double rho_V = parameters.rho * geometry.cell_volume[c];
    for (unsigned int j = 0; j < dim; ++j)
    {
      double acceleration = 0;
      if (parameters.transient)
      {
        const double u_c = u.components[j].local_element(c),
                     u1 = u_old.components[j].local_element(c),
                     u2 = u_old2.components[j].local_element(c),
                     v1 = v_old.components[j].local_element(c),
                     v2 = v_old2.components[j].local_element(c);
        acceleration = time_step_number == 1 ? (u_c - u1) / (dt * dt) - v1 / dt // backward Euler
                                             : (9 * u_c - 12 * u1 + 3 * u2) / (4 * dt * dt) -
                                                   (4 * v1 - v2) / (2 * dt); // Eqs 17-18
      }
      residual[j].local_element(c) += rho_V * (body_force_value[j][c] - acceleration);
    }
  }
}

template <int dim>
void SolidSolver<dim>::shift_time_levels()
{
  // v^[m-1] from the step just finished (BDF2 or, after the first step, backward Euler).
  const double dt = parameters.time_step;
  for (unsigned int j = 0; j < dim; ++j)
    for (unsigned int c = 0; c < geometry.n_relevant_cells(); ++c)
    {
      const double u_c = u.components[j].local_element(c),
                   u1 = u_old.components[j].local_element(c),
                   u2 = u_old2.components[j].local_element(c);
      const double v = time_step_number <= 1 ? (u_c - u1) / dt : (3 * u_c - 4 * u1 + u2) / (2 * dt);
      v_old2.components[j].local_element(c) = v_old.components[j].local_element(c);
      v_old.components[j].local_element(c) = v;
      u_old2.components[j].local_element(c) = u1;
      u_old.components[j].local_element(c) = u_c;
    }
}

template <int dim>
unsigned int SolidSolver<dim>::solve_time_step()
{
  begin_time_step();
  return solve_current_step();
}

template <int dim>
void SolidSolver<dim>::begin_time_step()
{
  if (time_step_number > 0 && parameters.transient)
    shift_time_levels();
  ++time_step_number;
  current_time += parameters.time_step;
  body_force.set_time(current_time);
  for (unsigned int j = 0; j < dim; ++j) // b at the cell centres, once per time step
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
      body_force_value[j][c] = body_force.value(geometry.centroid[c], j);
  for (auto& fn : functions)
    fn->set_time(current_time);
  evaluate_given_tractions();
  const double dt = parameters.time_step;
  const double mass_coefficient =
      !parameters.transient ? 0 : (time_step_number == 1 ? 1 / (dt * dt) : 9 / (4 * dt * dt));
  if (mass_coefficient != assembled_mass_coefficient)
    assemble_matrices(mass_coefficient);
  if (cell_hessian)
    update_boundary_values(); // this time's fixed displacements, also on ghost_boundary faces
}

template <int dim>
unsigned int SolidSolver<dim>::solve_current_step()
{
  std::array<CellVector, dim> residual, du;
  for (unsigned int j = 0; j < dim; ++j)
  {
    residual[j] = geometry.make_cell_vector();
    du[j] = geometry.make_cell_vector();
  }
  // Outer iterations: the fixed point u = u + A^-1 R(u), accelerated by Anderson mixing.
  const unsigned int n_owned = geometry.n_owned_cells();
  std::vector<double> x(dim * n_owned), g(dim * n_owned);
  if (acceleration)
    acceleration->reset();
  double change = 0;
  for (unsigned int k = 1; k <= parameters.max_outer_iterations; ++k)
  {
    update_gradients();
    compute_residual(residual);
    double max_du = 0, max_u = 0;
    for (unsigned int j = 0; j < dim; ++j)
    {
      du[j] = 0;
      try
      {
        linear_solver[j]->solve(matrix[j], du[j], residual[j],
                                "solid displacement component " + std::to_string(j));
      }
      catch (const std::exception& e)
      {
        throw std::runtime_error("Solid: at time step " + std::to_string(time_step_number) +
                                 " (t = " + Utilities::to_string(current_time) +
                                 " s), outer iteration " + std::to_string(k) + ": " + e.what());
      }
      for (unsigned int c = 0; c < n_owned; ++c)
      {
        x[j * n_owned + c] = u.components[j].local_element(c);
        g[j * n_owned + c] = x[j * n_owned + c] + du[j].local_element(c);
        max_du = std::max(max_du, std::abs(du[j].local_element(c)));
      }
    }
    if (acceleration)
      acceleration->step(x, g);
    for (unsigned int j = 0; j < dim; ++j)
      for (unsigned int c = 0; c < n_owned; ++c)
      {
        u.components[j].local_element(c) = g[j * n_owned + c];
        max_u = std::max(max_u, std::abs(g[j * n_owned + c]));
      }
    u.update_ghost_values();
    max_du = Utilities::MPI::max(max_du, geometry.comm());
    max_u = Utilities::MPI::max(max_u, geometry.comm());
    change = max_du / std::max(max_u, 1e-300);
    if (k % 500 == 0)
      pcout << "fvfsi: solid time step " << time_step_number << ", outer iteration " << k
            << ": relative change " << change << " (tolerance " << parameters.outer_tolerance
            << ")\n";
    if (!std::isfinite(max_u) || !std::isfinite(max_du))
      throw std::runtime_error(
          "Solid: displacement is not finite at time step " + std::to_string(time_step_number) +
          " (t = " + Utilities::to_string(current_time) + " s), outer iteration " + std::to_string(k));
    if (change < parameters.outer_tolerance || max_u == 0)
    {
      update_gradients();
      return k;
    }
  }
  throw std::runtime_error(
      "Solid: outer iterations did not converge at time step " + std::to_string(time_step_number) +
      " (t = " + Utilities::to_string(current_time) + " s): relative change " +
      Utilities::to_string(change) + " after " + std::to_string(parameters.max_outer_iterations) +
      " iterations (raise Solid/Max outer iterations, or reduce the load or time step)");
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
Tensor<1, dim> SolidSolver<dim>::patch_force(const unsigned int patch) const
{
  Tensor<1, dim> force;
  for (unsigned int f = 0; f < geometry.faces.size(); ++f)
    if (geometry.faces[f].kind == FaceKind::boundary && geometry.faces[f].patch == patch)
      force += geometry.faces[f].area * face_force_density(f);
  return Utilities::MPI::sum(force, geometry.comm());
}

template <int dim>
std::vector<Tensor<1, dim>> SolidSolver<dim>::vertex_displacements() const
{
  std::vector<Tensor<1, dim>> d(geometry.vertices().size());
  std::vector<double> values;
  for (unsigned int j = 0; j < dim; ++j)
  {
    const std::vector<double>* v = &vertex_u[j];
    if (parameters.variant != "present")
    {
      // The other variants do not use vertex values: reconstruct them (App. B) for the caller.
      FaceVector boundary_values(geometry.faces.size());
      for (unsigned int f = 0; f < geometry.faces.size(); ++f)
        boundary_values[f] = boundary_u[f][j];
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

template class SolidSolver<2>;
template class SolidSolver<3>;
} // namespace fvfsi
