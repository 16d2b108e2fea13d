// The thick plate in a channel (prm/thick_plate.prm, paper section 4.5) in 3D on its coarsest
// meshes: fluid h = 0.05 m (1 120 cells), plate h = 0.025 m (256 cells), steady FSI, IQN-ILS.
// Asserted:
//   (a) the steady coupled state in at most 4 coupling iterations (measured 3: the plate is
//       stiff, the added mass of a steady state zero), the plate bent downstream and lifted
//       (u_x(A), u_y(A) > 0), u_x(A) within 20% of the benchmark's 5.95e-5 m and F_x within 10%
//       of its 1.33 N (this coarse mesh: -13% and -7%; the shipped meshes meet 3%,
//       doc/results/fsi_3d.md);
//   (b) the large-deformation variant (E = 1e4 Pa, peak inflow 0.3 m/s) runs through with the
//       symmetry plane sliding (Mesh motion/Sliding patches): u_x(A) within 20% of the paper's
//       0.01463 m (this mesh: -14%; the shipped meshes -1%), every cell keeps more than half of
//       its volume (measured 0.89);
//   (c) np ranks equal one rank: every solve converged far below 1e-8 (linear solvers 1e-12,
//       the steady fluid to 1e-11, the solid's outer iterations to 1e-12, the coupling to 1e-11),
//       u(A) and the force within 1e-8 of their magnitudes (measured with np = 2: 1.8e-10 and
//       8e-12). The steady fluid's 1e-12 of earlier lay at its round-off: with the momentum
//       GMRES of deal.II the relative change of the np = 2 run oscillated between 1e-12 and
//       4e-12 and the fluid stopped with "no progress".
// With np = 1 (c) compares two identical runs. Verdicts and 6-digit values of the tight run only,
// so that NAME.output and NAME.mpirun=2.output are the same file.
#include "fsi_case.h"

#include <cmath>
#include <cstdio>

using namespace fvfsi_test;

const std::vector<std::string> coarse = {"Mesh/Generator arguments=0.05",
                                         "Solid mesh/Generator arguments=0.025"};
const std::vector<std::string> large = {
  "Solid/Young's modulus=1e4",
  "Fluid/Velocity inlet=inlet: 0.3*y*(0.4-y)*(0.16-z^2)/(0.04*0.16); 0; 0"};
const std::vector<std::string> tight = {"Fluid momentum solver/Residual reduction=1e-12",
                                        "Fluid pressure solver/Residual reduction=1e-12",
                                        "Mesh motion solver/Residual reduction=1e-12",
                                        "Solid linear solver/Residual reduction=1e-12",
                                        "Fluid/Steady tolerance=1e-11",
                                        "Solid/Outer tolerance=1e-12",
                                        "Coupling/Tolerance=1e-11"};

/// The last row of a run's fsi_steady_history.txt: coupling_iteration relative_residual
/// fluid_pseudo_steps solid_outer_iterations drag lift ux_A uy_A uz_A min_volume_ratio.
std::vector<double> result(const std::string& directory)
{
  const auto h = read_table(directory + "/fsi_steady_history.txt");
  return h.empty() ? std::vector<double>() : h.back();
}

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const MPI_Comm comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;

  const std::string error = run_fsi_case<3>("thick_plate", coarse, {}, comm, "out_shipped");
  const std::string error_large = run_fsi_case<3>("thick_plate", coarse, large, comm, "out_large");
  run_fsi_case<3>("thick_plate", coarse, tight, comm, "out_np");
  if (root)
    run_fsi_case<3>("thick_plate", coarse, tight, MPI_COMM_SELF, "out_1");
  if (!root)
    return 0;

  enum Column
  {
    iterations = 0,
    drag = 4,
    lift = 5,
    ux = 6,
    uy = 7,
    uz = 8,
    volume = 9
  };
  const auto r = result("out_shipped");
  if (!error.empty())
    std::printf("shipped settings: %s\n", error.c_str());
  out << "(a) steady state, at most 4 coupling iterations: "
      << yes_no(error.empty() && !r.empty() && r[iterations] <= 4) << "\n";
  if (!r.empty())
  {
    std::printf("coarse: %g coupling iterations, u(A) = (%.6e, %.6e, %.6e) m, F = (%.6f, %.6f) N\n",
                r[iterations], r[ux], r[uy], r[uz], r[drag], r[lift]);
    out << "    bent downstream and lifted, u_x(A), u_y(A) > 0: " << yes_no(r[ux] > 0 && r[uy] > 0)
        << "\n"
        << "    u_x(A) within 20% of 5.95e-5 m, F_x within 10% of 1.33 N: "
        << yes_no(std::abs(r[ux] / 5.95e-5 - 1) < 0.2 && std::abs(r[drag] / 1.33 - 1) < 0.1)
        << "\n";
  }

  const auto l = result("out_large");
  if (!error_large.empty())
    std::printf("large deformation: %s\n", error_large.c_str());
  out << "(b) large deformation, sliding symmetry plane: runs through: "
      << yes_no(error_large.empty() && !l.empty()) << "\n";
  if (!l.empty())
  {
    std::printf("large deformation: u(A) = (%.6e, %.6e, %.6e) m, smallest volume ratio %.3f\n",
                l[ux], l[uy], l[uz], l[volume]);
    out << "    u_x(A) within 20% of 0.01463 m, every cell above half its volume: "
        << yes_no(std::abs(l[ux] / 0.01463 - 1) < 0.2 && l[volume] > 0.5) << "\n";
  }

  const auto rn = result("out_np"), r1 = result("out_1");
  if (!rn.empty())
    out << format("tight: u(A) = (%.6g, %.6g, %.6g) m, F = (%.6g, %.6g) N", rn[ux], rn[uy], rn[uz],
                  rn[drag], rn[lift])
        << "\n";
  double du = 1, dF = 1;
  if (!rn.empty() && !r1.empty())
  {
    du = std::hypot(rn[ux] - r1[ux], rn[uy] - r1[uy], rn[uz] - r1[uz]) /
         std::hypot(r1[ux], r1[uy], r1[uz]);
    dF = std::hypot(rn[drag] - r1[drag], rn[lift] - r1[lift]) / std::hypot(r1[drag], r1[lift]);
  }
  std::printf("np - 1 rank, relative differences: u(A) %.2e, force %.2e\n", du, dF);
  out << "(c) np ranks equal one rank (u(A) and the force to 1e-8): "
      << yes_no(std::max(du, dF) <= 1e-8) << "\n";
}
