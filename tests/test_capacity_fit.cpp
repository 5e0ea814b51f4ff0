// The capacity fit (section 5, steps 2-4) against engines whose capacity is known.
#include <catch2/catch.hpp>
#include <cmath>

#include "trebuchet/capacity_fit.hpp"
#include "trebuchet/error.hpp"

using namespace trebuchet;

// An engine built from a shape with a known mu and L2 delivers some (R, T); fitting the shape
// to that (R, T) must give back mu and L2. The fit stops at 1e-6 relative in T; T ~ mu and
// R ~ L2 near the solution, so mu and L2 come back to a few 1e-6.
TEST_CASE("the capacity fit recovers the engine that delivered the capacity", "[fit][physics]") {
  const EngineShape shapes[] = {{5.68, 5.80 / 6.13, 660.0 / 14300, 30, 1}, {6.77, 5.69 / 6.20, 601.0 / 16900, 30, 2.0 / 3},
                                {4.69, 3.55 / 4.13, 174.0 / 3110, 30, 2.0 / 3}};
  for (const EngineShape& shape : shapes) {
    const double mu = 0.0071, L2 = 1.1;
    const Engine truth = engine_of_shape(shape, mu, L2, Material{});
    const Verification target = verify_engine(truth, ShotSettings{});
    const CapacityFit fit = fit_capacity(shape, target.R, target.T, Material{}, ShotSettings{});
    INFO("l = " << shape.l << ": " << fit.simulations << " shots");
    CHECK(std::abs(fit.verification.R / target.R - 1) < 1e-6);
    CHECK(std::abs(fit.verification.T / target.T - 1) < 1e-6);
    CHECK(std::abs(fit.engine.m / fit.engine.M / mu - 1) < 1e-5);
    CHECK(std::abs(fit.engine.L2 / L2 - 1) < 1e-5);
    CHECK(fit.simulations < 40);
  }
}

// eq:ExtraScalings: a shape fitted at lambda^5 times the energy and lambda times the range is
// the same engine lambda times larger (same mu), so eps and Q agree.
TEST_CASE("fits of one shape to scaled capacities are scaled engines", "[fit][physics]") {
  const EngineShape shape{5.68, 5.80 / 6.13, 660.0 / 14300, 30, 1};
  const CapacityFit a = fit_capacity(shape, 450, 235e3, Material{}, ShotSettings{});
  const double lambda = 0.5;
  const CapacityFit b = fit_capacity(shape, 450 * lambda, 235e3 * std::pow(lambda, 5), Material{}, ShotSettings{});
  CHECK(std::abs(b.engine.L2 / (a.engine.L2 * lambda) - 1) < 1e-5);
  CHECK(std::abs(b.engine.m / b.engine.M / (a.engine.m / a.engine.M) - 1) < 1e-5);
  CHECK(std::abs(b.verification.eps - a.verification.eps) < 1e-6);
  CHECK(std::abs(b.verification.Q / a.verification.Q - 1) < 1e-5);
}

TEST_CASE("a capacity out of a shape's reach is a named error", "[fit]") {
  const EngineShape shape{5.68, 5.80 / 6.13, 660.0 / 14300, 30, 1};
  // 450 m with 1 J: a projectile of 0.2 g, far below what the shape can throw that far.
  CHECK_THROWS_AS(fit_capacity(shape, 450, 1, Material{}, ShotSettings{}), Error);
}
