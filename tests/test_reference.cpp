// Issue 12: the verified shot against an independent slow reference (tests/reference), which
// shares no code with the library, on 500 random designs over the ranges the paper explores.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <random>
#include <array>
#include <vector>

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

// Each quantity's worst deviation from the reference over a set of designs, and what the set
// exercises.
struct Agreement {
  Deviation R{"R", 1e-8}, T{"T", 1e-8}, eps{"eps", 1e-8}, v{"v", 1e-8}, h{"h", 1e-8}, Q{"Q", 1e-9};
  int shot = 0, both_refused = 0, kinks = 0, kinks_found = 0, mismatched = 0;
  std::array<int, force_count> kinks_by_force{};
  int slack = 0, counterweight_low = 0, tip_low = 0;  // where the model stops holding (issue 12, part 2)

  void compare(const reference::Design& d, double L2, int design) {
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
      return;
    }
    if (ours_ok != reference_ok) {
      ++mismatched;
      std::printf("design %d: ours %s, the reference %s\n", design, ours_ok ? "shoots" : "refuses", reference_ok ? "shoots" : "refuses");
      return;
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

  void report(const char* set) const {
    std::printf(
        "reference check, %s: %d designs shot, %d refused by both, %d by one only; %d release at the onset of growth "
        "of a running extreme, %d of them found there by the library\n",
        set, shot, both_refused, mismatched, kinks, kinks_found);
    std::printf("  onsets: F_S_perp %d, |F_R| %d, max F_Rh %d, max -F_Rh %d\n", kinks_by_force[sling_perpendicular], kinks_by_force[pivot_reaction],
                kinks_by_force[pivot_horizontal], kinks_by_force[pivot_horizontal_negated]);
    std::printf("  warned before the release: slack sling %d, counterweight below the base %d, beam tip below the base %d\n", slack,
                counterweight_low, tip_low);
    for (const Deviation* dev : {&R, &T, &eps, &v, &h, &Q})
      std::printf("  %-3s worst relative deviation %.2e (design %d), target %.0e\n", dev->name, dev->worst, dev->worst_design, dev->target);
  }

  void check() const {
    CHECK(mismatched == 0);
    CHECK(kinks_found == kinks);
    for (const Deviation* dev : {&R, &T, &eps, &v, &h, &Q}) CHECK(dev->worst <= dev->target);
  }
};

}  // namespace

// Targets at the default settings: R, T, eps, v and h within 1e-8 relative, Q within 1e-9.
// The reference integrates at rtol 1e-14 and places every instant by bisection to round-off,
// so its own error is well below them; the library integrates at rtol = atol = 1e-11
// (docs/performance.md), 2.8e-9 in h and 3.2e-10 in Q at worst here. A release placed past a kink
// of Q, as before issue 12, misses by 1e-5 in R (the issue's example) and fails here, and so
// does the quintic interpolant of before, by 1.8e-7 in R and 1e-8 in Q. Since issue 26 the
// reference seeks the release over the whole of phase II (tests/reference), so a release search
// that ranks maxima by where the samples are highest fails here too, on about 1 % of such designs.
TEST_CASE("the shot agrees with the independent reference on 500 random designs", "[reference][shot][heavy]") {
  std::mt19937_64 random(20261121);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
  // The sanitizer pass checks every 10th design (TREBUCHET_REFERENCE_STRIDE=10, scripts/test.sh):
  // the same code paths at a tenth of the cost under AddressSanitizer.
  const char* stride_text = std::getenv("TREBUCHET_REFERENCE_STRIDE");
  const int stride = stride_text ? std::max(1, std::atoi(stride_text)) : 1;
  Agreement agreement;
  for (int design = 0; design < 500; ++design) {
    const reference::Design d{uniform(3.5, 7), uniform(0.7, 1.2), uniform(0.03, 0.15), uniform(0.004, 0.02), uniform(25, 45), uniform(0.5, 1)};
    const double L2 = uniform(0.3, 1.5);
    if (design % stride == 0) agreement.compare(d, L2, design);
  }
  agreement.report("500 random designs");
  agreement.check();
  CHECK(agreement.shot >= 400 / stride);
  CHECK(agreement.kinks > 0);  // the set exercises releases at a kink
}

