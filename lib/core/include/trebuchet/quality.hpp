// The quality function of section 5 and what enters it, as pure functions of scaled values:
// the energy at the target (eq:T), the efficiency (eq:Aux), the running extremes of the
// internal forces and the force factor (eq:F), and the quality Q (eq:Q) or Q_n (eq:Q_n).
// Scaled units as in dynamics.hpp: lengths in L2, masses in M, forces in M g.
#pragma once

#include <array>
#include <optional>

#include "trebuchet/air.hpp"
#include "trebuchet/dynamics.hpp"

namespace trebuchet {

/// What the release maximises: the quality eq:Q (eq:Q_n with n), the efficiency (Q_eps of
/// appendix B), or the range (Denny's criterion; the paper's tab:Denny "Present" row).
enum class Release { quality, efficiency, range };

/// The largest exponent n of eq:Q_n that the programs take (docs/stability.md): the paper's
/// tab:SketchBook-I uses 0 to 5.
inline constexpr double max_quality_exponent = 20;

/// A release the user sets instead of an optimum: by the time after the start (t = 0 when the
/// beam leaves rest at theta_i), by the projectile's velocity angle above the horizontal toward
/// the target, or by the pin angle from the long arm (pivot to tip) to the sling (tip to
/// projectile). Each is the first crossing after lift-off: the time rising to the value, an
/// angle falling to it (docs/verifier.md, "A given release").
enum class ReleaseBy { time, velocity_angle, pin_angle };
struct GivenRelease {
  ReleaseBy by = ReleaseBy::time;
  double value = 0;  ///< scaled time, or [rad]
  double time_unit = 1;  ///< [s] per scaled time: the messages give seconds
  /// What the messages add to an angle watched to give it as the user does [rad]: a pin's
  /// friction's delay (release_pin_angle), so that a pin is named as it is bent.
  double shown_offset = 0;
};

struct ReleaseCriterion {
  Release release = Release::quality;
  /// A release set by the user: the shot releases there, and `release` only names what Q is.
  std::optional<GivenRelease> given;
  /// For Release::range: the level the range is measured at, above the engine's base (scaled, in L2).
  double target_level = 0;
  double length_unit = 1;  ///< [m] per scaled length (L2): the messages give metres
  double n = 1;  ///< exponent of eps in eq:Q_n; Q is reported with it whatever the release
  /// For Release::range: the drag the range is flown through (scaled, air.hpp; none: vacuum),
  /// and whether the range is Denny's, from the release point to where the flight dips below
  /// the release height, rather than from the pivot to the base's level.
  std::optional<Drag> drag;
  bool range_from_release = false;
};

/// The forces of eq:F at one moment, in M g: F_S_perp, |F_R|, F_Rh and -F_Rh, so that every
/// running extreme is a running maximum (F_Rh is tracked both ways). F_Rh is the frame's horizontal
/// force on the machine: at the pivot, and the floating arm's at its guide, as its rail takes none.
enum ForceIndex { sling_perpendicular, pivot_reaction, pivot_horizontal, pivot_horizontal_negated };
inline constexpr int force_count = 4;
using ForceValues = std::array<double, force_count>;

ForceValues force_values(const Snapshot& snapshot);

/// The running maxima of the forces of eq:F over [0, t].
struct ForceExtremes {
  ForceValues max{0, 0, 0, 0};
  void add(const ForceValues& values);
};

/// tau_e = T/(M g L2) of eq:Aux with T of eq:T: mu (v^2/2 + h), speed and height scaled.
double energy_at_target(double mu, Vec2 velocity, double height);

/// eps = T/Delta U of eq:Aux, from tau_e and Delta U/(M g L2).
double efficiency(double tau_e, double energy_drop);

/// F of eq:F: ((F_S_perp/(m g))^2 (F_R/(M g)) (Delta F_Rh/(M g)))^(1/4), with
/// Delta F_Rh = max F_Rh - min F_Rh over [0, t] and m/M = mu.
double force_factor(const ForceExtremes& extremes, double mu);

/// Q_n of eq:Q_n (eq:Q for n = 1): rho~ mu eps^n / F, with rho~ = R/L1 = rho/l.
double quality(double rho, double l, double mu, double eps, double force_factor, double n);

}  // namespace trebuchet
