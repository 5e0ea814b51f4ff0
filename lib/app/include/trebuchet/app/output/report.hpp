// What the programs print for people: aligned lines with units, and the time series of a shot
// as CSV (for spreadsheets and gnuplot). SI units; angles in degrees. Machine-readable records
// are in schema.hpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "trebuchet/calculator.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/calibration.hpp"
#include "trebuchet/completion.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/app/input/units.hpp"
#include "trebuchet/shot.hpp"
#include "trebuchet/uncertainty.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

/// The places of a run's rank correlations (rank_correlations), the strongest first (ties in the run's order).
std::vector<std::size_t> strongest_first(const std::vector<RankCorrelation>& correlations);

/// How the records' rank correlations are found, as they say it.
inline constexpr const char* rank_correlation_method =
    "Spearman's rank correlation of each drawn input with the result, over the samples that worked; its 95 % interval by Fisher's z "
    "(variance 1.06/(n - 3)); resolved where the interval leaves 0 out";

/// What moves `subject` most, from a run's rank correlations with `against` (rank_correlations,
/// by input as `names`), over the `samples` that worked: those the samples resolve, the strongest
/// first, each with its 95 % interval; then the rest, named as not resolved at that many samples.
/// One line, without its end.
std::string moves_most_text(const std::string& subject, const std::string& against, const std::vector<std::string>& names,
                            const std::vector<RankCorrelation>& correlations, std::size_t samples);

/// The calculator's design. Throws Error(numerical) if a number is not finite.
std::string design_table(const OptimalEngine& design, UnitSystem units = UnitSystem::si);

/// A shot's figures, and the check of a predicted capacity when there is one. It begins with the
/// engine simulated and every assumption (vacuum, g, the release rule, the target level); forces
/// are in kN with their multiples of m·g or M·g, and the force factor of eq:F is named so, apart
/// from the arm fraction F = (L2 + L3)/H.
/// Then the builder's loads with their times and the beam's strength; the capacity check
/// compares the prediction with the shot in vacuum. Values in `units` (imperial: SI beside).
std::string verification_table(const Engine& engine, const ShotSettings& settings, const Verification& v,
                               const std::optional<CapacityCheck>& check = std::nullopt, UnitSystem units = UnitSystem::si);

/// What a shot assumed, in one line: the air or vacuum, g, the release rule and the target level
/// (or Denny's range).
std::string describe_assumptions(const Engine& engine, const ShotSettings& settings);
/// Its release rule and target level (or Denny's range) alone.
std::string describe_release(const ShotSettings& settings);
/// Where the range ends: "target level 0 m", or Denny's from the release point.
std::string describe_target(const ShotSettings& settings);

/// The pin to bend for a shot's release, in words: "59.11 deg for its friction 0.3 (42.42 deg
/// frictionless)", or "42.42 deg" where the pin has no friction; where no pin makes the release
/// (`releases` false: pin_release_note), "none makes it (a pin bent to 42.42 deg does not, ...)".
std::string pin_to_bend_text(const Verification& v, double pin_friction, bool releases = true);

/// A given release in words: "the pin angle 40 deg".
std::string describe_given_release(const SetRelease& release);

/// Two indented lines with units: Lb, H and the lengths; the masses and D.
std::string engine_table(const Engine& engine, UnitSystem units = UnitSystem::si);

/// An optimum: where its search started and what it cost, its engine and its shot.
std::string optimum_table(const Optimum& optimum, const ShotSettings& settings, UnitSystem units = UnitSystem::si);

/// A completed engine: each quantity attested, implied or chosen, the shot, and how far the
/// chosen values sit from the calculator's optimum for the same capacity.
/// With `longest`, the engine of the longest range for the same attested values follows, and how
/// much further it throws; or why there is none (`longest_note`).
/// The calibration of an engine's friction to a measured range, and its predictions.
std::string calibration_table(const Calibration& calibration, const MeasuredRange& measured, const std::vector<Prediction>& predictions,
                              const ShotSettings& settings, UnitSystem units = UnitSystem::si);

std::string completion_table(const Completion& completion, const ShotSettings& settings, UnitSystem units = UnitSystem::si,
                             const Completion* longest = nullptr, const std::string& longest_note = "");

/// One CSV row per trace point: phase, time [s], angles [deg], angular speeds [rad/s],
/// forces (F_S_perp/(m g), F_R and its components/(M g), F_H/(M g), normal/(m g)),
/// energy [J] and its drift relative to Delta U (in phase III, from the energy at release,
/// the projectile having left), the positions of counterweight, beam tip and projectile
/// (site_point, [m]), each body's energy [J] (potential from the pivot's level), the sling's
/// tension/(m g) and the beam's bending moment at the pivot/(M g L2). After the release, phi,
/// its rate, the projectile's position and the sling's tension are empty.
std::string trace_csv(const std::vector<TracePoint>& trace, const Engine& engine);

/// A point on the site: x [m] from the pivot toward the target, y [m] above the engine's base.
struct SitePoint {
  double x, y;
};

/// Where a scaled position relative to the pivot (dynamics.hpp: the target lies toward -x) is
/// on the site of `engine`.
SitePoint site_point(Vec2 scaled, const Engine& engine);

}  // namespace trebuchet
