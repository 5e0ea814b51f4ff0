// trebuchet-verify's options, declared once per subcommand and parsed into typed values as
// CLI11 reads them (a value with a unit, a range or a spread, a name): after parsing, nothing
// is text any more but the paths of files.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/calibration.hpp"
#include "trebuchet/completion.hpp"
#include "trebuchet/contest.hpp"
#include "trebuchet/sweep.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/app/run/calibration_run.hpp"
#include "trebuchet/app/run/requests.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/search_records.hpp"
#include "trebuchet/app/input/settings.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/app/run/verifier.hpp"
#include "trebuchet/app/run/what_if.hpp"

namespace trebuchet::verify {

enum class Format { table, json, csv };

struct Options {
  std::string input;  ///< a design file, "-" for stdin; empty: the flags
  DesignValues design;  ///< the table's flags (input_fields): the engine, its material, --R and --T, complete's --Lb, --H, --l
  SettingsValues settings;  ///< the settings a request takes too (settings.def): the release, the integrator, the target, the air, a run's
  std::optional<MeasuredRange> measured;  ///< calibrate: the measured range [m]
  std::vector<double> predict_m, predict_M;  ///< calibrate: masses to predict with [kg]
  std::array<double, 2> plausible_friction = handbook_friction;  ///< calibrate over unknowns: the plausible coefficients
  UnitSystem units = UnitSystem::si;  ///< --units: how tables print values
  Format format = Format::table;
  int digits = default_csv_digits;
  std::string series, plot;  ///< output paths
  double series_dt_s = 0;  ///< [s]
  int threads = 1;
  SweepSpec sweep;  ///< derive-table: its X grid (the rest from the other options)
  std::optional<Shard> shard;
  std::vector<std::string> parts;  ///< merge
  std::string draws;  ///< Monte Carlo: write every sample's drawn inputs and outputs here (CSV)
  std::vector<SpreadInput> spreads;  ///< the values given as ranges or spreads, in the order they are drawn
  ContestLimits limits;  ///< contest: --max-width ... --max-acceleration
  std::optional<double> beam_per_m;  ///< contest: the beam's mass per metre [kg/m]
  bool efficiency = false;  ///< contest: --objective eps
  bool all_machines = false;  ///< contest: --machine all, each machine's best side by side
  int pareto = 0;  ///< contest: points of the Pareto front; 0: none
  std::optional<double> min_clearance;  ///< contest: of the counterweight above the ground [m]; none given: 0 (or a record's, for compare)
  std::optional<WhatIf> what_if;  ///< sweep: the value varied and its range (--vary)
  int what_if_points = 21;  ///< sweep: --points
};

/// The subcommands, each with its options declared on it.
struct Subcommands {
  CLI::App *shot, *fit, *optimize, *derive_table, *merge, *complete, *calibrate, *compare, *contest, *sweep;
};
Subcommands declare_subcommands(CLI::App& app, Options& options);

/// The settings of the flags (settings.hpp's shot_settings); --series-dt needs --series. With
/// `over_designs`, as they go over each design's own (shot_settings_over_designs).
ShotSettings settings_of(const Options& options, bool over_designs = false);

/// The Monte Carlo run of the flags' values, shots or (`completes`) completions.
MonteCarloRequest monte_carlo_request(const Options& options, bool completes);

}  // namespace trebuchet::verify
