// What the verifier does for its users, apart from parsing their options: reads the designs of
// a run (a JSON object or array, or CSV rows), checks one design and reports it in each format,
// and reports a Monte Carlo run over uncertain inputs.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/completion.hpp"
#include "trebuchet/contest.hpp"
#include "trebuchet/uncertainty.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/app/input/csv.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {

/// The designs of a run: a JSON object, a JSON array, or CSV rows (docs/csv.md).
struct DesignInputs {
  std::vector<std::string> passed_columns;  ///< CSV columns that pass through, e.g. site
  std::vector<DesignRows::Row> rows;
  std::vector<std::string> where;  ///< how messages name each row: "design[2]", "line 3"
  bool single = true;  ///< one object: an error ends the run
};

/// The designs in `text`, read from `path` ("-": standard input): JSON if the file is named
/// .json, parses as JSON or opens like it (then its error is JSON's), else CSV. Throws
/// Error(usage) for text that holds no design.
DesignInputs read_design_inputs(const std::string& text, const std::string& path);

/// Refuses (Error(usage), naming `name`) a fixed beam ratio the optimizer's fixed-l search does
/// not cover: below 2 (no engine of the paper; most shapes leave no room for the counterweight
/// arm) or from max_beam_ratio up.
void check_fixed_beam_ratio(double l, const std::string& name);

/// How each design of a run is checked and reported.
struct DesignCheck {
  ShotSettings settings;
  /// The settings as the caller was given them (its flags, a request's keys): a design's own
  /// (EngineRecord::settings, a record's assumptions) are laid under them, and the shot's
  /// settings are theirs with the release and loads of `settings`. Empty: `settings` are the
  /// shot's, and the design's own are not read.
  std::optional<SettingsValues> given;
  DesignValues material;  ///< its material rows (the flags', a request's top-level g, ...) over each design's own
  double tolerance = 0.02;  ///< relative, on a predicted R and T
  bool fit = false;  ///< fit the design's shape to its capacity first
  bool csv = false;  ///< also the CSV cells of each design
  bool table = true;  ///< also the table of each design
  int csv_digits = default_csv_digits;
  std::string series_path;  ///< write the motion here (CSV) when not empty
  double series_dt_s = 0;  ///< [s]; 0: at the integrator's steps
  std::string plot_dir;  ///< draw the shot into this folder when not empty
  std::vector<std::string> inputs;  ///< the run's input files, which no picture may replace
  UnitSystem units = UnitSystem::si;  ///< of the table
  /// compare's: a contest's limits each column is measured against (contest_measures)
  LimitsToMeet limits;
};

/// One design checked: its record as JSON, (with check.table) as a table and (with check.csv) as CSV cells, and whether a capacity
/// it carries was met within the tolerance.
struct DesignReport {
  Engine engine;  ///< the engine shot (with check.fit, the fitted one)
  ShotSettings settings;  ///< those it was shot under: the check's, with the design's own release where the check sets none
  Verification verification;  ///< its shot
  nlohmann::ordered_json json;
  std::string table;
  std::vector<std::string> csv;
  bool outside_tolerance = false;
  bool pin_releases = true;  ///< whether a pin bent to its pin to bend makes its release (pin_release_note)
};

/// Shoots the design (fitted to its capacity first with check.fit), checks its capacity, and
/// writes the series and the pictures it asks for.
DesignReport check_design(const EngineRecord& record, const DesignCheck& check);

/// One design of check_released_designs: its report, or why it has none.
struct ReleasedDesign {
  std::optional<DesignReport> report;
  std::optional<Error> error;
};

/// check_design of each of `records`, which give one engine and differ in their release alone
/// (a sweep of it: run_what_if), each report the same bit for bit, the shots read off one
/// trajectory (verify_releases). Neither fitted nor drawn: a check with fit, a series or
/// pictures is refused, as is a record without its release.
std::vector<ReleasedDesign> check_released_designs(const std::vector<EngineRecord>& records, const DesignCheck& check);

/// The same engine, its parts, masses and lengths, built as each machine (compare, docs/machines.md):
/// its report, or why it cannot be built or shot so.
struct MachineComparison {
  MachineKind machine = MachineKind::hinged;
  std::optional<DesignReport> report;
  std::optional<Error> error;
  /// Under a contest's limits (DesignCheck::limits): those the column's engine breaks, or why it
  /// could not be measured against them.
  bool limited = false;  ///< whether it was measured against a contest's limits
  std::vector<BrokenLimit> broken;
  std::optional<Error> unmeasured;
};

/// Shoots `record`'s engine as the hinged counterweight, the fixed counterweight, the floating arm
/// and the whipper (pytrebuchet's start, on a frame as tall as the engine's pivot stands) under
/// `check` (no series or pictures), each refusal kept in its place.
std::vector<MachineComparison> compare_machines(const EngineRecord& record, const DesignCheck& check);

/// compare's run, as trebuchet-verify compare and api::compare take it: the design's `values`
/// (`where` names them), built as each machine under `settings` (the design's own with the
/// caller's over them; released where the range peaks unless they give quality or n), reported as
/// `check` says. Throws Error(usage) for the whipper,
/// whose column compare builds from another machine's engine.
std::vector<MachineComparison> compare_design(DesignValues values, const std::string& where, const SettingsValues& settings, DesignCheck check);

/// The comparison side by side: range, efficiency, the release, the pin to bend and the peak
/// loads, a column a machine, then what refused a machine (its names written by `word`, error.hpp).
std::string comparison_table(const std::vector<MachineComparison>& comparison, UnitSystem units,
                             const std::function<std::string(std::string_view)>& word);

