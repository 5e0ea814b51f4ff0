// The contest's promises (issue 63, docs/machines.md), held on ten contests: every machine, in
// vacuum and through air, limits on the box, the counterweight, the axle and the acceleration,
// a clearance and a counterweight's box. For each:
// - the engine meets every limit, and each binding one to 1e-5 of it (COBYLA stops where a step
//   of 1e-6 in the logs changes nothing);
// - monotone: each limit 10 % looser (the clearance 10 % less, the bounding box 10 % larger both
//   ways) never shortens what the contest returns by more than 1e-4 of it;
// - true gains: a binding limit's gain_if_relaxed is what the contest itself returns with it 10 %
//   looser, to 1e-3 of the objective; a limit marked not binding gains no more than that;
// - how sure: six local searches (more where a hop or a gain's search shot a better engine), at
//   least one of which reached the best.
// Each contest costs seconds of CPU (several through air): the tests are heavy (tests/heavy.hpp);
// the sanitizer pass runs the hinged builder alone (check_cases).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "contests.hpp"
#include "heavy.hpp"
#include "trebuchet/contest.hpp"

using namespace trebuchet;
using trebuchet::testing::school_contest;

namespace {

struct ContestCase {
  std::string name;
  ContestRequest request;
};

ContestRequest contest(MachineKind machine, double m, double beam_per_m, std::vector<std::pair<ContestLimit, double>> limits) {
  ContestRequest r;
  r.machine = machine;
  r.projectile_mass = m;
  r.beam_mass_per_length = beam_per_m;
  r.settings.criterion.release = Release::range;  // released where the range peaks, as trebuchet-verify contest does
  for (const auto& [limit, value] : limits) r.limits[limit] = value;
  return r;
}

// Issue 63's builders: the hinged engine for a 4 kg ball (its height touches 4 m without
// binding), and the floating arm with a counterweight's box and 5 cm of clearance, whose width
// bound the old search at 124.9 m.
ContestRequest builder_floating_arm(double width) {
  ContestRequest r = contest(MachineKind::floating_arm, 4, 10, {{width_limit, width}, {height_limit, 4}, {mass_limit, 400}, {axle_limit, 12e3}});
  r.box_width = r.box_height = 0.8;
  r.min_clearance = 0.05;
  return r;
}

ContestRequest through_air(ContestRequest r) {
  r.settings.air = Air{};
  return r;
}

// The hinged machine at school releases where its sling goes slack, the range's peak (test_shot's
// "the range peaks where the sling stops pulling"); until that release was no longer warned as a
// slack sling, its engines came and went between neighbouring L3, and the contest gave 146.49 m
// at 60 kg but 142.71 m at 66 kg.
std::vector<ContestCase> vacuum_cases() {
  const MachineKind hinged = MachineKind::hinged, fixed = MachineKind::fixed, floating = MachineKind::floating_arm;
  ContestRequest builder = contest(hinged, 4, 6, {{width_limit, 3}, {height_limit, 4}, {mass_limit, 400}, {axle_limit, 12e3}});
  ContestRequest clear = builder;
  clear.min_clearance = 0.1;
  return {{"hinged builder", builder},
          {"floating-arm builder, 3 m wide", builder_floating_arm(3)},
          {"floating-arm builder, 3.2 m wide", builder_floating_arm(3.2)},
          {"fixed school", school_contest(fixed)},
          {"hinged school", school_contest(hinged)},
          {"floating-arm school", school_contest(floating)},
          {"hinged builder, 10 cm clear", clear},
          {"fixed, acceleration 300 m/s2", contest(fixed, 0.5, 1.5, {{width_limit, 4}, {mass_limit, 60}, {acceleration_limit, 300}})}};
}

// Not here: issue 63's hinged engine in air (a 4 kg ball, a box of 20 m by 20 m, at most 10 t
// and 2000 m/s2), where the search's local searches end far apart (593 to 972 m), each on an
// optimum of its own: 971.89 m at 10 t, 986.32 m at 11 t though M claims no gain, and its
// acceleration's claimed gain 33.8 m where the contest at 10 % more finds 39.2 m (issue 63,
// open). Nor the efficiency's contest (--objective eps): without a limit on the acceleration it
// reaches eps = 1 on the fixed machine and the floating arm at school, where no limit binds. With
// one (the fixed machine at school, 4 m wide, 60 kg, 10 m/s2) it gives 0.7741, and 0.7805 with
// 10 % more width from an engine 3.35 m wide that it misses (issue 63, open).
std::vector<ContestCase> air_cases() {
  return {{"fixed school in air, 1.5 kN on the axle",
           through_air(contest(MachineKind::fixed, 0.5, 1.5, {{width_limit, 4}, {height_limit, 3}, {mass_limit, 60}, {axle_limit, 1500}}))},
          {"floating-arm builder in air", through_air(builder_floating_arm(3))}};
}

// The request with one thing 10 % looser, by name.
struct Relaxed {
  std::string what;
  ContestRequest request;
  std::optional<double> claimed_gain;  // what the contest said it gains
  bool claimed_binds = false;
};

std::vector<Relaxed> relaxations(const ContestRequest& r, const ContestEngine& best) {
  std::vector<Relaxed> out;
  for (int k = 0; k < contest_limit_count; ++k) {
    if (!r.limits[k]) continue;
    ContestRequest looser = r;
    looser.limits[k] = *r.limits[k] * 1.1;
    out.push_back({contest_limit_key(static_cast<ContestLimit>(k)), looser, best.gain_if_relaxed[k], best.binds[k]});
  }
  if (r.min_clearance > 0) {
    ContestRequest looser = r;
    looser.min_clearance = r.min_clearance * 0.9;
    const bool binds = best.gain_if_clearance_relaxed && *best.gain_if_clearance_relaxed > binding_gain * best.objective;
    out.push_back({"min_clearance", looser, best.gain_if_clearance_relaxed, binds});
  }
  if (r.limits[width_limit] && r.limits[height_limit]) {
    ContestRequest looser = r;
    looser.limits[width_limit] = *r.limits[width_limit] * 1.1, looser.limits[height_limit] = *r.limits[height_limit] * 1.1;
    out.push_back({"the bounding box", looser, std::nullopt, false});
  }
  return out;
}

void check_limits_met(const ContestRequest& r, const ContestEngine& best) {
  for (int k = 0; k < contest_limit_count; ++k) {
    if (!r.limits[k]) continue;
    CHECK(best.measured[k] <= *r.limits[k] * (1 + 1e-12));  // M = m/(m/M) may round a part in 1e16 above
    if (best.binds[k] && best.at_limit[k]) CHECK(best.measured[k] >= *r.limits[k] * (1 - 1e-5));
  }
  CHECK(best.clearance >= r.min_clearance);
  CHECK(best.verification.warnings.empty());
  // How sure: six local searches (and one for each better engine a gain's search found), at least
  // one at the best; none above it.
  REQUIRE(best.start_objectives.size() >= contest_local_searches);
  int at_best = 0;
  for (const auto& reached : best.start_objectives)
    if (reached) {
      CHECK(*reached <= best.objective * (1 + 1e-12));
      at_best += *reached >= best.objective * (1 - reached_best);
    }
  CHECK(at_best >= 1);
}

void check_contest(const ContestCase& c) {
  const ContestEngine best = contest_optimum(c.request);
  std::printf("%s: objective %.9g in %d shots; %s\n", c.name.c_str(), best.objective, best.shots, best.start_objectives.empty() ? "" : "starts:");
  for (const auto& reached : best.start_objectives) std::printf("  start reached %.9g\n", reached.value_or(-1));
  check_limits_met(c.request, best);
  for (const Relaxed& relaxed : relaxations(c.request, best)) {
    const double looser = contest_optimum(relaxed.request).objective;  // as the contest returns it, its gains' searches included
    const double gained = looser - best.objective;
    std::printf("  %s 10 %% looser: %.9g (gained %.4g, %.2g of the objective; claimed %.4g, %s)\n", relaxed.what.c_str(), looser, gained,
                gained / best.objective, relaxed.claimed_gain.value_or(-1), relaxed.claimed_binds ? "binds" : "does not bind");
    CHECK(gained >= -1e-4 * best.objective);  // monotone
    if (relaxed.claimed_binds) {
      REQUIRE(relaxed.claimed_gain);
      CHECK(std::abs(*relaxed.claimed_gain - gained) <= 1e-3 * best.objective);  // a true gain
    } else if (relaxed.what != "the bounding box") {
      CHECK(gained <= 1e-3 * best.objective);  // not binding: relaxing gains nothing
    }
  }
}

}  // namespace

