#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <fvfsi/fv/face_loop.h>
#include <fvfsi/fv/laplacian.h>

#include <stdexcept>

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
  double Laplacian<dim>::explicit_part(const FaceGeometry<dim>& face, const CellGradient<dim>& grad,
                                       const CellHessian<dim>* hessian) const
  {
    if (!hessian) // Eq. 19: exact for linear fields
    {
      double k_dot_grad = face.k_P * grad[face.P];
      if (face.N != invalid_cell)
        k_dot_grad += face.k_N * grad[face.N];
      return -k_dot_grad;
    }
    // phi(P') - phi_P: P' = r_P + k_P lies on the normal line, d_Pn = n . (r_f - r_P) behind r_f.
    const SymmetricTensor<2, dim> H_P = (*hessian)[face.P];
    const double dphi_P = face.k_P * grad[face.P] + 0.5 * (face.k_P * (H_P * face.k_P));
    if (face.N == invalid_cell) // Dirichlet form, d_fn = d_Pn
      return -dphi_P + 0.5 * face.d_n * face.d_n * (face.n * (H_P * face.n));

    // phi(N') - phi_N: N' = r_N - k_N lies on the normal line, d_Nn = d_fn - d_Pn ahead of r_f.
    const SymmetricTensor<2, dim> H_N = (*hessian)[face.N];
    const double dphi_N = -(face.k_N * grad[face.N]) + 0.5 * (face.k_N * (H_N * face.k_N));
    const double d_Pn = face.n * (face.centre - geometry.centroid[face.P]);
    const double d_Nn = face.d_n - d_Pn;
    const SymmetricTensor<2, dim> H_f = face.interpolate(H_P, H_N);
    return dphi_N - dphi_P - 0.5 * face.d_n * (d_Nn - d_Pn) * (face.n * (H_f * face.n));
  }

  template <int dim>
  void Laplacian<dim>::add_correction(const FaceVector& gamma,
                                      const ScalarBoundaryConditions<dim>& bc,
                                      const CellGradient<dim>& grad, CellVector& rhs,
                                      const CellHessian<dim>* hessian) const
  {
    for_each_face(geometry,
                  [&](const unsigned int f, const FaceGeometry<dim>& face)
                  {
                    if (face.N == invalid_cell && bc.type(face) == BoundaryType::neumann)
                      return;
                    // The explicit flux Gamma S_f (explicit part / d_fn) enters P (it is on the
                    // side of phi_N) and leaves N.
                    add_outflow(
                      face, gamma[f] * face.area * explicit_part(face, grad, hessian) / face.d_n,
                      rhs);
                  });
  }

  template <int dim>
  double Laplacian<dim>::normal_gradient(const unsigned int f, const CellVector& phi,
                                         const CellGradient<dim>& grad,
                                         const ScalarBoundaryConditions<dim>& bc,
                                         const CellHessian<dim>* hessian) const
  {
    const auto& face = geometry.faces[f];
    if (face.N == invalid_cell && bc.type(face) == BoundaryType::neumann)
      return bc.value[f];
    const double phi_other = face.N != invalid_cell ? phi.local_element(face.N) : bc.value[f];
    return (phi_other - phi.local_element(face.P) + explicit_part(face, grad, hessian)) / face.d_n;
  }

  template <int dim>
  FaceVector Laplacian<dim>::boundary_values(const CellVector& phi, const CellGradient<dim>& grad,
                                             const ScalarBoundaryConditions<dim>& bc,
                                             const CellHessian<dim>* hessian) const
  {
    FaceVector values(geometry.faces.size(), 0.0);
    for (unsigned int f = 0; f < geometry.faces.size(); ++f)
      if (geometry.faces[f].N == invalid_cell)
        values[f] = boundary_value(f, phi, grad, bc, hessian);
    return values;
  }

  template <int dim>
  double Laplacian<dim>::boundary_value(const unsigned int f, const CellVector& phi,
                                        const CellGradient<dim>& grad,
                                        const ScalarBoundaryConditions<dim>& bc,
                                        const CellHessian<dim>* hessian) const
  {
    const auto& face = geometry.faces[f];
    Assert(face.N == invalid_cell, ExcMessage("boundary_value() of an interior face"));
    // Neumann: solve the Dirichlet form g = (phi_b - phi_P + explicit part) / d_fn for phi_b.
    return bc.type(face) == BoundaryType::dirichlet
             ? bc.value[f]
             : phi.local_element(face.P) + face.d_n * bc.value[f] -
                 explicit_part(face, grad, hessian);
  }

  template class Laplacian<2>;
  template class Laplacian<3>;
} // namespace fvfsi
