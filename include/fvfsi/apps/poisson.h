#pragma once
// The Poisson scene: -div(Gamma grad phi) = s on a distributed mesh, with a manufactured exact
// solution, solved by the FV Laplacian with deferred non-orthogonal correction. It verifies the FV
// core (geometry, vertex reconstruction, gradients, Laplacian) and is fvfsi's default scene.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/gradients.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/linear_solver.h>
#include <fvfsi/fv/quadratic_reconstruction.h>
#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/io/summary.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace fvfsi
{
  struct PoissonParameters
  {
    double diffusivity = 1.0; ///< Gamma [m^2/s]
    /// Exact solution phi(x, y[, z]) for Dirichlet values and errors; gradient for Neumann faces.
    std::string exact_solution = "exp(x)*sin(pi*y)";
    std::string exact_gradient = "exp(x)*sin(pi*y); pi*exp(x)*cos(pi*y)";
    std::string source = "(pi^2 - 1)*exp(x)*sin(pi*y)"; ///< s = -div(Gamma grad phi)
    std::vector<std::string> neumann_patches = {"right"};
    /// The Laplacian's face normal gradient: "linear" (Eq. 19 with vertex Gauss-Green gradients)
    /// or "quadratic" (with the gradient and Hessian of a quadratic least-squares reconstruction).
    std::string face_gradient = "linear";
    unsigned int max_correction_iterations = 100;
    double correction_tolerance = 1e-10;
    LinearSolverParameters solver;

    void declare(dealii::ParameterHandler& prm);
  };

  /// What a Poisson run found.
  struct PoissonResults
  {
    dealii::types::global_cell_index n_cells = 0;
    double h = 0;                     ///< (domain measure / n_cells)^(1/dim) [m]
    double max_cell_error = 0;        ///< max_P |phi_P - phi(r_P)|
    double l2_cell_error = 0;         ///< sqrt(sum_P V_P (phi_P - phi(r_P))^2)
    /// max over interior faces of |n_f . (grad phi)_f - n_f . grad phi(r_f)| (Eq. 19)
    double max_face_gradient_error = 0;
    /// sqrt(sum_f e_f^2 S_f d_fn) over interior faces, e_f the error above
    double l2_face_gradient_error = 0;
    /// the same over Dirichlet boundary faces (Eq. 23, a one-sided difference: first order)
    double max_boundary_face_gradient_error = 0;
    unsigned int correction_iterations = 0;
    unsigned int linear_iterations = 0;
  };

  template <int dim>
  class PoissonProblem
  {
  public:
    PoissonProblem(const MeshParameters& mesh_parameters, const PoissonParameters& parameters,
                   MPI_Comm comm, const std::string& prm_directory = ".");

    /// make_grid, setup_system, then assemble and solve with deferred correction.
    void run();
    const PoissonResults& results() const { return result; }
    /// VTU of phi, the exact solution and the error, and summary.json, into `directory`.
    void output_results(const std::string& directory, Summary& summary) const;

    const FVGeometry<dim>& geometry() const { return *fv; }
    const CellVector& solution() const { return phi; }

  private:
    void make_grid();
    void setup_system();
    void assemble_system();
    void solve();
    /// The explicit part of the Laplacian with the current grad (and hessian), added to rhs.
    void add_correction(CellVector& rhs) const;
    /// grad (and hessian) from the current phi: vertex Gauss-Green or quadratic reconstruction.
    void update_gradients();
    /// n_f . (grad phi)_f of the Laplacian's face normal gradient.
    double normal_gradient(unsigned int f) const;
    void compute_errors();

    MPI_Comm comm;
    MeshParameters mesh_parameters;
    PoissonParameters parameters;
    std::string prm_directory;
    dealii::ConditionalOStream pcout;

    dealii::parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<FVGeometry<dim>> fv;
    std::unique_ptr<VertexInterpolation<dim>> vertex_interpolation;
    std::unique_ptr<QuadraticReconstruction<dim>> quadratic_reconstruction; ///< quadratic only
    std::unique_ptr<Laplacian<dim>> laplacian;
    dealii::FunctionParser<dim> exact, exact_gradient, source;

    ScalarBoundaryConditions<dim> bc;
    FaceVector gamma;
    dealii::TrilinosWrappers::SparseMatrix matrix;
    CellVector phi, rhs_fixed;
    CellGradient<dim> grad;
    CellHessian<dim> hessian; ///< FaceGradient::quadratic only
    std::vector<double> vertex_phi;
    PoissonResults result;
  };

  /// Parse a FunctionParser expression of x, y[, z], t; errors name the parameter.
  template <int dim>
  void initialize_function(dealii::FunctionParser<dim>& f, const std::string& expression,
                           const std::string& parameter_name);
} // namespace fvfsi
