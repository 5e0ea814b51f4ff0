// The quality function of section 5 on a state written out by hand: eq:T, eq:Aux, the running
// force extremes, eq:F, eq:Q and eq:Q_n. Every expected value is worked out in the comment
// beside it; the only error is round-off (a few 1e-16), so 1e-14 relative is the tolerance.
#include <catch2/catch.hpp>

#include "trebuchet/quality.hpp"

using namespace trebuchet;

TEST_CASE("eq:T and eq:Aux: energy at the target and efficiency", "[quality]") {
  // mu = 0.01, v = (3, 4) so v^2/2 = 12.5, h = 2: tau_e = 0.01 (12.5 + 2) = 0.145.
  CHECK(energy_at_target(0.01, {3, 4}, 2) == Approx(0.145).epsilon(1e-14));
  CHECK(energy_at_target(0.01, {-3, 4}, 2) == Approx(0.145).epsilon(1e-14));  // the direction does not matter
  // eps = tau_e / (Delta U / (M g L2)) = 0.145 / 1.45 = 0.1.
  CHECK(efficiency(0.145, 1.45) == Approx(0.1).epsilon(1e-14));
}

TEST_CASE("the forces of eq:F from a snapshot, and their running extremes", "[quality]") {
  Snapshot s;
  s.sling_perpendicular = 0.5;
  s.pivot_reaction = {0.3, 4};  // |F_R| = sqrt(0.09 + 16) = 4.01123...
  const ForceValues v = force_values(s);
  CHECK(v[sling_perpendicular] == 0.5);
  CHECK(v[pivot_reaction] == Approx(std::sqrt(16.09)).epsilon(1e-14));
  CHECK(v[pivot_horizontal] == 0.3);
  CHECK(v[pivot_horizontal_negated] == -0.3);
  // Two moments: F_S_perp 0.5 then 0.8, |F_R| 2 then 1.5, F_Rh +0.3 then -0.4. The maxima
  // are 0.8 and 2, F_Rh reaches +0.3 and -0.4, so Delta F_Rh = 0.7.
  ForceExtremes extremes;
  extremes.add({0.5, 2, 0.3, -0.3});
  extremes.add({0.8, 1.5, -0.4, 0.4});
  CHECK(extremes.max[sling_perpendicular] == 0.8);
  CHECK(extremes.max[pivot_reaction] == 2);
  CHECK(extremes.max[pivot_horizontal] == 0.3);
  CHECK(extremes.max[pivot_horizontal_negated] == 0.4);
  // eq:F with mu = 0.01: F_S_perp/(m g) = 0.8/0.01 = 80, so F = (80^2 * 2 * 0.7)^(1/4) = 8960^(1/4).
  const double F = force_factor(extremes, 0.01);
  CHECK(F == Approx(9.72919711639115).epsilon(1e-14));
  // eq:Q: rho~ = rho/l = 50/5 = 10; Q = 10 * 0.01 * 0.9 / F.
  CHECK(quality(50, 5, 0.01, 0.9, F, 1) == Approx(0.009250506380261694).epsilon(1e-14));
  // eq:Q_n: eps^5 = 0.59049 at n = 5; eps^0 = 1 at n = 0 (appendix B's other extreme).
  CHECK(quality(50, 5, 0.01, 0.9, F, 5) == Approx(0.006069257236089698).epsilon(1e-14));
  CHECK(quality(50, 5, 0.01, 0.9, F, 0) == Approx(0.010278340422512992).epsilon(1e-14));
}
