// The machines and the contest (issue 36): the median wall time of one optimal shot of the same
// engine built as each machine, with its ratio to the hinged one; then of the contest's
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
