// Designs read back: a JSON object, array or CSV rows, as users write them or as any of the
// programs' records carry them, into an engine with the capacity it claims.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include <istream>

#include "trebuchet/capacity.hpp"
#include "trebuchet/engine.hpp"
#include "trebuchet/uncertainty.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/input/settings.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {

/// An engine read from JSON, with the capacity it claims when it carries one.
struct EngineRecord {
  Engine engine;
  std::optional<Capacity> capacity;  ///< "R" and "T", both or neither (level 0)
  bool mb_from_D = false;  ///< mb was not given: it follows from D and the wood (eq:BeamMass)
  std::optional<SetRelease> release_at;  ///< the release its builder set (release_time, release_angle_deg or pin_angle_deg)
  nlohmann::json passed = nlohmann::json::object();  ///< the keys no reader knows, as given: an answer names them
  SettingsValues settings;  ///< the settings the design gives (a record's "assumptions"), under the flags' and a request's own
  std::vector<std::string> notes;  ///< what the reader did that the answer should say: a flag that replaced the design's value
};

/// An uncertain input of a Monte Carlo run, named as its user gave it ("--M", "M").
struct UncertainInput {
  std::string name;
  UnitDimension dimension;
  Spread spread;
};

/// A value of a Monte Carlo run given as a range or a spread, and where its draw goes: a design's
/// value or a setting's (the target level, the wind, the air's density, its drag coefficient).
struct SpreadInput {
  UncertainInput input;
  std::optional<double> DesignValues::*value = nullptr;
  std::optional<double> SettingsValues::*setting = nullptr;
};

/// Puts `spread` into `spreads` in the order a run draws them, whatever the order they were given
/// in: a shot's inputs in the table's order (inputs.def), the settings that may be spread in
/// theirs (settings.def: the target level, the air's density, its drag coefficient, the wind),
/// then what a completion alone takes (Lb, l). So a run draws the same numbers from flags, a
/// file or a request, and its report read back draws them again.
void add_spread(std::vector<SpreadInput>& spreads, SpreadInput spread);

/// Where a design object gives the setting a run may spread into `slot`: in its air ("air.wind",
/// as settings.def's alias says), or under its key ("target_level").
std::string spread_setting_path(std::optional<double> SettingsValues::*slot);

/// The key of the value a spread draws, however it was given (a flag's spread is named by its
/// flag): an input's ("axle_radius"), or a setting's ("wind").
std::string spread_key(const SpreadInput& spread);

/// Whether `over`, laid over a design's own settings (overlay), gives what the design's `spread`
/// of a setting draws: that setting, Cd(Re) for the drag coefficient, or vacuum for the air's.
bool replaces_spread(const SettingsValues& over, const SpreadInput& spread);

/// `object`, a design's or the attested values as a Monte Carlo run gives them, with each value
/// given as a range ("2.5t..3.5t") or a spread ("3.5m±0.2m") replaced by at(spread) (unless
/// given: its first number, a range's low end or a spread's mean) and that spread put into
/// `spreads` (add_spread), named by its key: the inputs of `operation` but the capacity and the
/// material, and the settings a run may spread, under their key or in "air"
/// (spread_setting_path). Messages name a value "where.key". Throws Error(bad_number |
/// unknown_unit) for a bad spread.
nlohmann::json take_spreads(const nlohmann::json& object, unsigned operation, const std::string& where, std::vector<SpreadInput>& spreads,
                            const std::function<double(const Spread&)>& at = nullptr);

/// The first value of `object` given as a range or a spread, where take_spreads would find one,
/// read without copying `object`; none when each is one value. Throws as take_spreads does.
std::optional<UncertainInput> first_spread(const nlohmann::json& object, unsigned operation, const std::string& where);

/// Refuses a shot's value given as a range or a spread (a Monte Carlo run's: take_spreads takes
/// them out first), naming the first: "where.M: '2t..3t' is a range or a spread; give one value"
/// (Error(usage)).
void refuse_spreads(const nlohmann::json& object, const std::string& where);

/// Whether a design (design_object: a record reads as its design) holds a range or a spread of
/// a shot's value, which makes it a Monte Carlo run's.
bool holds_spreads(const nlohmann::json& design);

