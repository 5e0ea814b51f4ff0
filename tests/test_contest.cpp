// The contest's optimizer (contest.hpp): the best engine within a contest's limits, held to a
// brute-force grid over the same variables, to its binding limit met with equality, and to the
// fewest limits that cannot be met together. Each contest costs seconds of CPU: these tests are
// heavy (tests/heavy.hpp), and the sanitizer pass runs their contests in part.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "heavy.hpp"
#include "trebuchet/contest.hpp"
#include "trebuchet/error.hpp"

using namespace trebuchet;

namespace {

// A school contest: a 0.5 kg ball, a beam of 1.5 kg/m, within a box 3 m high and 4 m wide, a
// counterweight of at most 60 kg.
ContestRequest school(MachineKind machine) {
  ContestRequest r;
  r.machine = machine;
  r.projectile_mass = 0.5;
  r.beam_mass_per_length = 1.5;
  r.limits[width_limit] = 4;
  r.limits[height_limit] = 3;
  r.limits[mass_limit] = 60;
  return r;
}

}  // namespace

TEST_CASE("the contest's optimum meets its limits, the binding ones with equality", "[contest][heavy]") {
  int index = 0;
  for (MachineKind machine : {MachineKind::fixed, MachineKind::floating_arm, MachineKind::hinged}) {
    if (!heavy_case_runs(index++)) continue;
    const auto start = std::chrono::steady_clock::now();
    const ContestEngine best = contest_optimum(school(machine));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("machine %d: R = %.6g m, width %.9g m, height %.9g m, M %.9g kg, axle %.4g N, acceleration %.4g m/s2, %d shots, %.3f s\n",
                static_cast<int>(machine), best.objective, best.measured[width_limit], best.measured[height_limit], best.measured[mass_limit],
                best.measured[axle_limit], best.measured[acceleration_limit], best.shots, seconds);
    CHECK(best.feasible);
    CHECK(best.measured[width_limit] <= 4);
    CHECK(best.measured[height_limit] <= 3);
    CHECK(best.measured[mass_limit] <= 60);
    // The counterweight's limit binds for every machine here: more mass throws farther. It is
    // held by the search's bound on m/M, so met to rounding.
    CHECK(best.measured[mass_limit] == Approx(60).epsilon(1e-12));
    // The fixed machine's height binds too (its optimum grows until the box stops it): the size
    // is bisected in log L2 to 1e-10, and the height grows as L2 (3 m per unit of log L2), so it
    // is met to 1e-9 relative. (The hinged engine and the floating arm stop a little short of the
    // box, where their counterweight would pass below the base: the model's own limit.)
    if (machine == MachineKind::fixed) CHECK(best.measured[height_limit] == Approx(3).epsilon(1e-9));
  }
}

// The search against a grid of the same variables (L1/L2, L4/L1, M and L2 for the fixed
// machine, the counterweight at the short arm's end) under the same loose limits: no grid
// point that meets them throws farther than the search's optimum. The grid's steps (0.5 in l,
// 0.1 in l4, 10 kg in M, 5 cm in L2) leave it some percent short of the optimum.
TEST_CASE("the contest's optimum throws at least as far as a grid of the same engines", "[contest][heavy]") {
  const ContestRequest r = school(MachineKind::fixed);
  const ContestEngine best = contest_optimum(r);
  double grid_best = 0;
  int shots = 0;
  for (double l = 2.5; l <= 6.51; l += 0.5)
    for (double l4 = 0.6; l4 <= 1.41; l4 += 0.1)
      for (double M = 40; M <= 60.01; M += 10) {
        // The largest L2 of the grid that meets the limits: the range grows with the size.
        for (double L2 = 0.1; L2 <= 1.21; L2 += 0.05) {
          Engine e;
          e.machine = r.machine, e.theta_i_deg = r.theta_i_deg, e.L2 = L2, e.L1 = l * L2, e.L3 = 0, e.L4 = l4 * e.L1, e.m = r.projectile_mass,
          e.M = M;
          e.mb = r.beam_mass_per_length * (e.L1 + e.L2);
          ++shots;
          try {
            Verification v;
            const auto measured = contest_measures(e, r.settings, &v);
            if (!v.warnings.empty() || measured[width_limit] > 4 || measured[height_limit] > 3) break;
            grid_best = std::max(grid_best, v.capacity.R);
          } catch (const Error&) {
            break;
          }
        }
      }
  std::printf("the search: R = %.6g m in %d shots; the grid's best: %.6g m in %d shots\n", best.objective, best.shots, grid_best, shots);
  CHECK(grid_best > 0);
  CHECK(best.objective >= grid_best);
}