// Issue 26: designs whose best release lies in a narrow window between two step ends, away
// from the step end where Q is highest: at an onset of growth of a running extreme (a kink) or
// on a second smooth hump. They were found among 2000 random designs with short slings and
// steep theta_i (l4 = L4/L1 0.15-0.5, theta_i 38-50 deg; the other parameters as above) as the
// 26 (1.3 %) where the release search of before issue 26, which looked only around the best step
// end, gave a Q lower by 1.3e-5 to 3.5e-2 (the comment on each row); the values are rounded to 6
// digits. The same search over 2000 designs of the ranges above found none, so the random set
// has none either. The issue's own design is the first.
TEST_CASE("releases at narrow maxima between step ends agree with the reference", "[reference][shot]") {
  const std::vector<reference::Design> designs{
      {2.324262562133648 / 0.43196974412459677, 0.45949581858546434 / 2.324262562133648, 168.5891228353421 / 5000, 22.796138875393417 / 5000,
       44.258495756036226, 0.9863316173552241},  // issue 26: Q +8.2e-04
      {5.984199, 0.306437, 0.058104, 0.010669, 45.4437, 0.837054},  // Q +3.6e-03
      {4.284906, 0.354257, 0.100691, 0.007267, 45.4872, 0.737451},  // Q +7.6e-05
      {4.350247, 0.286428, 0.116216, 0.007542, 41.7099, 0.937654},  // Q +3.2e-04
      {3.961526, 0.153164, 0.087092, 0.014486, 47.2900, 0.681249},  // Q +1.0e-02
      {3.911539, 0.313735, 0.049683, 0.012567, 44.0814, 0.683450},  // Q +1.0e-02
      {6.717478, 0.242034, 0.048409, 0.004292, 47.0854, 0.551908},  // Q +3.5e-02
      {3.831510, 0.305008, 0.147705, 0.014464, 49.1864, 0.881166},  // Q +7.3e-03
      {5.358214, 0.377479, 0.094609, 0.019007, 42.8900, 0.956891},  // Q +9.1e-03
      {6.418719, 0.220668, 0.149950, 0.011305, 40.7154, 0.980606},  // Q +1.4e-03
      {4.252301, 0.243110, 0.034280, 0.006176, 42.8737, 0.710393},  // Q +2.2e-03
      {3.811980, 0.167176, 0.091649, 0.006420, 49.1800, 0.938640},  // Q +4.3e-03
      {6.007128, 0.335242, 0.123051, 0.005699, 38.8406, 0.693514},  // Q +1.2e-02
      {5.154707, 0.191512, 0.119893, 0.006318, 46.1546, 0.526764},  // Q +2.4e-04
      {5.493370, 0.330394, 0.052551, 0.019191, 49.5784, 0.888710},  // Q +1.2e-02
      {4.779496, 0.187601, 0.038259, 0.012302, 44.9987, 0.723612},  // Q +8.6e-03
      {5.789148, 0.287454, 0.097416, 0.007050, 49.6852, 0.836089},  // Q +1.9e-03
      {4.834639, 0.245042, 0.046218, 0.018165, 42.3149, 0.849310},  // Q +4.7e-03
      {4.626623, 0.241387, 0.083714, 0.005251, 48.9068, 0.919113},  // Q +8.8e-03
      {4.387167, 0.158942, 0.143543, 0.008221, 44.7277, 0.680301},  // Q +1.4e-02
      {6.198545, 0.331027, 0.043670, 0.007562, 45.8369, 0.539753},  // Q +1.3e-05
      {3.873935, 0.237805, 0.125563, 0.012744, 42.2826, 0.981911},  // Q +3.0e-04
      {3.583536, 0.443424, 0.120491, 0.018052, 41.5260, 0.631957},  // Q +1.2e-02
      {4.974082, 0.191273, 0.132567, 0.018036, 46.6557, 0.608800},  // Q +9.8e-03
      {4.271023, 0.221477, 0.030911, 0.004410, 47.6867, 0.932586},  // Q +6.3e-03
      {5.006219, 0.244774, 0.071624, 0.007718, 47.7537, 0.690813},  // Q +3.6e-03
      {5.730332, 0.195358, 0.136360, 0.018839, 45.5711, 0.630720},  // Q +2.3e-03
  };
  Agreement agreement;
  for (std::size_t i = 0; i < designs.size(); ++i) agreement.compare(designs[i], 0.5, static_cast<int>(i));
  agreement.report("narrow maxima");
  agreement.check();
  CHECK(agreement.shot == static_cast<int>(designs.size()));
}

// Issue 26's design, in engine units: two maxima of Q, A (smooth, at 0.5233 s) and B, 8.2e-4
// higher, where max F_S_perp starts to grow, inside a window ~0.55 ms wide between two step ends
// 4.6 ms apart. The issue located B by a fine grid of Q(t) and two independent models:
// t_r = 0.564518409 s and Q = 3.6475658988e-3, given to 9 and 11 digits, so 1e-9 s and 1e-9
// relative cover their rounding (5e-10 s, 1.4e-11) with the library's own error (3e-10 in Q, above).
TEST_CASE("issue 26: the release is at the higher, narrow maximum B", "[reference][shot]") {
  Engine engine;
  engine.theta_i_deg = 44.258495756036226, engine.L1 = 2.3242625621336477, engine.L2 = 0.43196974412459677;
  engine.L4 = 0.45949581858546434, engine.M = 5000, engine.m = 22.796138875393417, engine.mb = 168.5891228353421;
  engine.L3 = counterweight_arm(engine.L1, engine.L2, engine.theta_i_deg, 0.9863316173552241);
  const ShotResult shot = simulate_shot(scaled_design(engine), ReleaseCriterion{}, IntegratorSettings{});
  const double time_unit = std::sqrt(engine.L2 / engine.material.g);  // [s]
  std::printf("issue 26: release at %.10f s (B: 0.564518409), Q %.11e (B: 3.6475658988e-3)\n", shot.release.t * time_unit, shot.release.quality);
  CHECK(std::abs(shot.release.t * time_unit - 0.564518409) < 1e-9);
  CHECK(shot.release.quality == Approx(3.6475658988e-3).epsilon(1e-9));
  CHECK(shot.release_at_growth_of == sling_perpendicular);
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
  std::printf("issue 12 kink: release %.3e s from the reference, R %.1e, Q %.1e relative\n", (ours.release.t - ref.t_release) * time_unit,
              ours.release.range / ref.rho - 1, ours.release.quality / ref.Q - 1);
  REQUIRE(ref.onset == pivot_horizontal);
  REQUIRE(ours.release_at_growth_of == pivot_horizontal);
  CHECK(std::abs(ours.release.t - ref.t_release) * time_unit < 1e-9);
  CHECK(ours.release.range == Approx(ref.rho).epsilon(1e-8));
  CHECK(ours.release.quality == Approx(ref.Q).epsilon(1e-9));
}
