// The ab-initio optimizer (issue 5, first part): it never returns a design that misses the
// capacity, it improves on its start, and it is deterministic.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "trebuchet/optimizer.hpp"

using namespace trebuchet;

TEST_CASE("the optimum for (425 m, 224 kJ) delivers the capacity and beats its start", "[optimizer]") {
  OptimizeRequest request;
  request.R = 425, request.T = 224e3, request.F = 1;
  const std::vector<Optimum> optima = optimize(request);
  REQUIRE(!optima.empty());
  for (const Optimum& o : optima) {
    INFO(o.start);
    // The capacity fit's own check: 1e-6 in R and T.
    CHECK(std::abs(o.fit.verification.R / 425 - 1) < 1e-6);
    CHECK(std::abs(o.fit.verification.T / 224e3 - 1) < 1e-6);
    // The calculator's design, fitted to the capacity ab initio, is where the search began.
    const CapacityFit start = fit_capacity(o.start_shape, 425, 224e3, Material{}, ShotSettings{});
    CHECK(o.objective > start.verification.Q);
    std::printf("start Q %.4f %% -> optimum (%s): Q %.4f %%, eps %.2f %%, l %.3f, l4 %.4f, mu_b %.5f, %d shots\n", 100 * start.verification.Q, o.start.c_str(), 100 * o.objective,
                100 * o.fit.verification.eps, o.shape.l, o.shape.l4, o.shape.mu_b, o.simulations);
  }
  // Same inputs, same numbers, bit for bit.
  const std::vector<Optimum> again = optimize(request);
  REQUIRE(again.size() == optima.size());
  CHECK(again[0].objective == optima[0].objective);
  CHECK(again[0].fit.engine.L4 == optima[0].fit.engine.L4);
}
