// MeshMotion: prescribed and Laplace mesh motion of the ALE fluid (see mesh_motion.h).

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/numerics/rtree.h>

#include <fvfsi/ale/mesh_motion.h>
#include <fvfsi/base/parsed_function.h>
#include <fvfsi/base/patch_list.h>
#include <fvfsi/fv/deferred_correction.h>
#include <fvfsi/fv/face_loop.h>

#include <algorithm>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  const SelectionNames<MeshMotionParameters::Type> MeshMotionParameters::type_names = {
    {"none", Type::none}, {"prescribed", Type::prescribed}, {"Laplace", Type::laplace}};

  MeshMotionParameters::MeshMotionParameters()
  {
    solver.method = LinearSolverParameters::Method::cg;
    solver.preconditioner = LinearSolverParameters::Preconditioner::amg;
    solver.reduction = 1e-8;
  }

  void MeshMotionParameters::declare(ParameterHandler& prm)
  {
    prm.enter_subsection("Mesh motion");
    add_selection(prm, "Type", type, type_names,
                  "none: a fixed mesh; prescribed: every vertex moves by `Displacement`; "
                  "Laplace: the `Moving patches` move as given, the other boundaries are fixed, "
                  "the interior follows a Laplace equation with variable diffusivity.");
    prm.add_parameter(
      "Displacement", displacement,
      "prescribed: d(X, t) [m] of a vertex at reference position X, dim expressions "
      "of x, y[, z], t separated by `;`.");
    prm.add_parameter("Moving patches", moving_patches,
                      "Laplace: `patch: expressions | patch: expressions`, d(X, t) [m] of the "
                      "vertices of each moving patch (dim expressions of x, y[, z], t separated by "
                      "`;`).");
    add_selection(prm, "Diffusivity", diffusivity,
                  {{"quadratic inverse distance", Diffusivity::quadratic_inverse_distance},
                   {"inverse distance", Diffusivity::inverse_distance},
                   {"uniform", Diffusivity::uniform}},
                  "Laplace: gamma_f = 1 / max(r_f, d_fn)^2 with r_f the distance of the face "
                  "centre from the nearest moving-patch face (quadratic inverse distance), "
                  "1 / max(r_f, d_fn) (inverse distance: spreads the deformation more evenly "
                  "in narrow channels), or 1 (uniform).");
    prm.add_parameter("Sliding patches", sliding_patches,
                      "Laplace: comma-separated planar patches normal to x, y or z (a symmetry "
                      "plane) whose vertices slide in their plane: zero normal displacement, zero "
                      "normal gradient of the others. A vertex on a moving or fixed patch as well "
                      "follows that patch.");
    prm.add_parameter("Non-orthogonal correctors", non_orthogonal_correctors,
                      "Laplace: deferred-correction solves of Eq. 19's non-orthogonal part per "
                      "motion.",
                      Patterns::Integer(0, 100));
    prm.leave_subsection();
    solver.declare(prm, "Mesh motion solver");
  }

  template <int dim>
  MeshMotion<dim>::MeshMotion(const FVGeometry<dim>& reference,
                              const MeshParameters& mesh_parameters,
                              const MeshMotionParameters& parameters, const TimeControl& clock)
      : reference(reference), prm(parameters), clock(clock), operators(reference),
        vertex_dofs(reference.triangulation())
  {
    if (prm.type == MeshMotionParameters::Type::prescribed)
    {
      prescribed = std::make_unique<FunctionParser<dim>>(dim);
      initialize_function(*prescribed, prm.displacement, "Mesh motion/Displacement");
    }
    else if (prm.type == MeshMotionParameters::Type::laplace)
    {
      setup_patches(mesh_parameters);
      setup_sliding_patches(mesh_parameters);
      compute_diffusivity();
      setup_systems();
      for (unsigned int j = 0; j < dim; ++j)
      {
        d_cell[j] = reference.make_cell_vector();
        grad_d[j] = CellGradient<dim>(reference);
      }
      rhs_boundary = reference.make_cell_vector();

      const FESystem<dim> q1(FE_Q<dim>(1), dim);
      vertex_dofs.distribute_dofs(q1);
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(vertex_dofs, relevant);
      vertex_vector.reinit(vertex_dofs.locally_owned_dofs(), relevant, reference.comm());
      vertex_dof.resize(reference.vertices().size());
      for (const auto& cell : vertex_dofs.active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int j = 0; j < dim; ++j)
              vertex_dof[cell->vertex_index(v)][j] = cell->vertex_dof_index(v, j);
    }
    d_vertex.assign(reference.vertices().size(), Tensor<1, dim>());
  }

  template <int dim>
  void MeshMotion<dim>::setup_patches(const MeshParameters& mesh_parameters)
  {
    for (const auto& [name, expression] :
         parse_named_values(prm.moving_patches, "Mesh motion/Moving patches"))
    {
      MovingPatch patch;
      patch.name = name;
      patch.id = mesh_parameters.patch_id(name, "Mesh motion/Moving patches");
      patch.expression = std::make_unique<FunctionParser<dim>>(dim);
      initialize_function(*patch.expression, expression, "Mesh motion/Moving patches");
      moving.push_back(std::move(patch));
    }
    if (moving.empty())
      throw std::runtime_error(
        "Mesh motion/Moving patches: Type = Laplace needs at least one patch");
    for (auto& patch : moving)
    {
      for_each_stored_boundary_face(
        reference,
        [&patch](const unsigned int, const FaceGeometry<dim>& face)
        {
          if (face.patch == patch.id)
            patch.vertices.insert(patch.vertices.end(), face.vertices.begin(), face.vertices.end());
        });
      std::sort(patch.vertices.begin(), patch.vertices.end());
      patch.vertices.erase(std::unique(patch.vertices.begin(), patch.vertices.end()),
                           patch.vertices.end());
    }
    // Every boundary but the sliding patches is Dirichlet: the moving patches' displacement,
    // zero elsewhere.
    boundary_vertex.assign(reference.vertices().size(), -1);
    std::set<unsigned int> sliding;
    for (const auto& name : parse_names(prm.sliding_patches))
      sliding.insert(mesh_parameters.patch_id(name, "Mesh motion/Sliding patches"));
    for_each_stored_boundary_face(reference,
                                  [&](const unsigned int, const FaceGeometry<dim>& face)
                                  {
                                    if (sliding.count(face.patch) > 0)
                                      return;
                                    for (unsigned int j = 0; j < dim; ++j)
                                      bc[j].patch_type[face.patch] = BoundaryType::dirichlet;
                                    bool is_moving = false;
                                    for (const auto& patch : moving)
                                      is_moving = is_moving || patch.id == face.patch;
                                    for (const unsigned int v : face.vertices)
                                      boundary_vertex[v] =
                                        std::max(boundary_vertex[v], is_moving ? 1 : 0);
                                  });
    for (unsigned int j = 0; j < dim; ++j)
      bc[j].value.assign(reference.faces.size(), 0.0);
    face_values.assign(reference.faces.size(), 0.0);
  }

  template <int dim>
  void MeshMotion<dim>::setup_sliding_patches(const MeshParameters& mesh_parameters)
  {
    // Each sliding patch's normal axis: the area-weighted |n_k| summed over all ranks' faces
    // must equal the patch's area for one k (a plane normal to x, y or z).
    fixed_components.assign(reference.vertices().size(), 0);
    for (const auto& name : parse_names(prm.sliding_patches))
    {
      const unsigned int id = mesh_parameters.patch_id(name, "Mesh motion/Sliding patches");
      for (const auto& patch : moving)
        if (patch.id == id)
          throw std::runtime_error("Mesh motion: patch `" + name +
                                   "` is both a Moving and a Sliding patch");
      std::array<double, dim + 1> sums{}; // area |n_k| per k, then the area
      for_each_patch_face(reference, id,
                          [&sums](const unsigned int, const FaceGeometry<dim>& face)
                          {
                            for (unsigned int k = 0; k < dim; ++k)
                              sums[k] += face.area * std::abs(face.n[k]);
                            sums[dim] += face.area;
                          });
      Utilities::MPI::sum(ArrayView<const double>(sums.data(), sums.size()), reference.comm(),
                          ArrayView<double>(sums.data(), sums.size()));
      const unsigned int axis = std::max_element(sums.begin(), sums.begin() + dim) - sums.begin();
      if (!(sums[dim] > 0) || std::abs(sums[axis] - sums[dim]) > 1e-10 * sums[dim])
        throw std::runtime_error("Mesh motion/Sliding patches: patch `" + name +
                                 "` is not a plane normal to x, y or z (or has no faces)");
      sliding_axis[id] = axis;
      for (unsigned int j = 0; j < dim; ++j)
        bc[j].patch_type[id] = j == axis ? BoundaryType::dirichlet : BoundaryType::neumann;
      for_each_stored_boundary_face(reference,
                                    [&](const unsigned int, const FaceGeometry<dim>& face)
                                    {
                                      if (face.patch == id)
                                        for (const unsigned int v : face.vertices)
                                          fixed_components[v] |= 1u << axis;
                                    });
    }
  }

  template <int dim>
  void MeshMotion<dim>::setup_systems()
  {
    // The matrices never change: one AMG set-up each for the whole run. Components whose
    // boundary types agree share a matrix.
    for (unsigned int j = 0; j < dim; ++j)
    {
      bool shared = false;
      for (unsigned int i = 0; i < j && !shared; ++i)
        if (bc[i].patch_type == bc[j].patch_type)
        {
          system_of[j] = system_of[i];
          shared = true;
        }
      if (shared)
        continue;
      auto matrix = std::make_unique<TrilinosWrappers::SparseMatrix>();
      operators.laplacian.reinit_matrix(*matrix);
      CellVector unused = reference.make_cell_vector();
      operators.laplacian.assemble(gamma, bc[j], *matrix, unused);
      matrix->compress(VectorOperation::add);
      solvers.push_back(std::make_unique<LinearSolver>(prm.solver));
      solvers.back()->initialize(*matrix);
      matrices.push_back(std::move(matrix));
      system_of[j] = matrices.size() - 1;
    }
  }

  template <int dim>
  void MeshMotion<dim>::compute_diffusivity()
  {
    gamma.assign(reference.faces.size(), 1.0);
    using Diffusivity = MeshMotionParameters::Diffusivity;
    if (prm.diffusivity == Diffusivity::uniform)
      return;
    // Centres of all moving-patch faces, from every rank, in an R-tree for nearest queries.
    std::vector<Point<dim>> local;
    for (const auto& patch : moving)
      for_each_patch_face(reference, patch.id,
                          [&local](const unsigned int, const FaceGeometry<dim>& face)
                          { local.push_back(face.centre); });
    std::vector<Point<dim>> centres;
    for (const auto& part : Utilities::MPI::all_gather(reference.comm(), local))
      centres.insert(centres.end(), part.begin(), part.end());
    const auto tree = pack_rtree(centres);
    for_each_stored_face(
      reference,
      [&](const unsigned int f, const FaceGeometry<dim>& face)
      {
        std::vector<Point<dim>> nearest;
        tree.query(boost::geometry::index::nearest(face.centre, 1), std::back_inserter(nearest));
        const double r = std::max(face.centre.distance(nearest[0]), face.d_n);
        gamma[f] = prm.diffusivity == Diffusivity::inverse_distance ? 1 / r : 1 / (r * r);
      });
  }

  template <int dim>
  typename MeshMotion<dim>::MovingPatch& MeshMotion<dim>::moving_patch(const std::string& name)
  {
    for (auto& patch : moving)
      if (patch.name == name)
        return patch;
    throw std::runtime_error("Mesh motion: `" + name +
                             "` is not one of the Moving patches (list it there to move it)");
  }

  template <int dim>
  const std::vector<unsigned int>& MeshMotion<dim>::patch_vertices(const std::string& name)
  {
    return moving_patch(name).vertices;
  }

  template <int dim>
  void MeshMotion<dim>::set_patch_displacement(const std::string& name,
                                               const std::vector<Tensor<1, dim>>& displacement)
  {
    if (prm.type != MeshMotionParameters::Type::laplace)
      throw std::runtime_error("Mesh motion: set_patch_displacement needs Type = Laplace");
    AssertDimension(displacement.size(), reference.vertices().size());
    MovingPatch& patch = moving_patch(name);
    patch.expression.reset(); // from now on the given values
    patch.given = displacement;
  }

  template <int dim>
  void MeshMotion<dim>::boundary_vertex_displacements(const double t)
  {
    // Moving vertices from their patch's expression; fixed boundary vertices stay.
    const auto& X = reference.vertices();
    for (auto& patch : moving)
      if (patch.expression)
        patch.expression->set_time(t);
    for (const auto& patch : moving)
      for (const unsigned int v : patch.vertices)
        for (unsigned int j = 0; j < dim; ++j)
          d_vertex[v][j] = patch.expression ? checked_value(*patch.expression, X[v], j,
                                                            "Mesh motion/Moving patches")
                                            : patch.given[v][j];
    for (unsigned int v = 0; v < d_vertex.size(); ++v)
      if (boundary_vertex[v] == 0)
        d_vertex[v] = Tensor<1, dim>();
  }

  template <int dim>
  void MeshMotion<dim>::solve_laplace()
  {
    // Per component: Dirichlet values on the boundary faces (the average of their vertices'),
    // zero normal gradient on the sliding patches' faces for the in-plane components, deferred
    // non-orthogonal corrections, then the vertex values by least squares (App. B).
    linear_iterations = 0;
    std::vector<double> vertex_values(d_vertex.size());
    for (unsigned int j = 0; j < dim; ++j)
    {
      rhs_boundary = 0;
      for_each_stored_boundary_face(reference,
                                    [&](const unsigned int f, const FaceGeometry<dim>& face)
                                    {
                                      if (bc[j].type(face) == BoundaryType::neumann)
                                        return; // a zero normal gradient: bc[j].value stays 0
                                      double value = 0;
                                      for (const unsigned int v : face.vertices)
                                        value += d_vertex[v][j] / face.vertices.size();
                                      bc[j].value[f] = value;
                                      face_values[f] = value;
                                    });
      // Eq. 23 on the owned boundary faces, as Laplacian::assemble adds it.
      for (const unsigned int f : reference.boundary_faces())
      {
        const auto& face = reference.faces[f];
        if (bc[j].type(face) == BoundaryType::dirichlet)
          rhs_boundary.local_element(face.P) += gamma[f] * face.area / face.d_n * bc[j].value[f];
      }
      const auto neumann_face_values = [&]()
      {
        if (sliding_axis.empty())
          return;
        for (const unsigned int f : reference.all_boundary_faces())
          if (bc[j].type(reference.faces[f]) == BoundaryType::neumann)
            face_values[f] = operators.laplacian.boundary_value(f, d_cell[j], grad_d[j], bc[j]);
      };
      DeferredCorrection control;
      control.max_iterations = prm.non_orthogonal_correctors + 1;
      const auto result = solve_deferred_correction(
        control, *solvers[system_of[j]], *matrices[system_of[j]], rhs_boundary, d_cell[j],
        [&](CellVector& rhs) { operators.laplacian.add_correction(gamma, bc[j], grad_d[j], rhs); },
        [&]()
        {
          neumann_face_values();
          operators.gradient(d_cell[j], face_values, vertex_values, grad_d[j]);
        },
        "mesh motion, component " + std::to_string(j));
      linear_iterations += result.linear_iterations;
      for (const unsigned int v : operators.vertex_interpolation.vertices())
        if (boundary_vertex[v] < 0)
          d_vertex[v][j] = (fixed_components[v] >> j) & 1u ? 0.0 : vertex_values[v];
    }
    exchange_vertex_displacements();
  }

  template <int dim>
  void MeshMotion<dim>::exchange_vertex_displacements()
  {
    // Every rank computed the same values for the vertices its owned cells share (App. B stencils
    // lie in the ghost layer); the owner of each vertex dof sends its value to the ghosts.
    const IndexSet& owned = vertex_dofs.locally_owned_dofs();
    for (const unsigned int v : operators.vertex_interpolation.vertices())
      for (unsigned int j = 0; j < dim; ++j)
        if (owned.is_element(vertex_dof[v][j]))
          vertex_vector[vertex_dof[v][j]] = d_vertex[v][j];
    vertex_vector.update_ghost_values();
    for (const auto& cell : vertex_dofs.active_cell_iterators())
      if (cell->is_ghost())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int j = 0; j < dim; ++j)
            d_vertex[cell->vertex_index(v)][j] =
              vertex_vector[vertex_dof[cell->vertex_index(v)][j]];
  }

  template <int dim>
  void MeshMotion<dim>::checkpoint(MeshArchive<dim>& archive)
  {
    // Only the Laplace motion has a state (the last solution, the warm start of the next solve);
    // a prescribed motion's vectors are empty.
    if (prm.type != MeshMotionParameters::Type::laplace)
      return;
    for (unsigned int j = 0; j < dim; ++j)
    {
      archive.cells(d_cell[j]);
      for (auto& component : grad_d[j].components)
        archive.cells(component);
      if (archive.loading())
        grad_d[j].update_ghost_values();
    }
  }

  template <int dim>
  std::vector<Point<dim>> MeshMotion<dim>::vertex_positions()
  {
    const double t = clock.time();
    std::vector<Point<dim>> x = reference.vertices();
    if (prm.type == MeshMotionParameters::Type::prescribed)
    {
      prescribed->set_time(t);
      for (unsigned int v = 0; v < x.size(); ++v)
        for (unsigned int j = 0; j < dim; ++j)
          x[v][j] +=
            checked_value(*prescribed, reference.vertices()[v], j, "Mesh motion/Displacement");
      return x;
    }
    if (prm.type == MeshMotionParameters::Type::laplace)
    {
      boundary_vertex_displacements(t);
      solve_laplace();
      for (unsigned int v = 0; v < x.size(); ++v)
        x[v] += d_vertex[v];
    }
    return x;
  }

  template <int dim>
  double min_volume_ratio(const FVGeometry<dim>& moved, const FVGeometry<dim>& reference,
                          const double t)
  {
    double min_ratio = std::numeric_limits<double>::max();
    Point<dim> worst;
    for (unsigned int c = 0; c < moved.n_owned_cells(); ++c)
      if (moved.cell_volume[c] / reference.cell_volume[c] < min_ratio)
      {
        min_ratio = moved.cell_volume[c] / reference.cell_volume[c];
        worst = reference.centroid[c];
      }
    const auto stats = Utilities::MPI::min_max_avg(min_ratio, moved.comm());
    worst = Utilities::MPI::broadcast(moved.comm(), worst, stats.min_index);
    if (stats.min > 0)
      return stats.min;
    std::ostringstream when, where; // six significant digits, as the progress lines
    when << t;
    where << worst;
    throw std::runtime_error("Mesh motion: a cell is inverted (volume <= 0) at t = " + when.str() +
                             " s, the cell with reference centroid (" + where.str() +
                             ") m; the displacement is too large for this mesh (try another Mesh "
                             "motion/Diffusivity, see doc/results/mesh_motion.md, or a finer "
                             "mesh near the moving patches)");
  }

  template double min_volume_ratio(const FVGeometry<2>&, const FVGeometry<2>&, double);
  template double min_volume_ratio(const FVGeometry<3>&, const FVGeometry<3>&, double);
  template class MeshMotion<2>;
  template class MeshMotion<3>;
} // namespace fvfsi
