#include "trebuchet/quality.hpp"

#include <algorithm>
#include <cmath>

namespace trebuchet {

ForceValues force_values(const Snapshot& s) {
  const Vec2& r = s.pivot_reaction;  // of order M g: no overflow to guard against, as hypot would
  // The frame is pushed along the ground at the pivot, and at the floating arm's guide, whose rail takes none.
  const double horizontal = r.x + s.guide_force.x;
  return {s.sling_perpendicular, std::sqrt(r.x * r.x + r.y * r.y), horizontal, -horizontal};
}

void ForceExtremes::add(const ForceValues& values) {
  for (int k = 0; k < force_count; ++k) max[k] = std::max(max[k], values[k]);
}

double energy_at_target(double mu, Vec2 v, double height) { return mu * (0.5 * (v.x * v.x + v.y * v.y) + height); }  // eq:T

double efficiency(double tau_e, double energy_drop) { return tau_e / energy_drop; }  // eq:Aux

double force_factor(const ForceExtremes& e, double mu) {
  const double sling = e.max[sling_perpendicular] / mu;  // F_S_perp / (m g)
  const double spread = e.max[pivot_horizontal] + e.max[pivot_horizontal_negated];  // Delta F_Rh / (M g)
  return std::sqrt(std::sqrt(sling * sling * e.max[pivot_reaction] * spread));  // eq:F, a fourth root
}

double quality(double rho, double l, double mu, double eps, double force_factor, double n) {
  return rho / l * mu * (n == 1 ? eps : std::pow(eps, n)) / force_factor;  // eq:Q, eq:Q_n
}

}  // namespace trebuchet
