// What the verifier prints: JSON (for tools), an aligned table (for people), and the time
// series of a shot as CSV (for spreadsheets and gnuplot). SI units; angles in degrees.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/engine.hpp"
#include "trebuchet/shot.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

/// A predicted capacity (from the calculator) against the simulated one.
struct CapacityCheck {
  double R = 0, T = 0;          ///< predicted [m], [J]
  double deviation_R = 0;       ///< simulated/predicted - 1
  double deviation_T = 0;
  double tolerance = 0;         ///< relative
  bool pass = false;            ///< both deviations within the tolerance
};

CapacityCheck check_capacity(const Verification& v, double R, double T, double tolerance);

/// Keys R, T, eps, Q, force_factor, v, h, x, A_deg, t_release, t_liftoff, FS_perp_mg, FR_Mg,
/// dFRh_Mg, energy_drift; with a check, also predicted, deviation, tolerance and pass.
/// Throws Error(numerical) if a number is not finite.
nlohmann::ordered_json verification_json(const Verification& v, const std::optional<CapacityCheck>& check);

/// Aligned lines with units.
std::string verification_table(const Verification& v, const std::optional<CapacityCheck>& check);

/// The engine's parameters under the calculator's JSON keys (L1 ... mb, theta_i_deg, F).
nlohmann::ordered_json engine_json(const Engine& engine);

/// Two indented lines with units: Lb, H and the lengths; the masses and D.
std::string engine_table(const Engine& engine);

/// One CSV row per trace point: phase, time [s], angles [deg], angular speeds [rad/s],
/// forces (F_S_perp/(m g), F_R and its components/(M g), F_H/(M g), normal/(m g)),
/// energy [J] and its drift relative to Delta U (in phase III, from the energy at release,
/// the projectile having left).
std::string trace_csv(const std::vector<TracePoint>& trace, const Engine& engine, double g);

}  // namespace trebuchet
