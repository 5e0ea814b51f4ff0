#include "trebuchet/quality.hpp"

#include <algorithm>
#include <cmath>

namespace trebuchet {

ForceValues force_values(const Snapshot& s) {
  return {s.sling_perpendicular, std::hypot(s.pivot_reaction.x, s.pivot_reaction.y), s.pivot_reaction.x, -s.pivot_reaction.x};
}

void ForceExtremes::add(const ForceValues& values) {
  for (int k = 0; k < force_count; ++k) max[k] = std::max(max[k], values[k]);
}

double energy_at_target(double mu, Vec2 v, double height) { return mu * (0.5 * (v.x * v.x + v.y * v.y) + height); }  // eq:T

double efficiency(double tau_e, double energy_drop) { return tau_e / energy_drop; }  // eq:Aux

double force_factor(const ForceExtremes& e, double mu) {
  const double sling = e.max[sling_perpendicular] / mu;  // F_S_perp / (m g)
  const double spread = e.max[pivot_horizontal] + e.max[pivot_horizontal_negated];  // Delta F_Rh / (M g)
  return std::pow(sling * sling * e.max[pivot_reaction] * spread, 0.25);  // eq:F
}

double quality(double rho, double l, double mu, double eps, double force_factor, double n) {
  return rho / l * mu * std::pow(eps, n) / force_factor;  // eq:Q, eq:Q_n
}

}  // namespace trebuchet
