// Calibration of an engine's friction to a measured shot (issue 24): the one friction scale,
// or an effective coefficient at both pins, that makes the simulated range the measured one,
// with the band its uncertainty gives; and what the calibrated engine does with another
// projectile or counterweight.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "trebuchet/engine.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

/// A range measured in the field, from where the settings measure it [m].
struct MeasuredRange {
  double range = 0;  ///< [m]
  double uncertainty = 0;  ///< one standard deviation [m]; 0: none given
};

/// What is fitted: the engine's own coefficients, all multiplied by one scale; or, for an
/// engine with none, one coefficient mu at both pins (axle and hinge), on their given radii.
enum class FrictionFit { scale, pin_coefficient };

/// One step of the explanation of a measured range, in a fixed order: the ideal engine at its
/// optimum in vacuum, then the given release, then the given air, then the fitted friction.
struct CalibrationStep {
  std::string what;  ///< "the given release"
  double R = 0;  ///< the range after this step, measured as the settings measure it [m]
};

struct Calibration {
  std::vector<CalibrationStep> steps;  ///< what each condition does to the range, in order
  FrictionFit fitted = FrictionFit::scale;
  double value = 0;  ///< the scale, or mu at both pins, that matches the range
  double value_low = 0, value_high = 0;  ///< those that match the range plus and minus its uncertainty (low: the longer range)
  /// The band's short end lies beyond the strongest friction the engine runs with: value_high
  /// is that friction, not the one matching the range less its uncertainty.
  bool band_clipped = false;
  std::optional<double> jams_at;  ///< the friction value at which the engine jams, when below coefficients of 2
  Engine engine;  ///< with the fitted friction
  Verification shot;  ///< of the calibrated engine
  Verification frictionless;  ///< of the same engine without friction
  int simulations = 0;
};

/// The engine with its friction set by a fitted value (FrictionFit): the coefficients times a
/// scale, or mu at both pins.
Engine with_friction(const Engine& engine, FrictionFit fitted, double value);

/// What calibrate fits on this engine: the scale of its coefficients, or one coefficient at both
/// pins where it has none. Throws Error(usage) for an engine without friction or the pins' radii.
FrictionFit friction_fit_of(const Engine& engine);

/// The friction (friction_fit_of) at which the engine throws `range` [m] as the settings measure
/// it, to 1e-5 of the largest allowed: one draw of a calibration over unknowns (calibration_run.hpp).
/// Throws Error(out_of_range) where none does, its message starting with why: "no friction
/// explains it" (the engine without friction throws no farther) or "friction alone does not
/// explain it" (the strongest friction allowed still throws farther).
double fit_friction(const Engine& engine, double range, const ShotSettings& settings);

/// Fits the friction to the measured range, after explaining what it can by the settings'
/// release and air (Calibration::steps), which the messages of its refusals repeat. Throws Error(usage) for an engine without
/// friction and without the pins' radii; Error(out_of_range) when the frictionless engine does
/// not reach the range (no friction lengthens a shot) or when the largest friction allowed
/// (coefficients of 2) still throws farther.
Calibration calibrate(const Engine& engine, const MeasuredRange& measured, const ShotSettings& settings);

/// A calibrated engine's range with another projectile or counterweight, and its band from the
/// calibration's.
struct Prediction {
  std::string changed;  ///< "m = 60 kg"
  Engine engine;
  double R = 0;  ///< at the fitted value [m]
  std::optional<double> R_low, R_high;  ///< at the ends of its band [m]; empty where that end's shot is refused
  std::string band_end_refused;  ///< why an end's shot is refused (the model's words)
  Verification shot;
};
Prediction predict(const Calibration& calibration, const Engine& changed, const std::string& what, const ShotSettings& settings);

}  // namespace trebuchet