/// An array, one shot record a machine, or {"machine", "error"} where it was refused.
nlohmann::ordered_json comparison_json(const std::vector<MachineComparison>& comparison, const std::function<std::string(std::string_view)>& word);

/// What complete reports: the completion and, unless it is already for the range, the engine of
/// the longest range for the same attested values ("could it throw that far?"), or why there is
/// none (its message with names written by `word`, error.hpp).
struct CompletionReport {
  Completion completion;
  std::optional<Completion> longest;
  std::string longest_note;
};
CompletionReport complete_with_longest(const CompletionRequest& request, const std::function<std::string(std::string_view)>& word);

/// derive-table's X points take about this many shots each, within max_run_shots (settings.hpp).
inline constexpr std::int64_t shots_per_sweep_point = 1100;
/// The samples of a run unless {{samples}} is given: 10000 shots (about 1 s), 1000 completions
/// (about 4 s); either puts the 5 and 95 % to a few percent of their spread.
inline constexpr int default_shot_samples = 10000, default_completion_samples = 1000;
/// Refuses, as Error(usage) naming {{samples}} and the numbers, a run of more shots than
/// max_run_shots; the fix is the most samples the budget allows.
void check_monte_carlo_work(std::int64_t samples, std::int64_t shots_per_sample, const std::string& sampled);

/// The shots one completion of a Monte Carlo run takes: those of `trial`, a completion at the
/// run's first values; 300 when it fails numerically (twice what the completions of
/// bench-completion take). Bad input at the first values is thrown: a range must hold only
/// values that make an engine.
std::int64_t shots_per_completion(const std::function<Completion()>& trial);

/// With no sample left, a run fails as its most frequent failure did: bad input (a range that
/// holds no engine) or a numerical failure, with that sample's message and numbers.
void refuse_when_no_sample_worked(const MonteCarloSummary& summary);

/// "--M uniform 2500..3500 kg", "--L4 normal 3.55±0.2 m".
std::string describe_uncertain(const UncertainInput& input);

/// A value a Monte Carlo run holds fixed, as its user gave it: "L1" 4.13 m.
struct FixedInput {
  std::string name;
  UnitDimension dimension;
  double value;  ///< SI; degrees for angles
};

/// A value a claim's run left at its default, shot at the two ends of its plausible span
/// (docs/verifier.md, "What decides a claim"): the drag coefficient, the projectile's density,
/// the wind, or in vacuum the air itself.
struct ClaimSpan {
  std::string key;  ///< the setting: "cd", "projectile", "wind" or "air"
  std::string what;  ///< in words: "the drag coefficient Cd"
  std::string low, high;  ///< the span's ends in words: "Cd(Re) of a smooth sphere", "0.5"
  std::optional<double> R_low, R_high;  ///< the farthest engine's range at each end [m]; none where it cannot be shot
  bool decides = false;  ///< the ends fall on both sides of the claim
};

/// What decides a claim's verdict, from the run's middle (each spread at its centre, or mean).
struct ClaimContext {
  /// Siano's black box: Delta U thrown whole from the ground at the best angle to the target
  /// level, 2 Delta U/(m g) on level ground; no engine of that energy throws farther [m].
  double energy_bound = 0;
  double farthest = 0;  ///< the middle engine's range under the run's air, released where it peaks (or as the run releases it) [m]
  bool given_release = false;  ///< the run's release is given: `farthest` is at it
  std::vector<ClaimSpan> spans;  ///< the values left at their defaults, each across its span
  std::string unavailable;  ///< why the middle could not be completed or shot; then nothing above is known
};

/// What a Monte Carlo run reports: its samples, seed, inputs (the uncertain and the fixed),
/// percentiles and failures; `air` describes the flight ("vacuum" or describe_air),
/// `assumptions` the release and the target level, `subject` what was sampled ("the shot").
struct MonteCarloReport {
  const MonteCarloSummary& summary;
  std::vector<UncertainInput> inputs;
  std::vector<FixedInput> fixed;
  std::string assumptions;
  std::uint64_t seed;
  std::string subject;
  std::string air;
  bool in_air;
  double seconds = 0;  ///< the run's wall time [s]; 0 where the caller measures it
  int threads = 1;
  std::optional<double> claim;  ///< a claimed range [m] whose odds the run reports (assess_claim)
  nlohmann::ordered_json request;  ///< the run as a request gives it (monte_carlo_request_json): it reads back as the same run
  std::optional<ClaimContext> claim_context;  ///< with a claim: what decides its verdict
};
/// The report as JSON: the run as a request gives it ("design" or "attested"), with the claim's odds, the inputs ranked by their rank correlation with R
/// ("sensitivity"), and every sample's drawn inputs beside its outputs ("draws", by column).
nlohmann::ordered_json monte_carlo_json(const MonteCarloReport& report);
/// The percentiles as CSV: a row for each of R_m, T_J, eps, v_m_s with p5, p50, p95 in SI
/// units and `digits` significant digits (no rows when no sample worked).
std::string monte_carlo_csv(const MonteCarloReport& report, int digits);
std::string monte_carlo_table(const MonteCarloReport& report);
/// Every sample as a CSV row: its number, its drawn inputs (SI columns: "M_kg", "theta_i_deg"),
/// R_m, T_J, eps, v_m_s (empty where it failed), whether it reaches the claim (with one), and
/// its failure. Every number to 17 significant digits, whatever --digits says: the file is data
/// for analysis, and reads back as the run's own numbers.
std::string monte_carlo_draws_csv(const MonteCarloReport& report);

}  // namespace trebuchet
