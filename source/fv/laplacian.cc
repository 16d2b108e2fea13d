#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <fvfsi/fv/laplacian.h>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  Laplacian<dim>::Laplacian(const FVGeometry<dim>& geometry) : geometry(geometry)
  {
  }

  template <int dim>
  void Laplacian<dim>::reinit_matrix(TrilinosWrappers::SparseMatrix& matrix) const
  {
    const auto& part = *geometry.partitioner();
    const IndexSet& owned = part.locally_owned_range();
    IndexSet relevant = owned;
    relevant.add_indices(part.ghost_indices());
    DynamicSparsityPattern dsp(relevant);
    for (unsigned int c = 0; c < geometry.n_owned_cells(); ++c)
      dsp.add(geometry.global_index(c), geometry.global_index(c));
    for (const auto& face : geometry.faces)
      if (face.kind == FaceKind::interior || face.kind == FaceKind::processor)
      {
        const auto P = geometry.global_index(face.P), N = geometry.global_index(face.N);
        dsp.add(P, N);
        if (face.kind == FaceKind::interior)
          dsp.add(N, P);
      }
    SparsityTools::distribute_sparsity_pattern(dsp, owned, geometry.comm(), relevant);
    matrix.reinit(owned, owned, dsp, geometry.comm());
  }

  template <int dim>
  void Laplacian<dim>::assemble(const FaceVector& gamma, const ScalarBoundaryConditions<dim>& bc,
                                TrilinosWrappers::SparseMatrix& matrix, CellVector& rhs) const
  {
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
    {
      const auto& face = geometry.faces[f];
      const double a = gamma[f] * face.area / face.d_n; // |a_N| of Eq. 27
      const auto P = geometry.global_index(face.P);
      switch (face.kind)
      {
      case FaceKind::interior:
        matrix.add(P, P, a);
        matrix.add(P, geometry.global_index(face.N), -a);
        matrix.add(geometry.global_index(face.N), geometry.global_index(face.N), a);
        matrix.add(geometry.global_index(face.N), P, -a);
        break;
      case FaceKind::processor: // the other rank assembles the N row
        matrix.add(P, P, a);
        matrix.add(P, geometry.global_index(face.N), -a);
        break;
      case FaceKind::boundary:
        if (bc.type(face) == BoundaryType::dirichlet)
        {
          matrix.add(P, P, a);
          rhs.local_element(face.P) += a * bc.value[f];
        }
        else
          rhs.local_element(face.P) += gamma[f] * face.area * bc.value[f];
        break;
      case FaceKind::ghost_boundary:
        break;
      }
    }
  }

  template <int dim>
  void Laplacian<dim>::add_correction(const FaceVector& gamma, const ScalarBoundaryConditions<dim>& bc,
                                      const CellGradient<dim>& grad, CellVector& rhs) const
  {
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
    {
      const auto& face = geometry.faces[f];
      if (face.kind == FaceKind::ghost_boundary ||
          (face.kind == FaceKind::boundary && bc.type(face) == BoundaryType::neumann))
        continue;
      double k_dot_grad = face.k_P * grad[face.P];
      if (face.N != invalid_cell)
        k_dot_grad += face.k_N * grad[face.N];
      // The correction flux Gamma S_f (-(k . grad)/d_fn) leaves P and enters N.
      const double flux = -gamma[f] * face.area * k_dot_grad / face.d_n;
      rhs.local_element(face.P) += flux;
      if (face.kind == FaceKind::interior)
        rhs.local_element(face.N) -= flux;
    }
  }

  template <int dim>
  double Laplacian<dim>::normal_gradient(const unsigned int f, const CellVector& phi,
                                         const CellGradient<dim>& grad,
                                         const ScalarBoundaryConditions<dim>& bc) const
  {
    const auto& face = geometry.faces[f];
    const double phi_P = phi.local_element(face.P);
    if (face.N != invalid_cell)
      return (phi.local_element(face.N) - phi_P - face.k_N * grad[face.N] - face.k_P * grad[face.P]) /
             face.d_n;
    if (bc.type(face) == BoundaryType::neumann)
      return bc.value[f];
    return (bc.value[f] - phi_P - face.k_P * grad[face.P]) / face.d_n;
  }

  template <int dim>
  FaceVector Laplacian<dim>::boundary_values(const CellVector& phi, const CellGradient<dim>& grad,
                                             const ScalarBoundaryConditions<dim>& bc) const
  {
    FaceVector values(geometry.faces.size(), 0.0);
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
    {
      const auto& face = geometry.faces[f];
      if (face.N != invalid_cell)
        continue;
      values[f] = bc.type(face) == BoundaryType::dirichlet
                    ? bc.value[f]
                    : phi.local_element(face.P) + face.d_n * bc.value[f] + face.k_P * grad[face.P];
    }
    return values;
  }

  template class Laplacian<2>;
  template class Laplacian<3>;
} // namespace fvfsi