// The cases in five test cases, which CTest runs side by side. The sanitizer pass runs one case
// in four by its index here (tests/heavy.hpp): the hinged builder alone, the others numbered from 1
// in groups of at most three. The rest take the same code paths at many times the cost.
void check_cases(const std::vector<ContestCase>& cases, std::size_t from, std::size_t to, int first_index) {
  int index = first_index;
  for (std::size_t k = from; k < to && k < cases.size(); ++k) {
    if (!heavy_case_runs(index++)) continue;
    SECTION(cases[k].name) { check_contest(cases[k]); }
  }
}

TEST_CASE("the contest is monotone in its limits and its gains are true for the builders", "[contest][heavy]") {
  check_cases(vacuum_cases(), 0, 3, 0);
}

TEST_CASE("the contest is monotone in its limits and its gains are true at school", "[contest][heavy]") { check_cases(vacuum_cases(), 3, 6, 1); }

TEST_CASE("the contest is monotone in its limits and its gains are true under a clearance and an acceleration", "[contest][heavy]") {
  check_cases(vacuum_cases(), 6, 8, 1);
}

// Through air, one contest per test case: they are the suite's longest (about 50 s each).
TEST_CASE("the contest is monotone in its limits and its gains are true through air at school", "[contest][heavy]") {
  check_cases(air_cases(), 0, 1, 1);
}

TEST_CASE("the contest is monotone in its limits and its gains are true through air for the builder", "[contest][heavy]") {
  check_cases(air_cases(), 1, 2, 2);
}

// The hinged machine at school, whose local searches disagree (one of six reaches its best), so
// that it hops from its best too.
TEST_CASE("the contest gives the same engine on every run", "[contest][heavy]") {
  ContestRequest r = school_contest(MachineKind::hinged);
  r.gains = false;
  const ContestEngine first = contest_optimum(r), second = contest_optimum(r);
  REQUIRE(first.hops > 0);
  CHECK(first.hops == second.hops);
  CHECK(first.objective == second.objective);
  CHECK(first.engine.L1 == second.engine.L1);
  CHECK(first.engine.M == second.engine.M);
  CHECK(first.start_objectives == second.start_objectives);
  CHECK(first.shots == second.shots);
}
