#pragma once
// The fixed-point iteration of a Dirichlet-Neumann coupling (paper section 3.4, Algorithm 1 and
// Eqs 30-31). The fluid takes an interface displacement d (at the fluid interface vertices), the
// solid answers with d~ = S(F(d)); the residual is r = d~ - d, and the next displacement is
//
//   fixed relaxation:  d <- d + omega r                                              (31)
//   Aitken:            the same with omega_k = -omega_(k-1) r_(k-1).(r_k - r_(k-1)) / |r_k - r_(k-1)|^2
//                      (Kuettler and Wall's dynamic relaxation)
//   IQN-ILS:           d <- d~ + W c, with c the least-squares solution of V c = -r, where the
//                      columns of V and W are the differences of r and of d~ between iterations
//                      (Degroote et al.: an approximate inverse Jacobian of the residual built
//                      from the iterations seen; columns of earlier time steps may be reused).
//   IQN-IMVJ:          d <- d~ - J r with J = J_prev + (W - J_prev V) V^+: the inverse Jacobian
//                      of the earlier time steps, J_prev, updated with this step's columns
//                      (Lindner et al. 2015; coupling/inverse_jacobian.h: J and its memory).
//                      On the first time step (J_prev = 0) it is IQN-ILS without reuse.
//
// As in the paper, Aitken and IQN-ILS start every time step with fixed-relaxation iterations
// (IQN-ILS not when it reuses columns of earlier time steps, IQN-IMVJ not once it has a J of
// earlier time steps: they model the Jacobian already).
//
// The QR filter (`QR filter`, default 1e-2, preCICE's QR2 filter): the columns are taken newest
// first, and one whose part orthogonal to the newer ones is at most filter x its norm is left out
// of the least-squares problem (IQN-ILS, IQN-IMVJ; for IQN-IMVJ also of its J update). Without
// it (0) nearly dependent columns (late iterations of a converging step, reused old steps) make
// the least-squares problem ill-conditioned and amplify round-off and noise into the update; too
// large a filter throws away information and costs iterations.
//
// Convergence (converged()): |r| <= Tolerance |d~| (Eq. 30) or, if `Residual reduction` > 0,
// |r| <= Residual reduction x the largest |r| of the step's iterations (Lindner et al.: 1e-6);
// with both set, whichever is met first ends the step.
//
// The vectors are the whole interface, replicated on every rank (InterfaceZone's InterfaceVector),
// so every rank computes the same update; nothing here communicates. The least-squares model of
// IQN-ILS is the one of the solid's Anderson acceleration (fv/least_squares_model.h).

#include <deal.II/base/parameter_handler.h>

#include <fvfsi/base/selection.h>
#include <fvfsi/coupling/interface_zone.h>
#include <fvfsi/coupling/inverse_jacobian.h>
#include <fvfsi/fv/least_squares_model.h>

#include <string>
#include <vector>

namespace fvfsi
{
  /// `subsection Coupling`: the interface and how its displacement is iterated.
  struct CouplingParameters
  {
    /// Fluid patches of the interface (walls that are also Mesh motion/Moving patches).
    std::vector<std::string> fluid_interface;
    /// Solid patches of the interface (Solid/External traction patches).
    std::vector<std::string> solid_interface;
    enum class Method
    {
      fixed,   ///< fixed relaxation (Eq. 31)
      aitken,  ///< dynamic relaxation
      iqn_ils, ///< interface quasi-Newton, least-squares inverse Jacobian
      iqn_imvj ///< interface quasi-Newton, multi-vector inverse Jacobian
    };
    static const SelectionNames<Method> method_names;
    Method method = Method::iqn_ils;
    double relaxation = 0.5;           ///< omega of fixed relaxation and of the first iterations
    unsigned int fixed_iterations = 2; ///< Aitken / IQN-*: fixed iterations that start a step
    double tolerance = 1e-6;           ///< |r|_2 / |d~|_2 below which a time step has converged
    double residual_reduction = 0;     ///< or |r| / max |r| of the step below this (0: off)
    unsigned int max_iterations = 100;
    unsigned int reuse_time_steps = 0; ///< IQN-ILS: keep V, W of this many earlier time steps
    /// Time before which the solid is held in its initial state and the fluid runs alone on the
    /// fixed mesh [s] (0: coupled from the first step).
    double start_time = 0;
    double qr_filter = 1e-2; ///< IQN-*: columns' relative orthogonal part kept above this
    unsigned int imvj_dense_limit = 2000; ///< IQN-IMVJ: dense J up to this many interface values
    unsigned int imvj_time_steps = 8;     ///< IQN-IMVJ, implicit J: the window of time steps
    bool iteration_log = false;           ///< print the residual of every coupling iteration
    /// Where the solid's interface displacement handed to the fluid comes from: its vertex
    /// values (the least-squares reconstruction of App. B, the paper's) or the average of the
    /// boundary-face displacements round each interface vertex.
    bool face_average_displacement = false;

    void declare(dealii::ParameterHandler& prm);
  };

  class CouplingAcceleration
  {
  public:
    explicit CouplingAcceleration(const CouplingParameters& parameters);

    /// Start a time step (Aitken: omega back to the fixed value; IQN-ILS: keep or drop the
    /// columns of earlier time steps; IQN-IMVJ: add the last step's columns to J).
    void new_time_step();

    /// The next interface displacement from the one used, d, and the solid's answer, d~.
    InterfaceVector next(const InterfaceVector& d, const InterfaceVector& d_tilde);

    /// |r|_2 / max(|d~|_2, tiny) of the last call to next().
    double relative_residual() const { return last_relative_residual; }

    /// Whether the last call to next() met the convergence test (see above).
    bool converged() const;

    /// IQN-IMVJ: the inverse Jacobian of the earlier time steps.
    const MultiVectorJacobian& inverse_jacobian() const { return jacobian; }

    /// Save or load the state kept between time steps (a checkpoint; Boost serialization): the
    /// IQN-ILS columns kept for reuse and the IQN-IMVJ Jacobian among it.
    template <class Archive>
    void serialize(Archive& ar, const unsigned int /*version*/)
    {
      ar& iteration& omega& previous_r& previous_d_tilde& model& jacobian& time_step&
        last_relative_residual& last_residual& largest_residual;
    }

  private:
    CouplingParameters prm;
    unsigned int iteration = 0; ///< within the time step
    double omega;
    InterfaceVector previous_r, previous_d_tilde;
    /// IQN-ILS: columns V (differences of r) and W (of d~), tagged with their time step.
    LeastSquaresModel<InterfaceVector> model;
    /// IQN-IMVJ: J_prev.
    MultiVectorJacobian jacobian;
    unsigned int time_step = 0;
    double last_relative_residual = 0, last_residual = 0, largest_residual = 0;

    /// The quasi-Newton updates; false (result untouched) where fixed relaxation is to be used.
    bool iqn_ils_update(const InterfaceVector& r, const InterfaceVector& d_tilde,
                        InterfaceVector& result) const;
    bool iqn_imvj_update(const InterfaceVector& r, const InterfaceVector& d_tilde,
                         InterfaceVector& result) const;
  };
} // namespace fvfsi
