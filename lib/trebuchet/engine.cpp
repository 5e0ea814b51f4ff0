#include "trebuchet/engine.hpp"

#include <cmath>

namespace trebuchet {
namespace {
double radians(double degrees) { return degrees * M_PI / 180.0; }
}  // namespace

ScaledDesign scaled_design(const Engine& engine) {
  const double l = engine.L1 / engine.L2;
  const double mu_b = engine.mb / engine.M;
  return {l, engine.L4 / engine.L1, engine.L3 / engine.L2, engine.m / engine.M, mu_b, (l + 1) / mu_b};
}

double beam_length(const Engine& engine) { return engine.L1 + engine.L2; }

double pivot_height(const Engine& engine) { return engine.L1 * std::cos(radians(engine.theta_i_deg)); }

double arm_fraction(const Engine& engine) { return (engine.L2 + engine.L3) / pivot_height(engine); }

double counterweight_arm(double L1, double L2, double theta_i_deg, double F) {
  return F * L1 * std::cos(radians(theta_i_deg)) - L2;
}

double potential_energy_drop(const Engine& engine, double g) {
  const double L_CM = (engine.L1 - engine.L2) / 2;  // pivot to beam centre of mass [m]
  return (engine.M * engine.L2 - engine.mb * L_CM) * g * (1 + std::cos(radians(engine.theta_i_deg)));
}

Engine scale_engine(const Engine& engine, double lambda) {
  const double mass = std::pow(lambda, 4);
  Engine scaled = engine;
  scaled.L1 *= lambda;
  scaled.L2 *= lambda;
  scaled.L3 *= lambda;
  scaled.L4 *= lambda;
  scaled.D *= std::pow(lambda, 1.5);
  scaled.M *= mass;
  scaled.m *= mass;
  scaled.mb *= mass;
  return scaled;
}

}  // namespace trebuchet
