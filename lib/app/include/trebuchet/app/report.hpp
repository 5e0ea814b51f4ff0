// What the programs print for people: aligned lines with units, and the time series of a shot
// as CSV (for spreadsheets and gnuplot). SI units; angles in degrees. Machine-readable records
// are in schema.hpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "trebuchet/calculator.hpp"
#include "trebuchet/app/schema.hpp"
#include "trebuchet/shot.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

/// The calculator's design. Throws Error(numerical) if a number is not finite.
std::string design_table(const OptimalEngine& design);

/// A shot's figures, and the check of a predicted capacity when there is one. It begins with the
/// engine simulated and every assumption (vacuum, g, the release rule, the target level); forces
/// are in kN with their multiples of m·g or M·g, and the force factor of eq:F is named so, apart
/// from the arm fraction F = (L2 + L3)/H.
std::string verification_table(const Engine& engine, const ShotSettings& settings, const Verification& v,
                               const std::optional<CapacityCheck>& check = std::nullopt);

/// Two indented lines with units: Lb, H and the lengths; the masses and D.
std::string engine_table(const Engine& engine);

/// An optimum: where its search started and what it cost, its engine and its shot.
std::string optimum_table(const Optimum& optimum, const ShotSettings& settings);

/// A completed engine: each quantity attested, implied or chosen, the shot, and how far the
/// chosen values sit from the calculator's optimum for the same capacity.
std::string completion_table(const Completion& completion, const ShotSettings& settings);

/// One CSV row per trace point: phase, time [s], angles [deg], angular speeds [rad/s],
/// forces (F_S_perp/(m g), F_R and its components/(M g), F_H/(M g), normal/(m g)),
/// energy [J] and its drift relative to Delta U (in phase III, from the energy at release,
/// the projectile having left), the positions of counterweight, beam tip and projectile
/// (site_point, [m]) and each body's energy [J] (potential from the pivot's level). After the
/// release, phi, its rate and the projectile's position are empty.
std::string trace_csv(const std::vector<TracePoint>& trace, const Engine& engine);

/// A point on the site: x [m] from the pivot toward the target, y [m] above the engine's base.
struct SitePoint {
  double x, y;
};

/// Where a scaled position relative to the pivot (dynamics.hpp: the target lies toward -x) is
/// on the site of `engine`.
SitePoint site_point(Vec2 scaled, const Engine& engine);

}  // namespace trebuchet
