// Quadratic drag on a sphere: the one form of air the flight (air.hpp) and the shot before
// its release (design.hpp, BuiltParts) share.
#pragma once

#include <optional>

namespace trebuchet {

/// Cd(Re) of a smooth sphere, by Morrison's correlation (2013; air.cpp cites the form), fitted
/// up to Re = max_fitted_reynolds; beyond it the value is an extrapolation.
double drag_coefficient_of(double reynolds);
/// Its slope, dCd/dRe (0 for Re <= 0).
double drag_coefficient_slope_of(double reynolds);
inline constexpr double max_fitted_reynolds = 1e6;

/// Drag in the units of a flight: SI, or scaled by L2 and sqrt(L2/g) (section 3). The drag
/// acceleration is -Cd per_length |u| u, u the velocity through the air.
struct Drag {
  double per_length = 0;  ///< rho_air A / (2 m), A the sphere's cross-section
  std::optional<double> drag_coefficient;  ///< constant Cd; nullopt: Cd(reynolds_per_speed |u|)
  double reynolds_per_speed = 0;  ///< rho_air d / viscosity
  double wind = 0;  ///< toward the target
  /// Cd at the speed |u| through the air.
  double coefficient_at(double speed) const { return drag_coefficient ? *drag_coefficient : drag_coefficient_of(reynolds_per_speed * speed); }
  /// dCd/d|u| at the speed |u|: 0 for a constant Cd.
  double coefficient_slope_at(double speed) const {
    return drag_coefficient ? 0 : reynolds_per_speed * drag_coefficient_slope_of(reynolds_per_speed * speed);
  }
};

}  // namespace trebuchet