// Limits no engine can meet are named, the fewest of them. The axle carries at least the
// projectile's weight (m g = 4.9 N here), so a limit of 2 N cannot be met alone. A peak
// acceleration of 5 m/s2 can be met alone (a feeble engine throws a little, slowly) but not in
// a box 4 m wide: the pair is named, and each of its limits alone is met.
TEST_CASE("the contest names the fewest limits that cannot be met together", "[contest][heavy]") {
  ContestRequest r = school(MachineKind::fixed);
  r.limits[axle_limit] = 2;  // N
  CHECK(conflicting_limits(r) == std::vector<ContestLimit>{axle_limit});
  r.limits[axle_limit].reset();
  r.limits[acceleration_limit] = 5;  // m/s2
  const std::vector<ContestLimit> pair{width_limit, acceleration_limit};  // named by contest_optimum below
  int index = 0;
  for (ContestLimit alone : pair) {
    if (!heavy_case_runs(index++)) continue;
    ContestRequest one = r;
    one.limits = {};
    one.limits[alone] = r.limits[alone];
    CHECK(contest_optimum(one).feasible);
  }
  try {
    contest_optimum(r);
    FAIL("a contest no engine can meet was answered");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::out_of_range);
    CHECK_THAT(e.what(), Catch::Contains("max_width and max_acceleration together"));
  }
  r.limits[acceleration_limit].reset();
  CHECK(conflicting_limits(r).empty());
}

// Issue 46's builder: a hinged machine for a 4 kg ball, a beam of 6 kg/m, in a box 3 m wide and
// 4 m high, at most 400 kg and 12 kN on the axle. Its winner once hung its counterweight 2.0 cm
// below the ground (F = 1.014) and stopped at 11.997 kN, unmarked. Now its counterweight clears
// the ground, hanging straight down and in the shot, and the axle's limit is met to 1e-4 and
// binds, with what 10 % more would gain (the unlimited engine throws 157 m: more than nothing).
TEST_CASE("the builder's contest returns an engine that clears the ground and meets its axle limit", "[contest][heavy]") {
  ContestRequest r;
  r.machine = MachineKind::hinged;
  r.projectile_mass = 4;
  r.beam_mass_per_length = 6;
  r.limits[width_limit] = 3;
  r.limits[height_limit] = 4;
  r.limits[mass_limit] = 400;
  r.limits[axle_limit] = 12e3;
  r.settings.criterion.release = Release::range;  // released where the range peaks, as trebuchet-verify contest does
  const ContestEngine best = contest_optimum(r);
  const Verification::Clearance& c = best.verification.clearance;
  std::printf("builder's contest: R %.6g m, clearance %.4g m hanging, %.4g m in the shot, axle %.8g N, height %.8g m, gain %.4g m\n", best.objective,
              c.geometric, c.in_shot.value_or(-1), best.measured[axle_limit], best.measured[height_limit],
              best.gain_if_relaxed[axle_limit].value_or(-1));
  CHECK(best.feasible);
  CHECK(c.geometric >= 0);
  REQUIRE(c.in_shot);
  CHECK(*c.in_shot >= 0);
  CHECK(best.verification.warnings.empty());
  CHECK(best.measured[axle_limit] <= 12e3 * (1 + 1e-12));
  CHECK(contest_binds(best, r, axle_limit));
  REQUIRE(best.gain_if_relaxed[axle_limit]);
  CHECK(*best.gain_if_relaxed[axle_limit] > 0);
  // A margin asked for is kept: 10 cm above the ground (a second contest: heavy case 1).
  if (!heavy_case_runs(1)) return;
  r.min_clearance = 0.1;
  const ContestEngine clear = contest_optimum(r);
  CHECK(clear.clearance >= 0.1 - 1e-9);
  CHECK(clear.objective <= best.objective * (1 + 1e-9));
}
