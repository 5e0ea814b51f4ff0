// A shot's record, as JSON and CSV (trebuchet-verify shot, api::shot), and what it assumed.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/verification.hpp"
#include "trebuchet/app/records/schema.hpp"

namespace trebuchet {

/// The settings of a shot under the keys a request gives them: "air" ("vacuum", or an object of
/// its density [kg/m^3], drag coefficient, projectile's density [kg/m^3], wind [m/s] and drag in
/// the sling), "range_from", the release criterion ("release") and n, a given release
/// ("release_at"), the target level [m] and the integrator where it is not the default. With
/// `engine`, also what follows from it: the sphere's diameter [m] in the air, g [m/s^2],
/// theta_i_deg and the arm fraction F (assumptions_json).
nlohmann::ordered_json settings_json(const ShotSettings& settings, const Engine* engine);

/// What a shot of `engine` assumed: settings_json of its settings (settings_for), with the engine.
nlohmann::ordered_json assumptions_json(const Engine& engine, const ShotSettings& settings);

/// Throws Error(numerical) naming the first figure of the shot that is not finite.
void require_finite(const Verification& verification);

/// Keys R, T, eps, Q, force_factor, v, h, x, A_deg, t_release, t_liftoff, FS_perp_mg, FR_Mg,
/// dFRh_Mg, energy_drift; with a check, also predicted, deviation, tolerance and pass.
/// Throws Error(numerical) if a number is not finite.
nlohmann::ordered_json verification_json(const Verification& v, const std::optional<CapacityCheck>& check = std::nullopt);

/// The verifier's CSV columns: the engine's keys, the shot's figures with units, the forces in
/// kN, the check (predicted_R_m ... pass, empty without a prediction), the assumptions and the
/// warnings; and one shot's cells with `digits` significant digits.
std::vector<std::string> verification_csv_header();
/// Every name the verifier's outputs use (CSV columns, JSON keys, error): a column of a CSV of
/// designs passed through must not take one of them.
std::vector<std::string> verification_output_names();
std::vector<std::string> verification_csv_row(const Engine& engine, const ShotSettings& settings, const Verification& v,
                                              const std::optional<CapacityCheck>& check, int digits);

}  // namespace trebuchet
