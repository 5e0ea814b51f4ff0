// The step-end interpolant and the odeiv2 wrapper of the shot (lib/core/src/ode.hpp).
#include <catch2/catch.hpp>
#include <array>
#include <cmath>

#include "ode.hpp"

using namespace trebuchet;

// The septic Hermite interpolant matches q, q', q'' and q''' at both ends, so it reproduces any
// polynomial of degree 7 exactly, and its derivative that polynomial's derivative: only
// round-off (a few 1e-15 for values of order 1) separates them.
TEST_CASE("the interpolant between step ends is exact for septics", "[ode]") {
  const std::array<double, 8> c{0.3, -1.2, 0.5, 2, -0.7, 0.25, 0.4, -0.15};
  auto derivative = [&](int order, double t) {
    double sum = 0;
    for (int k = order; k < 8; ++k) {
      double factor = 1;
      for (int j = 0; j < order; ++j) factor *= k - j;
      sum += factor * c[k] * std::pow(t, k - order);
    }
    return sum;
  };
  // A work of a loss after the angle and its speed (ode.hpp): a cubic, which the cubic
  // Hermite interpolant of the work and its power reproduces.
  auto work = [](double t) { return 0.3 - 0.2 * t + 1.7 * t * t - 0.9 * t * t * t; };
  auto power = [](double t) { return -0.2 + 3.4 * t - 2.7 * t * t; };
  auto end = [&](double t) {
    return StepEnd{t, {derivative(0, t), derivative(1, t), work(t)}, {derivative(1, t), derivative(2, t), power(t)}, {derivative(3, t), 0, 0}};
  };
  const StepEnd a = end(0.4), b = end(1.1);
  for (double t : {0.4, 0.5, 0.77, 1.0, 1.1}) {
    const OdeVector y = hermite(a, b, t, 1, 3);
    CHECK(y[0] == Approx(derivative(0, t)).epsilon(1e-13));
    CHECK(y[1] == Approx(derivative(1, t)).epsilon(1e-13));
    CHECK(y[2] == Approx(work(t)).epsilon(1e-14));
  }
}

// Phase III of a pendulum-like engine: the solution between step ends, integrated anew from
// the step start, agrees with the stepped solution at the next step end to the stepping
// tolerance (rtol 1e-11 over one step: 1e-10 is ample).
TEST_CASE("the solution between steps agrees with the stepped one", "[ode]") {
  const Dynamics dynamics(ScaledDesign{5, 0.9, 0.06, 0.01, 30, 2.0 / 3});
  PhaseIntegrator integrator(dynamics, Phase::released, IntegratorSettings{});
  const OdeVector start = {0.5, 0, 0, 0, 0, 0};
  OdeVector y = start;
  double t = 0, h = 1e-3;
  REQUIRE(integrator.step(t, y.data(), 1.0, h));
  REQUIRE(integrator.step(t, y.data(), 1.0, h));
  const OdeVector again = integrator.at(0, start, t);
  for (std::size_t i = 0; i < 4; ++i) CHECK(again[i] == Approx(y[i]).epsilon(1e-10).margin(1e-12));
}
