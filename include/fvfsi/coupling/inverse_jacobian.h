#pragma once
// The inverse Jacobian of IQN-IMVJ (interface quasi-Newton, multi-vector Jacobian: Lindner, Mehl,
// Scheufele, Uekermann 2015; Bogaers et al. 2014, IQN-MVJ; preCICE's IQN-IMVJ). J approximates
// the derivative of the solid's answer d~ with respect to the residual r = d~ - d, so that the
// next iterate is d <- d~ - J r (Delta r = -r). Every time step adds the secant pairs it has seen,
// V = [Delta r_k], W = [Delta d~_k] (the columns the QR filter keeps), to the inverse Jacobian of
// the earlier time steps, J_prev:
//
//   J = J_prev + (W - J_prev V) V^+,   V^+ = (V^T V)^-1 V^T,
//
// the least change of J_prev (in the Frobenius norm) with J V = W. Within a time step, IQN-IMVJ
// (source/coupling/methods/iqn_imvj.cc) applies this J without forming it:
// J r = J_prev (r - V c) + W c with c = V^+ r, i.e. the IQN-ILS correction of the step's own columns plus J_prev on the part of r
// that they do not explain (fv/least_squares_model.h).
//
// Memory. fvfsi's interfaces have N ~ 1e2-1e3 values in 2D and 1e4-1e5 on a 3D tube, so:
//   - dense (N <= `dense limit`, default 2000: at most 32 MB): J is an N x N matrix updated
//     in place at the end of every time step, O(N^2 m) work; it keeps every time step (the
//     method of the paper, no restart);
//   - implicit (larger N): J is the sum of the rank-m terms of the last M (`window`) time steps,
//     J = sum_k Wt_k Z_k^T with Wt_k = W_k - J_(k-1) V_k and Z_k^T = V_k^+, and the recursion
//     starts from J = 0 M time steps back (a sliding-window restart, preCICE's RS-SLIDE idea). When
//     the window slides, the oldest term is dropped and the Wt_k of the others are recomputed
//     from their V_k, W_k (O(M^2 m^2 N), once per time step), so J keeps the secant equations
//     J V_k = W_k of the newest step exactly. Memory 4 m M N doubles (V, W, Z, Wt per column;
//     e.g. 130 MB at N = 1e5, M = 8, m = 5), J x costs O(m M N).
// Why this restart: a chunk restart (preCICE's RS-0) throws J away every M steps, so the
// iterations jump back up periodically; RS-SVD needs a truncated SVD update and a rank threshold.
// The window costs O(M^2 m^2 N) per step, far below a fluid solve, and keeps J smooth in time;
// while J holds no more than M time steps it is the dense J up to round-off (tested:
// tests/coupling/coupling_imvj, where a window of 2 on a linear model also shows its price:
// what the dropped steps had learnt is lost, and the iterations go back up towards IQN-ILS's).
// The vectors are replicated on every rank (InterfaceVector): every rank computes the same J.

#include <deal.II/lac/full_matrix.h>

#include <boost/serialization/deque.hpp>
#include <boost/serialization/vector.hpp>

#include <fvfsi/coupling/interface_zone.h>

#include <deque>
#include <vector>

namespace fvfsi
{
  class MultiVectorJacobian
  {
  public:
    /// Dense storage for interfaces of up to `dense_limit` values, else the sliding window of
    /// `window` time steps.
    MultiVectorJacobian(const unsigned int dense_limit, const unsigned int window);

    /// No time step added yet (J = 0).
    bool empty() const { return n_updates == 0; }
    /// Whether J is a dense matrix (decided by the first update's size).
    bool is_dense() const { return dense; }

    /// y = J x (y is resized like x).
    void vmult(InterfaceVector& y, const InterfaceVector& x) const;

    /// J <- J + (W - J V) V^+ with a time step's secants: V = [dR], W = [dX], Z with
    /// V^+ x = (Z_k . x)_k (LeastSquaresModel::kept_secants()).
    void update(const std::vector<InterfaceVector>& dR, const std::vector<InterfaceVector>& dX,
                const std::vector<InterfaceVector>& Z);

    /// Save or load J (a checkpoint of the coupling; Boost serialization).
    template <class Archive>
    void serialize(Archive& ar, const unsigned int /*version*/)
    {
      ar& n_updates& dense& J& steps;
    }

  private:
    struct Step
    {
      std::vector<InterfaceVector> V, W, Z, W_tilde;
      template <class Archive>
      void serialize(Archive& ar, const unsigned int /*version*/)
      {
        ar& V& W& Z& W_tilde;
      }
    };
    /// y = sum over the first `n_steps` terms of the window of Wt_k (Z_k . x).
    void apply_steps(const unsigned int n_steps, InterfaceVector& y,
                     const InterfaceVector& x) const;
    /// Wt_k = W_k - J_(k-1) V_k for the k-th step of the window, from the steps before it.
    void compute_w_tilde(const unsigned int k);

    unsigned int dense_limit, window;
    unsigned int n_updates = 0;
    bool dense = false;
    dealii::FullMatrix<double> J;
    std::deque<Step> steps;
  };
} // namespace fvfsi
