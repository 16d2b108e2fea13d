#pragma once
// `subsection Coupling` of a .prm file: the interface of an FSI scene (its fluid and solid
// patches) and how Algorithm 1 iterates its displacement (the coupling method and its settings,
// coupling/coupling_method.h; the iteration itself, coupling/partitioned_coupling.h).

#include <deal.II/base/parameter_handler.h>

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
    /// The coupling method, by the name it registered (CouplingMethod::names(): fixed, Aitken,
    /// IQN-ILS, IQN-IMVJ).
    std::string method = "IQN-ILS";
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
} // namespace fvfsi