/// Whether a JSON object is a record the programs wrote of a shot: one with an "engine" object
/// (a shot's, fit's, optimum's, contest's, calibration's or a sweep's point), one with its
/// "assumptions" beside a shot's keys (a completion's), or a Monte Carlo run's report (its
/// "uncertain" beside its "design" or "attested").
bool is_record(const nlohmann::json& given);

/// Whether `given` is the report of calibrate's run over unknowns (calibration_run.hpp), which
/// runs again as a whole, not as a design.
bool is_calibration_record(const nlohmann::json& given);

/// The design a JSON object gives: the object itself, or, for a record (is_record), its engine with the settings it was shot with (its "assumptions",
/// under the settings' keys), the capacity it checked ("predicted" against vacuum, and its
/// tolerance) and the keys it passed through. So every record reads back as the same shot.
/// A Monte Carlo run's report gives its "design", the run as a request gives it: its ranges and
/// spreads as text, its settings and its samples, seed and claim; complete's run (its
/// "attested") is refused with the flags that run it again (Error(usage)).
nlohmann::json design_object(const nlohmann::json& given);

/// The settings a JSON object gives under the keys of the table of settings that a request of
/// `doors` takes (settings.def), each read as its flag is (read_setting); "air" may be false,
/// true, "vacuum" or an object of the air's keys (density, drag_coefficient, ...). Messages name
/// a key "{{key}}" (where empty) or "where.key". Other keys are passed over.
SettingsValues read_settings(const nlohmann::json& object, unsigned doors, const std::string& where);

/// `over` laid over `base`: each setting that `over` gives replaces `base`'s, each of the air's
/// details too; the air is on if either turns it on, unless `over` turns it off (vacuum), which
/// drops `base`'s details.
SettingsValues overlay(SettingsValues base, const SettingsValues& over);

/// What laying `over` on a design's own settings `own` (named in `where`) changes, a note each
/// ("--wind 0 m/s replaces design.wind = 5 m/s"), as overlay_flags says it of the engine's values.
std::vector<std::string> settings_notes(const SettingsValues& own, const SettingsValues& over, const std::string& where);

/// `flags` laid over a file's `values`: each value the flags give replaces the file's, and
/// `notes` says so where it differs ("--L4 = 5 m replaces design.L4 = 4 m"). A value that the
/// flag's fixes another way goes with it: --L3 drops the file's F, --F its L3, a new geometry
/// (--L1, --L2, --H, --theta) the F a record writes beside its L3, --theta or --L1 a pivot height
/// H (but the whipper's, which is its own), a taper the file's mb and D.
DesignValues overlay_flags(DesignValues values, const DesignValues& flags, const std::string& where, std::vector<std::string>& notes);

/// The parts as built that do not depend on the engine's other values (complete's, CompletionRequest::parts):
/// the pins' friction, the counterweight's inertia, the trough's friction and the rope, from the values given.
EngineParts independent_parts(const DesignValues& values);

/// The value of `key` in a JSON object: an SI number, or a string with a unit ("6.13m");
/// empty when absent or null. Messages name it "where.key" (where empty: "{{key}}"). Throws
/// Error(bad_number | unknown_unit) for a value of another kind.
std::optional<double> read_value(const nlohmann::json& object, const std::string& key, UnitDimension dimension, const std::string& where);

/// The values of a JSON design object, each an SI number or a string with a unit ("6.13m"), under
/// its key or an alias (input_fields). A key that the programs write passes silently; any other
/// key is refused or put in `passed` by pass_through (which lets a record's own, one that carries
/// its version, pass as written).
/// Throws Error(bad_number | unknown_unit | usage) naming the key, and Error(usage) for a value
/// given as a range or a spread (a Monte Carlo run's: take_spreads reads them).
/// A record the programs wrote reads as its design_object; the settings it gives go to `settings`
/// when not null (else they are passed over).
DesignValues read_design_values(const nlohmann::json& object, const std::string& where, nlohmann::json* passed = nullptr,
                                SettingsValues* settings = nullptr);

/// The values of the inputs `operation` takes (input_fields), each under its key or an alias
/// (not both: Error(usage)), and with a shot the machine; other keys are passed over. Each an SI
/// number or a string with a unit, named "where.key" in messages.
DesignValues read_input_values(const nlohmann::json& object, const std::string& where, unsigned operation);

