// Calibration over what nobody measured (issue 48; docs/verifier.md, "Calibration over
// unknowns"): each unknown given as a range or a spread (the pins' radii, the release, the
// sling's masses, Cd, the wind), and the measured range within its uncertainty, drawn as a
// Monte Carlo run draws them; each draw fits the friction once (fit_friction). The answer is the
// fitted friction as a distribution, the share of the draws that a friction inside a plausible
// range explains, and which unknown moves the fit most.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "trebuchet/app/output/pictures.hpp"
#include "trebuchet/app/run/requests.hpp"
#include "trebuchet/app/input/units.hpp"
#include "trebuchet/app/run/verifier.hpp"
#include "trebuchet/calibration.hpp"
#include "trebuchet/parallel.hpp"
#include "trebuchet/uncertainty.hpp"

namespace trebuchet {

/// The coefficients of sliding friction the engineering handbooks give a pin, from greased metal
/// to dry wood on wood (docs/real-engines.md), unless the user gives another range.
inline constexpr std::array<double, 2> handbook_friction = {0.1, 0.5};

struct CalibrationRunInputs {
  MonteCarloRequest request;  ///< the engine's values with the unknowns among its spreads
  MeasuredRange measured;
  std::array<double, 2> plausible = handbook_friction;  ///< the friction coefficients deemed plausible
  int samples = 200;
  std::uint64_t seed = 1;
  int threads = 0;
};

struct CalibrationRun {
  CalibrationRunInputs given;
  FrictionFit fitted = FrictionFit::pin_coefficient;
  /// Each draw's: values[0] the fitted friction, values[1] the range it was fitted to [m]; drawn
  /// the unknowns, then the measured range.
  MonteCarloSummary summary;
  std::vector<UncertainInput> unknowns;  ///< the request's spreads, then the measured range's
  std::array<double, 5> percentiles{};  ///< 5, 25, 50, 75 and 95 % of the fitted friction
  int plausible = 0;  ///< draws fitted inside the plausible range
  Share share;  ///< of all draws
  std::vector<RankCorrelation> moves;  ///< Spearman's rank correlation of each unknown with the fit, with its interval
  double seconds = 0;
  int threads = 1;
};

/// Runs the draws. Throws Error for bad input at the unknowns' first values, before the run.
CalibrationRun calibrate_over_unknowns(const CalibrationRunInputs& inputs, const Progress& progress = {});

std::string calibration_run_table(const CalibrationRun& run);
/// The run's report, which also carries what runs it again: the version, and its "design" as a
/// Monte Carlo report writes it (the engine with the unknowns as ranges or spreads, the
/// settings, samples and seed) beside the measured range and the plausible friction.
nlohmann::ordered_json calibration_run_json(const CalibrationRun& run);

/// The run a calibration report holds, to run again as the same run (the same draws and
/// percentiles); messages name its values "where.design.key". Throws Error as
/// read_monte_carlo_design does, and Error(usage) for a malformed measured range or friction.
CalibrationRunInputs calibration_run_inputs(const nlohmann::json& report, const std::string& where);
/// friction.svg: the histogram of the fitted friction, the plausible range shaded.
std::vector<PictureFile> calibration_run_pictures(const CalibrationRun& run);

}  // namespace trebuchet
