// The propped counterweight of section 7.2 (sec:SVdH): row 2 of tab:SketchBook-I reaches its highest
// efficiency, 93.0 %, at psi_i = -4.6 deg (issue 14, part 6).
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <iostream>
#include <memory>

#include "trebuchet/engine.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;

namespace {
// tab:SketchBook-I row 2 as printed: F = 2/3, theta_i = 30 deg, L1 = 6.20 m, Lb = 7.12 m,
// L4 = 5.69 m, M = 16.9 t, m = 100 kg, mb = 601 kg; eps = 92.6 % unpropped.
Engine row2(double psi_i_deg) {
  Engine e;
  e.L1 = 6.20, e.L2 = 7.12 - 6.20, e.L4 = 5.69, e.M = 16900, e.m = 100, e.mb = 601, e.theta_i_deg = 30;
  e.L3 = counterweight_arm(e.L1, e.L2, 30, 2.0 / 3);
  e.psi_i_deg = psi_i_deg;
  return e;
}

double eps_at(double psi_i_deg) { return verify_engine(row2(psi_i_deg), ShotSettings{}).eps; }
}  // namespace

TEST_CASE("a propped counterweight: the energy drop includes its extra height", "[propped]") {
  // eq:DU with the counterweight L3 (1 - cos psi_i) higher above its final rest: exact.
  const Engine hanging = row2(0), propped = row2(-10);
  const double extra = propped.M * propped.material.g * propped.L3 * (1 - std::cos(10 * M_PI / 180));
  CHECK(potential_energy_drop(propped) - potential_energy_drop(hanging) == Approx(extra).epsilon(1e-12));
  // And the shot conserves the energy it starts with, propped or not (the integrator's 1e-11).
  CHECK(verify_engine(propped, ShotSettings{}).energy_drift < 1e-9);
}

TEST_CASE("tab:SketchBook-I row 2 propped: eps peaks near psi_i = -4.6 deg", "[propped][paper]") {
  // The scan shows the sign convention: holding the counterweight back (psi_i < 0, against the
  // sense in which theta grows) helps; pushing it forward hurts.
  for (double psi = -10; psi <= 5; psi += 2.5) std::cout << "psi_i = " << psi << " deg: eps = " << 100 * eps_at(psi) << " %\n";
  CHECK(eps_at(-4.6) > eps_at(0));
  CHECK(eps_at(4.6) < eps_at(0));

  // The maximum, by GSL's Brent minimiser on -eps over [-10, 0] deg.
  gsl_set_error_handler_off();
  gsl_function minus_eps{[](double psi, void*) { return -eps_at(psi); }, nullptr};
  std::unique_ptr<gsl_min_fminimizer, decltype(&gsl_min_fminimizer_free)> minimizer(gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent),
                                                                                    gsl_min_fminimizer_free);
  REQUIRE(gsl_min_fminimizer_set(minimizer.get(), &minus_eps, -4, -10, 0) == GSL_SUCCESS);
  for (int k = 0; k < 100; ++k) {
    gsl_min_fminimizer_iterate(minimizer.get());
    if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(minimizer.get()), gsl_min_fminimizer_x_upper(minimizer.get()), 0.01, 0) == GSL_SUCCESS)
      break;
  }
  const double best_psi = gsl_min_fminimizer_x_minimum(minimizer.get()), best_eps = eps_at(best_psi), gain = best_eps - eps_at(0);
  std::cout << "maximum: eps = " << 100 * best_eps << " % at psi_i = " << best_psi << " deg (paper: 93.0 % at -4.6 deg), a gain of " << 100 * gain
            << " points over unpropped (paper: 93.0 - 92.6 = 0.4)\n";
  // The top is flat: within 1.5 deg of it eps moves by at most 0.05 points (the scan: 92.78 %
  // at -2.5 deg), the printed eps's rounding, so the paper's -4.6 places it no closer than that.
  CHECK(std::abs(best_psi - -4.6) < 1.5);
  // The gain, from two printed values each rounded to 0.05 points: 0.4 +- 0.1. The absolute eps
  // is not compared: the printed row's L2 = 7.12 - 6.20 m is uncertain by 1 %.
  CHECK(std::abs(100 * gain - 0.4) <= 0.1);
}
