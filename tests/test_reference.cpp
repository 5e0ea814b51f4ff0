// Issue 12: the verified shot against an independent slow reference (tests/reference), which
// shares no code with the library, on 500 random designs over the ranges the paper explores.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <random>
#include <array>

#include "reference/reference_shot.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;

namespace {

struct Deviation {
  const char* name;
  double target;  // relative, the issue's
  double worst = 0;
  int worst_design = -1;
  void add(double ours, double reference, int design) {
    const double d = std::abs(ours / reference - 1);
    if (d > worst) worst = d, worst_design = design;
  }
};

}  // namespace

// Targets at the default settings: R, T, eps, v and h within 1e-8 relative, Q within 1e-9.
// The reference integrates at rtol 1e-14 and places every instant by bisection to round-off,
// so its own error is well below them; the library integrates at rtol = atol = 1e-11
// (docs/performance.md), 2.8e-9 in h and 3.2e-10 in Q at worst here. A release placed past a kink
// of Q, as before issue 12, misses by 1e-5 in R (the issue's example) and fails here, and so
// does the quintic interpolant of before, by 1.8e-7 in R and 1e-8 in Q.
TEST_CASE("the shot agrees with the independent reference on 500 random designs", "[reference][shot]") {
  std::mt19937_64 random(20261121);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  Deviation R{"R", 1e-8}, T{"T", 1e-8}, eps{"eps", 1e-8}, v{"v", 1e-8}, h{"h", 1e-8}, Q{"Q", 1e-9};
  int shot = 0, both_refused = 0, kinks = 0, kinks_found = 0, mismatched = 0;
  std::array<int, force_count> kinks_by_force{};
  int slack = 0, counterweight_low = 0, tip_low = 0;  // where the model stops holding (issue 12, part 2)
  for (int design = 0; design < 500; ++design) {
    const reference::Design d{uniform(3.5, 7), uniform(0.7, 1.2), uniform(0.03, 0.15),
                              uniform(0.004, 0.02), uniform(25, 45), uniform(0.5, 1)};
    const double L2 = uniform(0.3, 1.5);
    const Engine engine = engine_of(ScaledDesign{d.l, d.l4, d.mu_b, d.mu, d.theta_i_deg, d.F}, L2, Material{});
    bool ours_ok = true, reference_ok = true;
    Verification ours;
    ShotResult result;
    reference::Shot ref{};
    try {
      result = simulate_shot(scaled_design(engine), ReleaseCriterion{}, IntegratorSettings{});
      ours = verification_of(engine, result, 0);
    } catch (const Error&) {
      ours_ok = false;
    }
    try {
      ref = reference::shoot(d);
    } catch (const std::runtime_error&) {
      reference_ok = false;
    }
    if (!ours_ok && !reference_ok) {
      ++both_refused;
      continue;
    }
    if (ours_ok != reference_ok) {
      ++mismatched;
      std::printf("design %d: ours %s, the reference %s\n", design, ours_ok ? "shoots" : "refuses", reference_ok ? "shoots" : "refuses");
      continue;
    }
    ++shot;
    const double g = engine.material.g;
    R.add(ours.capacity.R, ref.rho * L2, design);
    T.add(ours.capacity.T, ref.tau_e * engine.M * g * L2, design);
    eps.add(ours.eps, ref.eps, design);
    v.add(ours.v, ref.speed * std::sqrt(g * L2), design);
    h.add(ours.h, ref.height * L2, design);
    Q.add(ours.Q, ref.Q, design);
    slack += result.slack_sling.has_value(), counterweight_low += result.counterweight_below_base.has_value(),
        tip_low += result.tip_below_base.has_value();
    if (ref.onset >= 0) {
      ++kinks;
      ++kinks_by_force[ref.onset];
      if (result.release_at_growth_of && *result.release_at_growth_of == ref.onset) ++kinks_found;
    }
  }
  std::printf("reference check: %d designs shot, %d refused by both, %d by one only; %d release at the onset of growth "
              "of a running extreme, %d of them found there by the library\n",
              shot, both_refused, mismatched, kinks, kinks_found);
  std::printf("  onsets: F_S_perp %d, |F_R| %d, max F_Rh %d, max -F_Rh %d\n", kinks_by_force[sling_perpendicular],
              kinks_by_force[pivot_reaction], kinks_by_force[pivot_horizontal], kinks_by_force[pivot_horizontal_negated]);
  std::printf("  warned before the release: slack sling %d, counterweight below the base %d, beam tip below the base %d\n", slack,
              counterweight_low, tip_low);
  for (const Deviation* dev : {&R, &T, &eps, &v, &h, &Q})
    std::printf("  %-3s worst relative deviation %.2e (design %d), target %.0e\n", dev->name, dev->worst, dev->worst_design, dev->target);
  CHECK(mismatched == 0);
  CHECK(shot >= 400);
  CHECK(kinks > 0);  // the set exercises releases at a kink
  CHECK(kinks_found == kinks);
  for (const Deviation* dev : {&R, &T, &eps, &v, &h, &Q}) CHECK(dev->worst <= dev->target);
}

// The issue's example: Q rises until the largest F_Rh starts to grow, then falls. A release
// found as the root of a slope lands past that kink: 3.2e-6 s late, R 2.0e-5 off and Q 6.9e-7
// below the maximum. Now it sits on the kink, as in the reference, within the issue's targets.
TEST_CASE("the release at the onset of growth of max F_Rh agrees with the reference", "[reference][shot]") {
  Engine engine;
  engine.L1 = 6.045, engine.L2 = 1.116, engine.L3 = 2.476, engine.L4 = 4.419;
  engine.M = 13400, engine.m = 67, engine.mb = 737, engine.theta_i_deg = 30;
  const ScaledDesign d = scaled_design(engine);
  const ShotResult ours = simulate_shot(d, ReleaseCriterion{}, IntegratorSettings{});
  const reference::Shot ref = reference::shoot({d.l, d.l4, d.mu_b, d.mu, d.theta_i_deg, d.F});
  const double time_unit = std::sqrt(engine.L2 / engine.material.g);  // [s]
  std::printf("issue 12 kink: release %.3e s from the reference, R %.1e, Q %.1e relative\n",
              (ours.release.t - ref.t_release) * time_unit, ours.release.range / ref.rho - 1, ours.release.quality / ref.Q - 1);
  REQUIRE(ref.onset == pivot_horizontal);
  REQUIRE(ours.release_at_growth_of == pivot_horizontal);
  CHECK(std::abs(ours.release.t - ref.t_release) * time_unit < 1e-9);
  CHECK(ours.release.range == Approx(ref.rho).epsilon(1e-8));
  CHECK(ours.release.quality == Approx(ref.Q).epsilon(1e-9));
}
