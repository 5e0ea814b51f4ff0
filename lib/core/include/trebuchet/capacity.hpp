// A capacity (section 1): the range R and the energy T delivered at a target level, and the
// rotated coordinates (X, Y) of eq:XY_RT in which optimal engines scale along constant X.
#pragma once

namespace trebuchet {

struct Capacity {
  double R = 0;  ///< range from the pivot to the impact at the target level [m]
  double T = 0;  ///< kinetic energy at the target level, eq:T [J]
  double target_level = 0;  ///< target height relative to the engine's base [m], e.g. -54
};

/// (X, Y) of eq:XY_RT, scaled.
struct CapacityCoordinates {
  double X = 0;
  double Y = 0;
};

/// eq:XY_RT (and eq:Xi for X) from log(R/R0) and log(T/T0).
CapacityCoordinates capacity_coordinates(double log_R_ratio, double log_T_ratio);

/// eq:XY_RT inverted: the capacity at (X, Y) for the reference (R0 [m], T0 [J]), level 0.
Capacity capacity_at(CapacityCoordinates coordinates, double R0, double T0);

}  // namespace trebuchet
