// The records of the searches: an optimum (optimize), a completion (complete) and a calibration
// (calibrate), each with the shot of the engine it found.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/calibration.hpp"
#include "trebuchet/completion.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

/// An optimum: the engine's keys, start, simulations, iterations, wall_time_s (the whole
/// search's, given by the caller), the verification's keys of its shot and the `settings` it was
/// shot with ("assumptions"), so that it reads back as the same shot.
nlohmann::ordered_json optimum_json(const Optimum& optimum, const ShotSettings& settings, double wall_time_s);

/// A completed engine: the engine's keys, attested, implied and chosen (names), simulations,
/// the shot's keys, the assumptions, and the calculator's optimum for the same capacity
/// (its design, or calculator_note).
/// A completion, and beside it (`longest`) the engine of the longest range for the same attested
/// values under "longest_range", or why there is none (`longest_note`).
/// The calibration as JSON: the calibrated engine, what was fitted and its band, the measured
/// range, the shot with and without the friction, and each prediction with its band.
nlohmann::ordered_json calibration_json(const Calibration& calibration, const MeasuredRange& measured, const std::vector<Prediction>& predictions,
                                        const ShotSettings& settings);

nlohmann::ordered_json completion_json(const Completion& completion, const ShotSettings& settings, const Completion* longest = nullptr,
                                       const std::string& longest_note = "");

}  // namespace trebuchet
