#include "trebuchet/capacity.hpp"

#include <cmath>

namespace trebuchet {
namespace {
const double sqrt26 = std::sqrt(26.0);
}  // namespace

CapacityCoordinates capacity_coordinates(double log_R_ratio, double log_T_ratio) {
  return {(5 * log_R_ratio - log_T_ratio) / sqrt26, (log_R_ratio + 5 * log_T_ratio) / sqrt26};  // eq:XY_RT; X is eq:Xi
}

Capacity capacity_at(CapacityCoordinates c, double R0, double T0) {
  // The rotation of eq:XY_RT is orthogonal: its inverse is its transpose.
  return {R0 * std::exp((5 * c.X + c.Y) / sqrt26), T0 * std::exp((-c.X + 5 * c.Y) / sqrt26), 0};
}

}  // namespace trebuchet
