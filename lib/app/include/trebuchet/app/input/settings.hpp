// The table of settings (its rows: settings.def): every flag of the programs and every key of the
// api's requests that is not an engine's input (fields.hpp), declared once with its name, the
// aliases it still reads, its dimension, help, default, range and the doors that take it. The
// programs' options, the requests' keys (and so the Python module's keyword arguments), the
// page's controls and docs/inputs.md come from these rows; the settings of a shot are read from
// text by one function (read_setting), whichever door they come through.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "trebuchet/integrator.hpp"
#include "trebuchet/quality.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {

/// The doors a setting comes through, a bit each: the programs' subcommands (cmd_) and the api's
/// requests (req_, api.hpp), which the Python module and the page call.
enum Door : unsigned {
  cmd_calc = 1u << 0,  ///< trebuchet-calc
  cmd_shot = 1u << 1,
  cmd_fit = 1u << 2,
  cmd_calibrate = 1u << 3,
  cmd_compare = 1u << 4,
  cmd_contest = 1u << 5,
  cmd_sweep = 1u << 6,
  cmd_complete = 1u << 7,
  cmd_optimize = 1u << 8,
  cmd_derive_table = 1u << 9,
  req_design = 1u << 16,
  req_shot = 1u << 17,
  req_sweep = 1u << 18,
  req_optimize = 1u << 19,
  req_complete = 1u << 20,
  req_monte_carlo = 1u << 21,
  req_value = 1u << 22,
  req_compare = 1u << 23,
  req_contest = 1u << 24,
  /// The subcommands that shoot an engine at a release they search for, and the requests that do.
  shooting = cmd_shot | cmd_fit | cmd_calibrate | cmd_compare | cmd_sweep | cmd_complete | cmd_optimize,
  shooting_but_optimize = shooting & ~cmd_optimize,
  req_shooting = req_shot | req_sweep | req_optimize | req_complete | req_monte_carlo | req_compare,
  /// The commands that print a table or a record (derive-table and merge write a table's file).
  printing = cmd_calc | shooting | cmd_contest,
};

/// A row of settings.def, by its id.
enum class Setting {
#define TREBUCHET_SETTING(id, ...) id,
#include "trebuchet/app/input/settings.def"
#undef TREBUCHET_SETTING
};

struct SettingRow {
  Setting id;
  const char* key;  ///< a request's key and the Python keyword: "tol"; "" where only the programs take it
  const char* flag;  ///< the programs' option: "--tol"; "" where only a request takes it
  std::vector<const char*> aliases;  ///< other names a request reads it under ("tolerance")
  UnitDimension dimension;  ///< of its value; dimensionless for a word, a switch or a path
  unsigned doors;  ///< Door bits
  const char* help;  ///< one line, for --help, the page and the docs
  const char* fallback;  ///< the value taken when it is not given, in words
  const char* range;  ///< the values taken, in words
};

/// Every setting, in the order of settings.def.
const std::vector<SettingRow>& setting_rows();

/// The row of a setting.
const SettingRow& setting_row(Setting id);

/// The row whose key or one of whose aliases is `name` exactly, among those a door of `doors`
/// takes; nullptr for none.
const SettingRow* find_setting(std::string_view name, unsigned doors);

/// A row's help for a program's option: the help, its default and the units it takes.
std::string setting_help(const SettingRow& row);

/// The keys and aliases of the settings a request of `doors` takes.
std::vector<std::string> setting_names(unsigned doors);

/// The work one run may do, decided before it starts: a Monte Carlo run's samples times the
/// shots of one sample (1 for a shot, those of a trial completion for complete), or
/// derive-table's X points times about shots_per_sweep_point (run/verifier.hpp), at most this: about 30 s on two
/// cores of the reference machine (docs/stability.md). It bounds {{samples}} too.
inline constexpr std::int64_t max_run_shots = 500000;

/// The settings of a shot or a run as given, whichever door they came through; empty where not
/// given. Values in SI units.
struct SettingsValues {
  std::optional<Release> quality;
  std::optional<double> n;  ///< eq:Q_n's exponent
  std::optional<double> tol;  ///< relative, on a predicted R and T
  std::optional<Stepper> stepper;
  std::optional<double> rtol, atol;  ///< per step: relative; absolute, scaled
  std::optional<double> target_level;  ///< [m]
  std::optional<bool> range_from_release;  ///< Denny's range, from the release point
  bool air = false;
  bool vacuum = false;  ///< the air given as off (false, "vacuum"): so it replaces a design's own air (overlay)
  std::optional<bool> drag_in_sling;  ///< the air acts before the release too (given false: not, over a design's own)
  std::optional<double> air_density;  ///< [kg/m^3]
  std::optional<double> cd;  ///< the sphere's drag coefficient
  bool cd_of_reynolds = false;  ///< Cd(Re) of a smooth sphere instead of a constant Cd
  std::optional<double> projectile;  ///< the projectile's density [kg/m^3]
  std::optional<double> wind;  ///< [m/s], toward the target
  std::optional<int> samples;  ///< of a Monte Carlo run
  std::optional<std::uint64_t> seed;
  std::optional<double> claim;  ///< a claimed range [m]
};

/// The settings of a shot from their values, checked (check_shot_settings): details of the air
/// without the air are refused, as is drag in the sling. Messages name {{air_density}}, {{cd}},
/// {{projectile}}, {{wind}} and {{drag_in_sling}}.
ShotSettings shot_settings(const SettingsValues& values);

/// The settings a caller lays over each design's own (DesignCheck::given), checked as far as
/// they go alone: a detail of the air without the air is left to the design's air.
ShotSettings shot_settings_over_designs(SettingsValues values);

/// The member of SettingsValues that a setting given as a number sets (target_level, wind,
/// air_density, cd: a Monte Carlo run may spread them); nullptr for the others.
std::optional<double> SettingsValues::*number_slot(Setting id);

/// Whether read_setting reads the setting: those a request takes as the programs' flag does (the
/// release, the integrator, the target, the air, a Monte Carlo run's). The others (a file, a
/// design, an output's format) are read by the command that takes them.
bool read_by_table(Setting id);

/// Reads the setting `id` from `text` (as a flag's value or a request's value written as text:
/// "range", "1e-9", "5m/s", "true") into `values`, checked as the row's range says; messages name
/// it `name` ("--tol", "{{tol}}"). Throws Error(usage | bad_number | unknown_unit).
void read_setting(Setting id, std::string_view text, SettingsValues& values, std::string_view name);

}  // namespace trebuchet
