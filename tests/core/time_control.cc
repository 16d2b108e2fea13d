// The clock every physics shares (TimeControl): how many steps a run has, also after the time
// step has been halved (Time/Time step control), under a step limit (--steps) and for an end
// time that is not a whole number of steps, which the progress lines report as "step N of M";
// the count before the run and the step at which at_end() stops it agree. Exact integer
// results; no tolerance.
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
  out << "steps from 0 to 0.1 s with dt = 0.01 s: " << clock.last_step() << '\n';

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
  out << "with --steps 8: last step " << limited.last_step() << '\n';

  // 0.1 s with dt = 0.03 s: the third step ends at 0.09 s, short of the end time, so the run
  // takes a fourth, to 0.12 s; the count before the run says so.
  TimeControl uneven(0.03, 0.1);
  out << "steps from 0 to 0.1 s with dt = 0.03 s: " << uneven.last_step();
  while (!uneven.at_end())
    uneven.advance();
  out << "; the run ends at step " << uneven.step() << " (t = " << uneven.time() << " s)\n";
}
