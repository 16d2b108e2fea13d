#pragma once
// The FV operators of one mesh that every equation uses (paper section 3 and Appendices A-B):
// vertex values by least squares (App. B), the vertex-based Gauss-Green cell gradient (Eq. 37) and
// the Laplacian with Eq. 19's face gradient. Built once per mesh; reinit() after the mesh moves.

#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/fv/gradients.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/mesh/fv_geometry.h>

#include <vector>

namespace fvfsi
{
  template <int dim>
  class FVOperators
  {
  public:
    explicit FVOperators(const FVGeometry<dim>& geometry)
        : vertex_interpolation(geometry), gauss_green(geometry), laplacian(geometry)
    {
    }

    /// Recompute the coefficients of the vertex values and the gradient; call after
    /// FVGeometry::reinit().
    void reinit()
    {
      vertex_interpolation.reinit();
      gauss_green.reinit();
    }

    /// (grad phi)_P of every owned cell (ghosts updated) by Gauss-Green from the vertex values of
    /// phi (ghosts up to date) and its boundary values phi_b; the vertex values are kept in
    /// `vertex_values` (indexed like the triangulation's vertices).
    void gradient(const CellVector& phi, const FaceVector& boundary_values,
                  std::vector<double>& vertex_values, CellGradient<dim>& grad) const
    {
      vertex_interpolation.interpolate(phi, boundary_values, vertex_values);
      gauss_green.compute(vertex_values, grad);
    }

    VertexInterpolation<dim> vertex_interpolation;
    GaussGreenGradient<dim> gauss_green;
    Laplacian<dim> laplacian;
  };
} // namespace fvfsi
