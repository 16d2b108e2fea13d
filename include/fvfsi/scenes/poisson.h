#pragma once
// The Poisson scene: -div(Gamma grad phi) = s on a distributed mesh, with a manufactured exact
// solution, solved by the FV Laplacian with deferred non-orthogonal correction. It verifies the FV
// core (geometry, vertex reconstruction, gradients, Laplacian): prm/poisson_2d.prm, poisson_3d.prm.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/gradients.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/linear_solver.h>
#include <fvfsi/fv/quadratic_fit.h>
#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/io/summary.h>
#include <fvfsi/io/vtu_output.h>
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
    /// The Laplacian's face normal gradient.
    enum class FaceGradient
    {
      linear,   ///< Eq. 19 with vertex Gauss-Green gradients: exact for linear fields
      quadratic ///< with the gradient and Hessian of a quadratic fit: exact for quadratics
    };
    FaceGradient face_gradient = FaceGradient::linear;
    unsigned int max_correction_iterations = 100;
    double correction_tolerance = 1e-10;
    LinearSolverParameters solver;

    void declare(dealii::ParameterHandler& prm);
  };

  /// What a Poisson run found.
  struct PoissonResults
  {
    dealii::types::global_cell_index n_cells = 0;
    double h = 0;              ///< (domain measure / n_cells)^(1/dim) [m]
    double max_cell_error = 0; ///< max_P |phi_P - phi(r_P)|
    double l2_cell_error = 0;  ///< sqrt(sum_P V_P (phi_P - phi(r_P))^2)
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
    /// grad (and hessian) from the current phi: vertex Gauss-Green or quadratic fit.
    void update_gradients();
    /// The Hessian of the quadratic face gradient, or none (Eq. 19).
    const CellHessian<dim>* hessian_or_null() const { return quadratic_fit ? &hessian : nullptr; }
    void compute_errors();

    MPI_Comm comm;
    MeshParameters mesh_parameters;
    PoissonParameters parameters;
    std::string prm_directory;
    dealii::ConditionalOStream pcout;

    dealii::parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<FVGeometry<dim>> fv;
    std::unique_ptr<VertexInterpolation<dim>> vertex_interpolation;
    std::unique_ptr<GaussGreenGradient<dim>> gauss_green;
    std::unique_ptr<QuadraticFit<dim>> quadratic_fit; ///< FaceGradient::quadratic only
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

} // namespace fvfsi
