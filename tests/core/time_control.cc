// The clock every physics shares (TimeControl): how many steps a run has, also after the time
// step has been halved (Time/Time step control) and under a step limit (--steps), which the
// progress lines report as "step N of M". Exact integer results; no tolerance.
#include <fvfsi/base/time_control.h>

#include "../test_utilities.h"

#include <deal.II/base/mpi.h>

using fvfsi::TimeControl;

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto out = fvfsi_test::open_output();

  // 0.1 s with dt = 0.01 s: 10 steps.
  TimeControl clock(0.01, 0.1);
  out << "steps from 0 to 0.1 s with dt = 0.01 s: " << clock.n_steps() << ", last step "
      << clock.last_step() << '\n';

  // Four steps, then dt halved: step 5 runs with 0.005 s (t = 0.045 s), and 0.055 s remain
  // after it at 0.005 s per step: the last step is 5 + 11 = 16.
  for (int k = 0; k < 4; ++k)
    clock.advance();
  clock.set_time_step(0.005);
  clock.advance();
  out << "after step " << clock.step() << " (t = " << clock.time()
      << " s) with dt = 0.005 s: last step " << clock.last_step() << '\n';
  while (!clock.at_end())
    clock.advance();
  out << "the run ends at step " << clock.step() << " (t = " << clock.time() << " s)\n";

  // A step limit of 8 caps both counts.
  TimeControl limited(0.01, 0.1, 8);
  limited.advance();
  limited.set_time_step(0.005);
  limited.advance();
  out << "with --steps 8: " << limited.n_steps() << " steps, last step " << limited.last_step()
      << '\n';
}
