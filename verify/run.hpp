// trebuchet-verify's subcommands, one file each: each takes the parsed options, calls the
// library and prints; it returns the exit code (docs/exit_codes.md) or throws Error.
#pragma once

#include "options.hpp"
#include "trebuchet/app/run/calibration_run.hpp"

namespace trebuchet::verify {

int run_shot(const Options& options, bool fit);  // shot.cpp: shot and fit
/// monte_carlo.cpp: a run of shots (or, with `complete`, of completions) whose values are given as
/// ranges or spreads: by the flags, or by the one design of a file (`design`, named `where`) with
/// the flags' over it.
int run_monte_carlo(const Options& options, bool complete, const nlohmann::json* design = nullptr, const std::string& where = "");

/// Refuses --samples, --seed, --claim and --draws for a run with no range or spread (Error(usage)).
void refuse_monte_carlo_settings(const Options& options);
int run_complete(const Options& options);  // complete.cpp
int run_calibrate(const Options& options);  // calibrate.cpp
int run_calibration(const Options& options, CalibrationRunInputs inputs);  // calibrate.cpp: over unknowns, from flags or a report read back
int run_optimize(const Options& options);  // tables.cpp
int run_derive_table(const Options& options);  // tables.cpp
int run_merge(const Options& options);  // tables.cpp
int run_compare(const Options& options);  // compare.cpp
int run_contest(const Options& options);  // contest.cpp
int run_sweep(const Options& options);  // sweep.cpp: the what-if sweep

/// Whether the flags give an engine's value or part, which a design file gives instead (shot.cpp);
/// the material, the capacity and the release are settings of a file's designs too.
bool has_engine_flags(const DesignValues& design);

/// How the flags check and report a design (shot.cpp): the settings, the material, the units, the
/// format and the input file, which no output may replace. shot, compare and sweep start from it.
DesignCheck design_check(const Options& options);

/// The values of the one design a subcommand takes (compare, sweep): from the file, the flags'
/// values over its own (each change printed as a note), refusing a file of more designs; or from
/// the flags. `where` names it in messages, `passed` gets a file's keys that no reader knows,
/// `settings` the flags' settings over the file's own (a record's assumptions).
DesignValues one_design(const Options& options, const std::string& subcommand, std::string& where, nlohmann::json& passed, SettingsValues& settings,
                        nlohmann::json* object = nullptr);

/// Prints what a reader did that the user should know (a flag that replaced a file's value) to
/// stderr, as notes.
void print_notes(const std::vector<std::string>& notes);

}  // namespace trebuchet::verify
