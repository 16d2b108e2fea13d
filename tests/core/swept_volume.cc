// Swept volumes of moving faces (FVGeometry::swept_volumes), the mesh fluxes of the ALE fluid,
// 2D and 3D, serial and mpirun=2.
//
// Asserts, on randomly distorted meshes (distortion 0.25) whose vertices, boundary ones included,
// are moved by a smooth nonlinear map in three successive steps (cells are strongly sheared and
// 3D faces warped):
//  - discrete space conservation law: for every owned cell, sum over its faces of the swept
//    volume (sign: out of the cell) equals V_P(new) - V_P(old) as FVGeometry computes them;
//  - the boundary faces' swept volumes add up to the change of the domain volume;
//  - under a translation by t every face sweeps exactly S_f . t (a prism on the face).
//
// Tolerances: all three are identities in exact arithmetic. The errors are relative to V_P (first),
// the domain volume (second) and |S_f| |t| (third); they are round-off of sums of O(10) terms, measured
// <= 3e-15 (FVFSI_TEST_VERBOSE=1 prints them), checked against 1e-12.
#include "fv_core_test_tools.h"

#include <cmath>

using namespace fvfsi_core_test;

template <int dim>
Point<dim> moved(const Point<dim>& x, const unsigned int step)
{
  // A smooth map far from the identity: shear, bulge and rotation-like terms of 5-10% per step.
  Point<dim> y = x;
  const double s = 0.05 * (step + 1);
  y[0] += s * std::sin(numbers::PI * x[1]) + 0.5 * s * x[0] * x[0];
  y[1] += s * std::cos(2 * x[0]) * x[1] - 0.3 * s * x[0];
  if constexpr (dim == 3)
    y[2] += s * std::sin(x[0] + x[1]) * x[2] + 0.2 * s * x[1] * x[1];
  return y;
}

template <int dim>
void run(std::ofstream& out)
{
  TestMesh<dim> mesh(out, "subdivided_hyper_cube", dim == 2 ? "12: 0: 1: false" : "5: 0: 1: false",
                     1);
  fvfsi::FVGeometry<dim>& fv = *mesh.fv;
  out << dim << "D: " << fv.n_global_cells() << " cells" << std::endl;

  const auto total_volume = [&fv]()
  {
    double V = 0;
    for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
      V += fv.cell_volume[c];
    return Utilities::MPI::sum(V, MPI_COMM_WORLD);
  };

  double cell_error = 0, domain_error = 0;
  for (unsigned int step = 0; step < 3; ++step)
  {
    std::vector<Point<dim>> y = fv.vertices();
    for (auto& p : y)
      p = moved(p, step);
    const std::vector<double> V_old = fv.cell_volume;
    const double domain_old = total_volume();
    const std::vector<double> dV = fv.swept_volumes(fv.vertices(), y);
    fv.reinit(y);

    std::vector<double> net(fv.n_owned_cells(), 0.0);
    double boundary = 0;
    for (unsigned int f = 0; f < fv.faces.size(); ++f)
    {
      const auto& face = fv.faces[f];
      if (face.kind == fvfsi::FaceKind::ghost_boundary)
        continue;
      net[face.P] += dV[f];
      if (face.kind == fvfsi::FaceKind::interior)
        net[face.N] -= dV[f];
      if (face.kind == fvfsi::FaceKind::boundary)
        boundary += dV[f];
    }
    for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
      cell_error =
        std::max(cell_error, std::abs(net[c] - (fv.cell_volume[c] - V_old[c])) / fv.cell_volume[c]);
    const double domain_new = total_volume();
    domain_error = std::max(domain_error, std::abs(Utilities::MPI::sum(boundary, MPI_COMM_WORLD) -
                                                   (domain_new - domain_old)) /
                                            domain_new);
  }
  check(out, format("%dD: sum_f dV_f = V_P(new) - V_P(old) in every cell, 3 steps", dim),
        cell_error, 1e-12);
  check(out, format("%dD: boundary swept volumes = change of the domain volume", dim), domain_error,
        1e-12);

  Tensor<1, dim> t;
  for (unsigned int d = 0; d < dim; ++d)
    t[d] = 0.03 * (d + 1);
  std::vector<Point<dim>> y = fv.vertices();
  for (auto& p : y)
    p += t;
  const std::vector<double> dV = fv.swept_volumes(fv.vertices(), y);
  double translation_error = 0;
  for (unsigned int f = 0; f < fv.faces.size(); ++f)
    translation_error = std::max(translation_error, std::abs(dV[f] - fv.faces[f].S * t) /
                                                      (fv.faces[f].area * t.norm()));
  check(out, format("%dD: a translation by t sweeps S_f . t", dim), translation_error, 1e-12);
}

int main(int argc, char** argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  run<2>(out);
  run<3>(out);
}
