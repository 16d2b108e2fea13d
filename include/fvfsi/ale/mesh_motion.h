#pragma once
// Mesh motion for the ALE fluid: where the vertices of the fluid mesh are at time t.
//
//  - `prescribed`: every vertex moves by a given displacement d(X, t) of its reference position X
//    (tests, forced motions);
//  - `Laplace`: the moving patches have a given displacement d(X, t) (an expression or, for
//    fluid-structure interaction, values set from outside per boundary vertex), every other
//    boundary is fixed, and the interior follows the Laplace equation div(gamma grad d) = 0 with a
//    variable diffusivity that stiffens the mesh near the moving patches,
//      gamma_f = 1 / max(r_f, r_min)^2   (quadratic inverse distance, r_f from the face centre to
//                                         the nearest moving-patch face centre, r_min a cell size;
//                                         or 1 / max(r_f, r_min), or 1),
//    so that the small cells there move almost rigidly and the large ones far away absorb the
//    deformation. It is discretised on the cells by the same FV Laplacian as everything else
//    (Eq. 19 with deferred non-orthogonal correction), on the reference (undeformed) mesh: the
//    matrix never changes and its AMG preconditioner is built once. The cell displacements are
//    carried to the vertices by the least-squares reconstruction of Appendix B; boundary vertices
//    take their prescribed displacement exactly (a vertex shared by a moving and a fixed patch
//    follows the moving one). `Sliding patches` (planes normal to x, y or z, such as a symmetry
//    plane) let their vertices slide in the plane: the normal component is zero there, the
//    others have a zero normal gradient, so the cells next to a moving patch that meets the plane
//    are not squeezed against fixed vertices.
//
// The class knows nothing about the fluid: it returns vertex positions at the time of the scene's
// clock, which a driver passes to FVGeometry::swept_volumes, FVGeometry::reinit and
// FluidSolver::move_mesh. Every Laplace solve starts from the last one's cell displacements (a
// warm start: between time steps or coupling iterations they change little).

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/base/selection.h>
#include <fvfsi/base/time_control.h>
#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/fv/fv_operators.h>
#include <fvfsi/fv/gradients.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/linear_solver.h>
#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/io/checkpoint.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_parameters.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fvfsi
{
  struct MeshMotionParameters
  {
    enum class Type
    {
      none,       ///< a fixed mesh
      prescribed, ///< every vertex by a given displacement
      laplace     ///< moving patches given, the interior by a Laplace equation
    };
    enum class Diffusivity
    {
      quadratic_inverse_distance, ///< 1 / max(r, d_fn)^2
      inverse_distance,           ///< 1 / max(r, d_fn)
      uniform                     ///< 1
    };
    static const SelectionNames<Type> type_names;
    Type type = Type::none;
    /// prescribed: dim expressions of the reference position x, y[, z] and t [m].
    std::string displacement = "";
    /// Laplace: `patch: expressions | patch: expressions`, the displacement of moving patches.
    std::string moving_patches = "";
    /// Laplace: comma-separated planar patches (normal to x, y or z) whose vertices slide.
    std::string sliding_patches = "";
    Diffusivity diffusivity = Diffusivity::inverse_distance;
    unsigned int non_orthogonal_correctors = 2;
    LinearSolverParameters solver;

    MeshMotionParameters();
    void declare(dealii::ParameterHandler& prm);
    bool moves() const { return type != Type::none; }
  };

  /// The smallest V_P / V_P(reference) over the cells of a moved mesh (collective). Throws,
  /// naming the worst cell by its reference centroid and the time t [s], if a cell is inverted
  /// (ratio <= 0).
  template <int dim>
  double min_volume_ratio(const FVGeometry<dim>& moved, const FVGeometry<dim>& reference, double t);

  template <int dim>
  class MeshMotion
  {
  public:
    /// `reference` is a geometry of the undeformed mesh that is never moved; `clock` the scene's.
    MeshMotion(const FVGeometry<dim>& reference, const MeshParameters& mesh_parameters,
               const MeshMotionParameters& parameters, const TimeControl& clock);

    /// The vertices (triangulation indices) of a moving patch that this rank's cells touch: the
    /// entries set_patch_displacement reads.
    const std::vector<unsigned int>& patch_vertices(const std::string& patch);

    /// Laplace: set the displacement [m] of the vertices of a moving patch from outside (e.g. the
    /// solid's interface displacement), replacing the patch's expression from then on. Indexed
    /// like the triangulation's vertices; only the entries of patch_vertices(patch) are read.
    /// Throws if the patch is not one of the Moving patches.
    void set_patch_displacement(const std::string& patch,
                                const std::vector<dealii::Tensor<1, dim>>& vertex_displacement);

    /// The vertex positions at the clock's time (indexed like the triangulation's vertices;
    /// vertices of no locally relevant cell stay where they are).
    std::vector<dealii::Point<dim>> vertex_positions();

    /// Save or load the last solve's cell displacements and their gradients (the next solve
    /// starts from them); see io/checkpoint.h.
    void checkpoint(MeshArchive<dim>& archive);

    /// Linear iterations of the last Laplace solve (all components and corrections).
    unsigned int last_linear_iterations() const { return linear_iterations; }

  private:
    void setup_patches(const MeshParameters& mesh_parameters);
    void setup_sliding_patches(const MeshParameters& mesh_parameters);
    void setup_systems();
    void compute_diffusivity();
    void boundary_vertex_displacements(double t);
    void solve_laplace();

    const FVGeometry<dim>& reference;
    MeshMotionParameters prm;
    const TimeControl& clock;
    std::unique_ptr<dealii::FunctionParser<dim>> prescribed;

    // Laplace.
    struct MovingPatch
    {
      std::string name;
      unsigned int id;
      std::unique_ptr<dealii::FunctionParser<dim>> expression; ///< null when set from outside
      std::vector<dealii::Tensor<1, dim>> given; ///< per vertex, when set from outside
      std::vector<unsigned int> vertices; ///< the patch's vertices of this rank's cells, sorted
    };
    std::vector<MovingPatch> moving;
    MovingPatch& moving_patch(const std::string& name);
    FVOperators<dim> operators; ///< on the reference mesh
    // One matrix and AMG preconditioner per distinct set of boundary types: components normal to
    // no sliding patch share the all-Dirichlet one.
    std::vector<std::unique_ptr<dealii::TrilinosWrappers::SparseMatrix>> matrices;
    std::vector<std::unique_ptr<LinearSolver>> solvers;
    std::array<unsigned int, dim> system_of; ///< component -> index into matrices, solvers
    CellVector rhs_boundary; ///< the Dirichlet sources of the assembled matrix, per unit value
    FaceVector gamma;
    std::array<ScalarBoundaryConditions<dim>, dim> bc; ///< per component
    FaceVector face_values; ///< boundary face values of the component being solved
    /// Per sliding patch id: the axis of its normal.
    std::map<unsigned int, unsigned int> sliding_axis;
    /// Per vertex: bit j set if component j is held at zero by a sliding patch.
    std::vector<unsigned int> fixed_components;
    std::array<CellVector, dim> d_cell; ///< cell displacements (last solve)
    std::array<CellGradient<dim>, dim> grad_d;
    std::vector<dealii::Tensor<1, dim>> d_vertex; ///< vertex displacements
    std::vector<int> boundary_vertex;             ///< -1 interior, else 0 fixed / 1 moving
    // Vertex values of ghost cells whose vertices no owned cell shares come from their owner,
    // through the vertex dofs of an FE_Q(1)^dim DoFHandler (a ghosted vector).
    dealii::DoFHandler<dim> vertex_dofs;
    std::vector<std::array<dealii::types::global_dof_index, dim>> vertex_dof; ///< per vertex
    dealii::LinearAlgebra::distributed::Vector<double> vertex_vector;
    void exchange_vertex_displacements();
    unsigned int linear_iterations = 0;
  };
} // namespace fvfsi
