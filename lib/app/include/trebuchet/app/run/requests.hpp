// One typed request per operation. The programs parse their flags into these values, the api
// (the page, the Python module) parses JSON into them, and both call the same functions, so
// that a shot, a completion, an optimum or a Monte Carlo run asked either way is the same.
// Values are as given: SI units, angles in degrees, empty where not given.
#pragma once

#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "trebuchet/completion.hpp"
#include "trebuchet/contest.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/input/settings.hpp"
#include "trebuchet/app/run/verifier.hpp"

namespace trebuchet {

/// complete's request: the attested values (engine, stand-ins, parts and material), under `settings`.
/// A contest's request (contest.hpp) from the values given: the projectile {{m}}, the beam by its
/// diameter {{D}} (of the wood) or its mass per metre `beam_per_m` [kg/m], theta_i, the material,
/// the counterweight's box, the machine (hinged unless given); released where the objective (the
/// range, or eps with `efficiency`) peaks. Throws Error(usage | bad_number) naming the value.
ContestRequest contest_request(const DesignValues& values, const ShotSettings& settings, std::optional<double> beam_per_m, bool efficiency);

CompletionRequest completion_request(const DesignValues& attested, const ShotSettings& settings);

/// optimize's request: R with T or with the stone's m, theta_i and F (the standard 30 deg, 2/3
/// when not given), a beam ratio l to hold, the material, the settings. Throws Error(usage) for a
/// capacity that is not R with one of T and m, naming {{R}}, {{T}} and {{m}}.
OptimizeRequest optimize_request(const DesignValues& values, const ShotSettings& settings);

/// A Monte Carlo run: the shot of a design, or the completion of attested values, at draws of
/// its spreads. The values hold each spread's first number (a range's low end, a spread's mean).
struct MonteCarloRequest {
  DesignValues values;
  SettingsValues settings;
  std::vector<SpreadInput> spreads;  ///< in the order they are drawn
  bool completes = false;  ///< complete each sample (attested values) instead of shooting it
  std::string where;  ///< how messages name the design's values: "" flags ("--M"), "design" a request's ("design.M")
  std::vector<std::string> notes;  ///< what reading the design left out, and why
};

/// The Monte Carlo run of the shots of a design object (a file's, a request's "design", or a
/// run's report read back, design_object): its values, each range or spread at its first number
/// and kept (take_spreads), and its settings with its samples, seed and claim. Messages name a
/// value "where.key"; keys no reader knows go to `passed`. The design's capacity (R, T, its
/// tolerance) is left out, with a note. Throws Error as read_design_values.
MonteCarloRequest read_monte_carlo_design(const nlohmann::json& design, const std::string& where, nlohmann::json& passed);

/// A caller's values, settings and spreads (flags, or a request's keys) laid over a run read from
/// a design or a run's report (read_monte_carlo_design), each change noted in run.notes as the
/// caller gave it ({{key}}): a spread of the run's that the caller fixes (one value, a spread,
/// Cd(Re), or vacuum for the air's) is no longer drawn, and a caller's spread replaces the run's
/// one value; then the caller's values, settings and spreads are the run's.
void lay_over_run(MonteCarloRequest& run, const DesignValues& values, const SettingsValues& settings, const std::vector<SpreadInput>& spreads,
                  const std::string& where);

/// The run as a request gives it, for its report: {"design": ...} (or "attested" for
/// completions) with each value under its key (SI, degrees for angles), each range or spread as
/// its text (spread_text), the machine, the settings as a shot's record writes them with the air
/// in full (settings_json), and `samples`, `seed` and the claim. It reads back as the same run.
nlohmann::ordered_json monte_carlo_request_json(const MonteCarloRequest& request, int samples, std::uint64_t seed);

/// What decides the verdict on a `claim`ed range [m] (issue 64), at the run's middle: each
/// spread at its centre (a range) or mean (a spread). Its engine (completed as the run's samples
/// are, where the run completes) gives the energy bound 2 Delta U/(m g) and its farthest throw
/// under the run's settings, released where the range peaks; then each air value left at its
/// default is shot at the ends of its span, the same engine (docs/verifier.md, "What decides a
/// claim"). Where the middle cannot be completed or shot, says why (its names by `word`).
ClaimContext claim_context(const MonteCarloRequest& request, double claim, const std::function<std::string(std::string_view)>& word);

/// The values and settings of a sample: each spread set to value(its spread).
MonteCarloRequest with_draws(const MonteCarloRequest& request, const std::function<double(const Spread&)>& value);

/// The shot of one sample at the request's values (R, T, eps and v; no loads). Throws Error.
Verification sample_verification(const MonteCarloRequest& sample);

/// How the run's shots are released, for its report (report.hpp, describe_release): at the
/// criterion's optimum, at a release the design gives, or at one drawn from a spread, named as
/// the user named it.
std::string describe_monte_carlo_release(const MonteCarloRequest& request);

/// The air the run's shots fly through, for its report: "vacuum", or describe_air with the
/// values drawn from a spread said to be drawn ("air (Cd drawn, ...)"), not given as the first
/// sample's.
std::string describe_monte_carlo_air(const MonteCarloRequest& request);

/// The shots a sample takes (1, or those of a completion at the first values), checking that
/// the first values make an engine and its shot: bad input there is thrown, as the run's.
std::int64_t shots_per_sample(const MonteCarloRequest& request);

/// The run's uncertain inputs, as its user named them, in the order they are drawn.
std::vector<UncertainInput> uncertain_inputs(const MonteCarloRequest& request);

/// The values the run holds fixed, in the order the report lists them: what a completion alone
/// takes (Lb, l), then the others of the table's order (the engine's, its parts, its
/// material), none of them spread.
std::vector<FixedInput> fixed_inputs(const MonteCarloRequest& request);

/// The report of a run of `samples` from `seed` whose outcomes `summary` holds: what it drew and
/// held fixed, its release, subject and air, the run as a request gives it, and with a claim what
/// decides it (claim_context, its names by `word`). Its wall time and threads are the caller's
/// (0 and 1 until set).
MonteCarloReport monte_carlo_report(const MonteCarloRequest& run, const MonteCarloSummary& summary, int samples, std::uint64_t seed,
                                    const std::function<std::string(std::string_view)>& word);

/// The outcome of one sample drawn with `random`; a failure is recorded, its message's names
/// written by `word` (error.hpp).
SampleOutcome sample_outcome(const MonteCarloRequest& request, std::mt19937_64& random, const std::function<std::string(std::string_view)>& word);

}  // namespace trebuchet
