// The machines and the contest (issue 36): the median wall time of one optimal shot of the same
// engine built as each machine, with its ratio to the hinged one; of pytrebuchet's default
// whipper, with its ratio to the same parts hung as the paper's engine; then of the contest's
// optimum within a school contest's limits (issue 36's bound: 1 s) and of its Pareto front of 20
// points (bound: 10 s), for each machine.
// Usage: bench-machines [seconds per point]
#include <cstdio>
#include <cstdlib>

#include "engines.hpp"
#include "timing.hpp"
#include "trebuchet/contest.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;
using namespace trebuchet::bench;

int main(int argc, char** argv) {
  const double budget = argc > 1 ? std::atof(argv[1]) : 1.0;
  const MachineKind machines[] = {MachineKind::hinged, MachineKind::fixed, MachineKind::floating_arm};
  const char* names[] = {"hinged", "fixed", "floating-arm"};
  ShotSettings settings;
  settings.loads = false;  // the shot alone, as searches run it
  std::printf("machine,shot_median_s,ratio_to_hinged\n");
  double hinged = 0;
  for (int k = 0; k < 3; ++k) {
    Engine engine = testing::alcala_ca();  // row Ca's engine, its counterweight arm L3 as the others' hanger
    engine.machine = machines[k];
    const double seconds = median_seconds([&] { verify_engine(engine, settings); }, budget);
    if (k == 0) hinged = seconds;
    std::printf("%s,%.4e,%.3f\n", names[k], seconds, seconds / hinged);
  }
  // The whipper's shot runs its whole forward swing for the optimum (docs/machines.md).
  Engine whipper;
  whipper.machine = MachineKind::whipper;
  whipper.L1 = 4, whipper.L2 = 2, whipper.L3 = 4, whipper.L4 = 4, whipper.M = 100, whipper.m = 3, whipper.mb = 10;
  whipper.theta_i_deg = whipper_theta_i_deg, whipper.whipper.H = 5, whipper.projectile_diameter = 0.2;
  Engine hung = whipper;
  hung.machine = MachineKind::hinged, hung.theta_i_deg = standard_theta_i_deg;
  const double whip = median_seconds([&] { verify_engine(whipper, settings); }, budget);
  const double paper = median_seconds([&] { verify_engine(hung, settings); }, budget);
  std::printf("whipper (pytrebuchet's default),%.4e,%.3f\n", whip, whip / paper);
  std::printf("\nmachine,contest_optimum_s,pareto_20_s\n");
  for (int k = 0; k < 3; ++k) {
    ContestRequest r;  // a 0.5 kg ball, a beam of 1.5 kg/m, a box 4 m wide and 3 m high, at most 60 kg
    r.machine = machines[k];
    r.projectile_mass = 0.5;
    r.beam_mass_per_length = 1.5;
    r.limits[width_limit] = 4, r.limits[height_limit] = 3, r.limits[mass_limit] = 60;
    r.settings.criterion.release = Release::range;
    const double best = median_seconds([&] { contest_optimum(r); }, budget);
    const double front = median_seconds([&] { pareto_front(r, 20); }, 0);  // three runs: each takes seconds
    std::printf("%s,%.4e,%.4e\n", names[k], best, front);
  }
  return 0;
}
