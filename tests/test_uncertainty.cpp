// Uncertain inputs and the Monte Carlo run (issue 14, part 3).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "trebuchet/error.hpp"
#include "trebuchet/uncertainty.hpp"
#include "trebuchet/app/input/units.hpp"

using namespace trebuchet;

TEST_CASE("ranges and spreads read with their units", "[uncertainty]") {
  const auto range = parse_spread("2.5t..3.5t", UnitDimension::mass, "--M");
  REQUIRE(range);
  CHECK(range->kind == Spread::Kind::uniform);
  CHECK(range->a == 2500);
  CHECK(range->b == 3500);
  const auto spread = parse_spread("3.5m\u00b10.2m", UnitDimension::length, "--L4");
  REQUIRE(spread);
  CHECK(spread->kind == Spread::Kind::normal);
  CHECK(spread->a == 3.5);
  CHECK(spread->b == Approx(0.2).epsilon(1e-15));
  CHECK(parse_spread("350cm+-20cm", UnitDimension::length, "--L4")->a == Approx(3.5).epsilon(1e-15));
  CHECK(!parse_spread("3.5m", UnitDimension::length, "--L4"));
  CHECK_THROWS_WITH(parse_spread("3.5t..2.5t", UnitDimension::mass, "--M"), Catch::Contains("not a range from low to high"));
  CHECK_THROWS_WITH(parse_spread("3.5m..4kg", UnitDimension::length, "--L4"), Catch::Contains("is a mass"));
}

TEST_CASE("a spread written as text reads back to the same bits, in every dimension a run may spread", "[uncertainty]") {
  // A run's report writes its spreads as text (spread_text) and reads them again: any lost bit
  // would draw other numbers. The ends are chosen so that a short or rounded form would not do.
  const std::vector<std::pair<Spread, UnitDimension>> cases = {
      {{Spread::Kind::uniform, 0.1 + 0.2, 0.7}, UnitDimension::length}, {{Spread::Kind::normal, 1900.0000000000002, 1e-7}, UnitDimension::mass},
      {{Spread::Kind::uniform, -60, -54.3}, UnitDimension::length},  // a target level below the base
      {{Spread::Kind::normal, 35, 2.5}, UnitDimension::angle},          {{Spread::Kind::uniform, -3, 1e-300}, UnitDimension::speed},
      {{Spread::Kind::normal, 1.225, 0.05}, UnitDimension::density},    {{Spread::Kind::uniform, 0.4, 0.6}, UnitDimension::dimensionless},
      {{Spread::Kind::normal, 45, 5}, UnitDimension::inertia},
  };
  for (const auto& [spread, dimension] : cases) {
    const std::string text = spread_text(spread, dimension);
    INFO(text);
    const auto read = parse_spread(text, dimension, "M");
    REQUIRE(read);
    CHECK(read->kind == spread.kind);
    CHECK(read->a == spread.a);
    CHECK(read->b == spread.b);
  }
  CHECK(spread_text({Spread::Kind::uniform, 1900, 2100}, UnitDimension::mass) == "1900kg..2100kg");
  CHECK(spread_text({Spread::Kind::normal, 3.55, 0.2}, UnitDimension::length) == "3.55m\u00b10.2m");
}

TEST_CASE("a Monte Carlo run is the same on any number of threads, and new with a new seed", "[uncertainty]") {
  const Spread uniform{Spread::Kind::uniform, 100, 200}, normal{Spread::Kind::normal, 50, 5};
  auto sample = [&](std::mt19937_64& random) {
    SampleOutcome o;
    o.values = {draw(uniform, random), draw(normal, random), 0.9, 40};
    if (o.values[0] > 195) o.failure = "too far: beyond " + std::to_string(o.values[0]) + " m", o.failure_kind = ErrorKind::out_of_range;
    return o;
  };
  const MonteCarloSummary one = run_monte_carlo(10000, 7, 1, sample), two = run_monte_carlo(10000, 7, 2, sample);
  CHECK(one.values == two.values);
  REQUIRE(one.failures.size() == two.failures.size());
  for (std::size_t k = 0; k < one.failures.size(); ++k)
    CHECK((one.failures[k].reason == two.failures[k].reason && one.failures[k].count == two.failures[k].count &&
           one.failures[k].first == two.failures[k].first));
  CHECK(run_monte_carlo(10000, 8, 2, sample).values != one.values);
  // The failures are counted by reason: about 5 % of a uniform 100..200 lies above 195. The
  // count is binomial, sd sqrt(10000 0.05 0.95) = 22: 4 sd is 87.
  REQUIRE(one.failures.size() == 1);
  CHECK(one.failures.front().reason == "too far: beyond # m");
  CHECK(std::abs(one.failures.front().count - 500) < 87);
  // The first failing sample's own message, numbers and all, and its kind, are kept.
  CHECK_THAT(one.failures.front().first, Catch::Matches("too far: beyond 19[5-9]\\.[0-9]+ m"));
  CHECK(one.failures.front().kind == ErrorKind::out_of_range);
  // Percentiles of what worked (uniform on 100..195, normal 50 ± 5), each to 4 standard errors
  // of a quantile, sqrt(p (1 - p)/N)/density with N = 9500: 0.49 m for the uniform's median
  // (density 1/95 per m), 0.064 for the normal's (density 0.080), 0.109 at 5 and 95 % (0.021).
  CHECK(one.percentiles[0][1] == Approx(147.5).margin(4 * 0.49));
  CHECK(one.percentiles[1][1] == Approx(50).margin(4 * 0.064));
  CHECK(one.percentiles[1][0] == Approx(50 - 1.645 * 5).margin(4 * 0.109));
  CHECK(one.percentiles[1][2] == Approx(50 + 1.645 * 5).margin(4 * 0.109));
}