/// Refuses `key`, which no reader of `known` takes, when it is near one of them:
/// 'where: unknown key "theta_i"; did you mean "theta_i_deg"?' (Error(usage)).
void refuse_near_miss(const std::string& key, const std::vector<std::string>& known, const std::string& where);

/// The key under which a user's own numbers pass through a design unread ({"notes": {"year":
/// 1304}}), as a site's name or a comment does under any key of its own.
inline constexpr const char* notes_key = "notes";

/// A key of a design that no reader of `known` takes: refused when it is near one of them
/// (refuse_near_miss) or when its value is a number or a quantity ("0.5", "0.5kg", "2t..3t"), which
/// may be meant for the engine and must not pass unread (Error(usage), naming notes_key as the
/// place for a user's own numbers); any other value (a text, true, a list, an object) is put in
/// `passed` when that is not null. In a record the programs wrote (`by_program`: it carries its
/// version), what passed through once (a CSV's columns) passes again, numbers too, and its own
/// notes are dropped (they are written again).
void pass_through(const std::string& key, const nlohmann::json& value, const std::vector<std::string>& known, const std::string& where,
                  nlohmann::json* passed, bool by_program = false);

/// The release that a design's values set, by time, velocity angle or pin angle; none when they
/// set none. Throws Error(usage) for more than one, Error(bad_number) for a value out of range,
/// naming the keys as engine_record does.
std::optional<SetRelease> release_of(const DesignValues& values, const std::string& where);

/// How messages name a key of a design: "{{key}}" for flags, which a program writes as its
/// option (error.hpp), or "where.key" in a file ("design.L4").
std::string engine_key_name(const std::string& where, const std::string& key);

/// The engine of a design's values: L3, or F = (L2 + L3)/H, theta_i 30 deg unless given, the
/// material of eq:kMkD where not given; checked (check_engine). `where` names the design in
/// messages ("design[2]"; empty: a program's options, named "{{L4}}" as error.hpp says).
EngineRecord engine_record(const DesignValues& values, const std::string& where);

/// Reads an engine: L1, L2, L4, M, m, mb; L3, or F = (L2 + L3)/H; optional theta_i_deg
/// (default 30), D, the material keys (default eq:kMkD's) and R with T. Values are SI numbers
/// or strings with a unit ("6.13m"); other keys are ignored, so that every writer's output
/// reads back. `where` names the object in messages ("design[2]"; empty: the command line,
/// whose keys are named as flags, "--L1"). Throws Error(bad_number | unknown_unit | usage)
/// naming the key and the fix, and checks the engine (check_engine).
/// With `flags`, the flags' values are laid over the design's (overlay_flags), named in the notes.
EngineRecord read_engine(const nlohmann::json& object, const std::string& where, const DesignValues* flags = nullptr);

/// Designs read from CSV (docs/csv.md), such as the calculator's batch output: one design a row.
struct DesignRows {
  std::vector<std::string> passed_columns;  ///< columns that are no engine key, e.g. site, in order
  struct Row {
    int line = 0;  ///< line number in the input
    nlohmann::json design;  ///< the engine keys as strings with units, for read_engine
    std::vector<std::string> passed;  ///< the pass-through cells
    std::string error;  ///< a row that cannot be read, or an "error" cell written upstream
    std::string air_described;  ///< the verifier's "air" cell of a shot in air: described, not given
  };
  std::vector<Row> rows;
};

/// Why `row` makes no shot under the caller's settings `given` (empty: it may): it could not be
/// read, failed upstream, or was shot in an air its CSV only describes and `given` sets none.
std::string row_refusal(const DesignRows::Row& row, const SettingsValues& given);

/// Reads CSV text: the engine's keys (with units in the header, "L1_m", or in the cells), R and
/// T as the capacity to check, theta for theta_i_deg. The calculator's other columns (X, Y, Lb,
/// H, l, l4, L, mu, mu_b, K, DeltaU, amplification, branch, warnings) follow from the engine and
/// are dropped; any other column passes through. Throws Error(usage) for an input without a header.
DesignRows read_design_rows(std::istream& input, const std::string& source);

}  // namespace trebuchet
