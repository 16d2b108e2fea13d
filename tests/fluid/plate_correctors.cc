// Pressure-velocity coupling that converges itself, and adaptive time steps through an impulsive
// start (the hard-case issue, items 2, 3 and 5), on the rigid plate in a channel of
// prm/wall_plate_channel.prm (a sharp-cornered obstacle that nobody tuned fvfsi on).
//   (a) At the shipped settings (25 110 cells, dt = 2.5 ms, largest Courant number 4.2-4.3 at
//       the plate's corners) the run is stable for its 40 steps to t = 0.1 s; the correctors
//       per step adapt (more than the least two in the impulsive start, two later, at most the
//       Max pressure correctors 6); the drag at t = 0.1 s is within 1% of a run with 6 correctors
//       in every step (Pressure correctors = 6), the converged PISO step. Two correctors in every
//       step (Max pressure correctors = 2, fvfsi's count before) diverge at step 25
//       (tests/fluid/divergence_guard).
//   (b) Time/Adaptive = Courant with Max Courant number = 2 on the tutorial mesh (r = 1, 2 790
//       cells) from dt = 1e-4 s through the impulsive start to t = 0.3 s: every step after the
//       first two holds the Courant number within 1.25 x the target (the growth limit 1.2 and
//       the flow's change), and the steps grow by at most 1.2.
//   (c) Time/Adaptive = error (Error tolerance = 1e-3) on the same case: the steps grow from
//       1e-4 s as the impulsive start decays (the last larger than the tenth), and the drag at
//       t = 0.3 s is within 2% of (b)'s.
// np = 1 and np = 2 print the same verdicts (the counts themselves may differ by round-off where
// a corrector's change is near the tolerance).
#include "../test_utilities.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace fvfsi_test;

int main(int argc, char** argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  const std::string history = "out/fluid_history.txt";

  // (a)
  const auto shipped = run_fluid_case("wall_plate_channel", 0.0025, {"Time/End time=0.1"});
  const double drag = shipped->body_force()[0];
  const auto correctors = history_column(history, "correctors");
  const auto courant = history_column(history, "courant");
  const auto [least, most] = std::minmax_element(correctors.begin(), correctors.end());
  const auto reference = run_fluid_case("wall_plate_channel", 0.0025,
                                        {"Time/End time=0.1", "Fluid/Pressure correctors=6"});
  const double drag_6 = reference->body_force()[0];
  out << "(a) 40 steps run: " << yes_no(correctors.size() == 40)
      << ", largest Courant number of the last 10 steps in [4, 4.5]: "
      << yes_no(*std::max_element(courant.end() - 10, courant.end()) >= 4 &&
                *std::max_element(courant.end() - 10, courant.end()) <= 4.5)
      << "\n(a) correctors per step from 2 to 6: " << yes_no(*least == 2 && *most <= 6)
      << ", more than 2 in the first steps: " << yes_no(correctors[0] > 2 && correctors[1] > 2)
      << "\n(a) drag at t = 0.1 s " << format("%.0f", drag) << " N/m, within 1% of 6 correctors' "
      << format("%.0f", drag_6) << ": " << yes_no(std::abs(drag - drag_6) <= 0.01 * drag_6) << "\n";

  // (b)
  const std::vector<std::string> tutorial_mesh = {"Mesh/Generator arguments=30: 3: 15: 30",
                                                  "Time/End time=0.3"};
  auto settings = tutorial_mesh;
  settings.insert(settings.end(), {"Time/Adaptive=Courant", "Time/Max Courant number=2"});
  const auto courant_run = run_fluid_case("wall_plate_channel", 1e-4, settings);
  const double drag_b = courant_run->body_force()[0];
  const auto co = history_column(history, "courant");
  const auto dt = history_column(history, "dt");
  const auto t = history_column(history, "t");
  double worst_courant = 0, worst_growth = 0;
  for (unsigned int i = 2; i < co.size(); ++i)
    worst_courant = std::max(worst_courant, co[i] / 2);
  for (unsigned int i = 1; i < dt.size(); ++i) // (dt as printed: 10 digits)
    worst_growth = std::max(worst_growth, dt[i] / dt[i - 1]);
  out << "(b) reaches t = 0.3 s: " << yes_no(std::abs(t.back() - 0.3) < 1e-9) << " in "
      << (co.size() < 100 ? "fewer" : "more") << " than 100 steps, Courant number / target "
      << "after step 2 at most 1.25: " << yes_no(worst_courant <= 1.25)
      << ", step growth at most 1.2: " << yes_no(worst_growth <= 1.2 * (1 + 1e-8)) << "\n";

  // (c)
  settings = tutorial_mesh;
  settings.insert(settings.end(), {"Time/Adaptive=error", "Time/Error tolerance=1e-3"});
  const auto error_run = run_fluid_case("wall_plate_channel", 1e-4, settings);
  const auto dt_e = history_column(history, "dt");
  const auto t_e = history_column(history, "t");
  out << "(c) reaches t = 0.3 s: " << yes_no(std::abs(t_e.back() - 0.3) < 1e-9)
      << ", the last step larger than the tenth: " << yes_no(dt_e.back() > dt_e.at(9))
      << ", drag at t = 0.3 s within 2% of (b)'s: "
      << yes_no(std::abs(error_run->body_force()[0] - drag_b) <= 0.02 * std::abs(drag_b)) << "\n";
}