TEST_CASE("a claim's odds carry Wilson's 95 % interval", "[uncertainty]") {
  // Wilson's score interval at z = 1.96, from its formula by hand: 0 of 10 gives 0 to
  // z^2/(n + z^2) = 0.2775; 5 of 10 gives 0.5 -+ 0.2634 (to 1e-4, the figures' rounding).
  const auto summary_of = [](int reached, int n) {
    std::vector<SampleOutcome> outcomes(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
      outcomes[static_cast<std::size_t>(i)] = {{i < reached ? 200.0 : 100.0, 1, 0.5, 30}, {double(i)}, "", ErrorKind::numerical};
    return summarize_samples(outcomes);
  };
  const ClaimAssessment none = assess_claim(summary_of(0, 10), 150);
  CHECK(none.reached == 0);
  CHECK(none.low == 0);
  CHECK(none.high == Approx(0.2775).margin(1e-4));
  const ClaimAssessment half = assess_claim(summary_of(5, 10), 150);
  CHECK(half.probability == 0.5);
  CHECK(half.low == Approx(0.2366).margin(1e-4));
  CHECK(half.high == Approx(0.7634).margin(1e-4));
  // The samples that reach it drew 0 to 4: their median is 2.
  REQUIRE(half.median_reaching.size() == 1);
  CHECK(half.median_reaching[0] == 2);
}

TEST_CASE("the rank correlation ranks an input that moves R monotonically above one that does not", "[uncertainty]") {
  // R = x^3 (monotone: Spearman's rho is exactly 1 whatever the shape), y drawn apart from it:
  // its rho is near 0 within the sampling error 1/sqrt(n - 1) = 0.03 of 1000 samples (3 of them).
  std::mt19937_64 random(7);
  std::vector<SampleOutcome> outcomes;
  for (int i = 0; i < 1000; ++i) {
    const double x = std::uniform_real_distribution<double>(1, 2)(random), y = std::uniform_real_distribution<double>(1, 2)(random);
    outcomes.push_back({{x * x * x, 1, 0.5, 30}, {y, x}, "", ErrorKind::numerical});
  }
  const std::vector<RankCorrelation> rho = rank_correlations(summarize_samples(outcomes));
  REQUIRE(rho.size() == 2);
  CHECK(std::abs(rho[0].rho) < 0.1);
  CHECK(rho[1].rho == Approx(1).margin(1e-12));
  CHECK(rho[1].resolved());
}

TEST_CASE("a rank correlation is resolved only where its 95 % interval leaves out 0", "[uncertainty]") {
  // Inputs drawn apart from R: their rho is noise, near normal in Fisher's z with the standard
  // deviation sqrt(1.06/(n - 3)). Over 200 such inputs of 100 samples each, about 5 % are
  // resolved by chance (binomial: 10 expected, 2 to 20 with more than 99.8 % probability); and
  // the interval holds the true 0 in the others. An input that moves R weakly (R = y + 4 x, y
  // spread 10 times as wide) is resolved at 2000 samples, where rho's noise is 0.02.
  std::mt19937_64 random(11);
  const auto uniform = [&] { return std::uniform_real_distribution<double>(0, 1)(random); };
  std::vector<SampleOutcome> outcomes;
  for (int i = 0; i < 100; ++i) {
    std::vector<double> drawn;
    for (int k = 0; k < 200; ++k) drawn.push_back(uniform());
    outcomes.push_back({{uniform(), 1, 0.5, 30}, drawn, "", ErrorKind::numerical});
  }
  int by_chance = 0;
  for (const RankCorrelation& c : rank_correlations(summarize_samples(outcomes))) {
    CHECK(c.low < c.rho);
    CHECK(c.rho < c.high);
    // Near 0 the interval is +-tanh(1.96 sqrt(1.06/97)) = +-0.20; it narrows as rho nears +-1.
    if (std::abs(c.rho) < 0.05) CHECK(c.high - c.low == Approx(2 * std::tanh(1.96 * std::sqrt(1.06 / 97))).epsilon(0.01));
    by_chance += c.resolved();
  }
  std::printf("resolved by chance: %d of 200 inputs that do not move R (about 10 expected)\n", by_chance);
  CHECK(by_chance >= 2);
  CHECK(by_chance <= 20);
  outcomes.clear();
  for (int i = 0; i < 2000; ++i) {
    const double x = uniform(), y = 40 * uniform();
    outcomes.push_back({{y + 4 * x, 1, 0.5, 30}, {x}, "", ErrorKind::numerical});
  }
  const RankCorrelation weak = rank_correlations(summarize_samples(outcomes)).front();
  std::printf("a weak input at 2000 samples: rho %.3f, 95 %% interval %.3f to %.3f\n", weak.rho, weak.low, weak.high);
  CHECK(weak.resolved());
  CHECK(weak.rho > 0.03);  // its own rho is near 0.1 (the share of R's variance x explains, 1/101, rooted), the noise 0.023
}
