#include "trebuchet/capacity_fit.hpp"

#include <cmath>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/solve_1d.hpp"

namespace trebuchet {

EngineShape engine_shape(const Engine& engine) {
  const ScaledDesign s = scaled_design(engine);
  return {s.l, s.l4, s.mu_b, engine.theta_i_deg, arm_fraction(engine)};
}

Engine engine_of_shape(const EngineShape& shape, double mu, double L2, const Material& material) {
  const double K = (shape.l + 1) / shape.mu_b;  // eq:kMkD
  Engine e;
  e.theta_i_deg = shape.theta_i_deg;
  e.L2 = L2;
  e.L1 = shape.l * L2;
  e.L3 = counterweight_arm(e.L1, L2, shape.theta_i_deg, shape.F);
  e.L4 = shape.l4 * e.L1;
  e.M = K * K * k_M(material) / material.beta2 * std::pow(L2, 4);       // eq:ExtraScalings [kg]
  e.D = std::sqrt(K * k_D(material) / material.beta2) * std::pow(L2, 1.5);  // eq:ExtraScalings [m]
  e.m = mu * e.M;
  e.mb = shape.mu_b * e.M;
  return e;
}

CapacityFit fit_capacity(const EngineShape& shape, double R, double T, const Material& material,
                         const ShotSettings& settings, double rtol) {
  ShotSettings level_zero = settings;
  level_zero.target_level = 0;
  level_zero.g = material.g;
  CapacityFit fit;
  // At level 0, R/L2 and T/(M g L2) depend on mu alone. One shot of the engine with L2 = 1 m
  // gives the L2 that lands at R, and the T delivered there: T grows as L2^5 (eq:ExtraScalings).
  struct Trial {
    double L2, T;
  };
  auto trial = [&](double mu) {
    const Verification unit = verify_engine(engine_of_shape(shape, mu, 1.0, material), level_zero);
    ++fit.simulations;
    const double L2 = R / unit.R;
    return Trial{L2, unit.T * std::pow(L2, 5)};
  };
  auto log_T_error = [&](double log_mu) { return std::log(trial(std::exp(log_mu)).T / T); };
  // First guess without a shot: T ~ m g R / 2 gives m (section 4), and T ~ 0.9 Delta U with
  // Delta U = M g L2 (1 - mu_b (l - 1)/2)(1 + cos th_i) (eq:DU) and M ~ L2^4 gives L2 and M.
  const Engine unit_size = engine_of_shape(shape, 1.0, 1.0, material);
  const double drop_per_L2_5 = potential_energy_drop(unit_size, material.g);  // Delta U at L2 = 1 m [J]
  const double L2_guess = std::pow(T / (0.9 * drop_per_L2_5), 0.2);
  const double m_guess = 2 * T / (material.g * R);
  const double log_mu_guess = std::log(m_guess / engine_of_shape(shape, 1.0, L2_guess, material).M);
  // T(mu) need not be monotone (the release can move between maxima of the objective), so
  // walk outward from the guess on both sides, 5 % steps in mu, up to a factor 20, and take
  // the first sign change of the T error; shots that fail on the way are stepped over.
  const double step = 0.05, reach = 3.0;
  auto error_or_nan = [&](double log_mu) {
    if (log_mu < std::log(1e-6) || log_mu > 0) return std::nan("");
    try {
      return log_T_error(log_mu);
    } catch (const Error&) {
      return std::nan("");
    }
  };
  const double at_guess = error_or_nan(log_mu_guess);
  double lo = 0, hi = 0;
  bool bracketed = false;
  double previous[2] = {at_guess, at_guess};
  for (int k = 1; !bracketed && k * step <= reach; ++k) {
    for (int side = 0; side < 2 && !bracketed; ++side) {
      const double inner = log_mu_guess + (side ? 1 : -1) * (k - 1) * step, outer = log_mu_guess + (side ? 1 : -1) * k * step;
      const double value = error_or_nan(outer);
      if (std::isfinite(value) && std::isfinite(previous[side]) && (value > 0) != (previous[side] > 0)) {
        lo = std::min(inner, outer), hi = std::max(inner, outer);
        bracketed = true;
      }
      previous[side] = value;
    }
  }
  if (!bracketed)
    throw Error(ErrorKind::out_of_range, "no projectile mass within a factor 20 of m = 2T/(gR) = " + format_significant(m_guess, 3) +
                                             " kg lets this shape deliver " + format_significant(T / 1e3, 4) + " kJ at " +
                                             format_significant(R, 4) + " m; change the shape (l, l4, mu_b) or the capacity");
  const double log_mu = find_root(log_T_error, lo, hi, 0.1 * rtol, 0);
  const double mu = std::exp(log_mu);
  fit.engine = engine_of_shape(shape, mu, trial(mu).L2, material);
  fit.verification = verify_engine(fit.engine, level_zero);
  ++fit.simulations;
  if (!(std::abs(fit.verification.R / R - 1) <= rtol && std::abs(fit.verification.T / T - 1) <= rtol))
    throw Error(ErrorKind::numerical, "the capacity fit reached R = " + format_significant(fit.verification.R, 8) +
                                          " m, T = " + format_significant(fit.verification.T, 8) + " J, not within " +
                                          format_significant(rtol, 2) + " of the request: T jumps with mu here, as the "
                                          "release moves from one maximum of the objective to another");
  return fit;
}

}  // namespace trebuchet
