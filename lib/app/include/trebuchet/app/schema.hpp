// The one JSON and CSV form of an engine and of the records that carry one, read and written
// by both programs, the sweep parts and the derived tables. Keys are the paper's symbols in SI
// base units (m, kg, J, Pa, kg/m^3, m/s^2); angles carry _deg; forces as multiples of m g or
// M g carry _mg or _Mg. docs/schema.md lists every key.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/calculator.hpp"
#include "trebuchet/capacity.hpp"
#include "trebuchet/engine.hpp"
#include "trebuchet/calibration.hpp"
#include "trebuchet/completion.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/app/fields.hpp"
#include "trebuchet/app/units.hpp"

namespace trebuchet {

/// A named number of a record, in print order.
struct Field {
  const char* key;
  double value;
  const char* unit = "";  ///< SI unit in the CSV column name ("m" gives "R_m"); "" for pure numbers
};

/// A field's CSV column: the key with its unit, "R_m", "wood_density_kg_m3" (docs/csv.md).
std::string csv_column(const Field& field);

/// One CSV line of `cells`, each quoted where it must be, ending in a line feed.
std::string csv_line(const std::vector<std::string>& cells);

/// The engine's keys: theta_i_deg, F, beta2, L1, L2, L3, L4, D, M, m, mb, Lb, H, the scaled
/// design l, l4, L, mu, mu_b, K, DeltaU (eq:DU) and the material youngs_modulus, wood_density, g.
std::vector<Field> engine_fields(const Engine& engine);

/// engine_fields as JSON members of `out`. Throws Error(numerical) if a value is not finite.
void write_engine(nlohmann::ordered_json& out, const Engine& engine);

/// An engine read from JSON, with the capacity it claims when it carries one.
struct EngineRecord {
  Engine engine;
  std::optional<Capacity> capacity;  ///< "R" and "T", both or neither (level 0)
  bool mb_from_D = false;            ///< mb was not given: it follows from D and the wood (eq:BeamMass)
  nlohmann::json passed = nlohmann::json::object();  ///< the keys no reader knows, as given: an answer names them
};

/// The parts as built that do not depend on the engine's other values (complete's, CompletionRequest::parts):
/// the pins' friction, the counterweight's inertia, the trough's friction and the rope, from the values given.
EngineParts independent_parts(const DesignValues& values);

/// The value of `key` in a JSON object: an SI number, or a string with a unit ("6.13m");
/// empty when absent or null. Messages name it "where.key" (where empty: "{{key}}"). Throws
/// Error(bad_number | unknown_unit) for a value of another kind.
std::optional<double> read_value(const nlohmann::json& object, const std::string& key, UnitDimension dimension, const std::string& where);

/// The values of a JSON design object, each an SI number or a string with a unit ("6.13m"), under
/// its key or an alias (input_fields). A key that the programs write passes silently; a key near
/// an input's name is refused with that name (near_miss); any other key is put in `passed`.
/// Throws Error(bad_number | unknown_unit | usage) naming the key.
DesignValues read_design_values(const nlohmann::json& object, const std::string& where, nlohmann::json* passed = nullptr);

/// Refuses `key`, which no reader of `known` takes, when it is near one of them:
/// 'where: unknown key "theta_i"; did you mean "theta_i_deg"?' (Error(usage)).
void refuse_near_miss(const std::string& key, const std::vector<std::string>& known, const std::string& where);

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
EngineRecord read_engine(const nlohmann::json& object, const std::string& where);

/// Designs read from CSV (docs/csv.md), such as the calculator's batch output: one design a row.
struct DesignRows {
  std::vector<std::string> passed_columns;  ///< columns that are no engine key, e.g. site, in order
  struct Row {
    int line = 0;                      ///< line number in the input
    nlohmann::json design;             ///< the engine keys as strings with units, for read_engine
    std::vector<std::string> passed;   ///< the pass-through cells
    std::string error;                 ///< a row that cannot be read, or an "error" cell written upstream
  };
  std::vector<Row> rows;
};

/// Reads CSV text: the engine's keys (with units in the header, "L1_m", or in the cells), R and
/// T as the capacity to check, theta for theta_i_deg. The calculator's other columns (X, Y, Lb,
/// H, l, l4, L, mu, mu_b, K, DeltaU, amplification, branch, warnings) follow from the engine and
/// are dropped; any other column passes through. Throws Error(usage) for an input without a header.
DesignRows read_design_rows(std::istream& input, const std::string& source);

/// Throw Error(bad_number | numerical) naming the first figure of the record that is not finite,
/// as its writers do: for a report that prints the record in another form.
void require_finite(const OptimalEngine& design);
void require_finite(const Verification& verification);

/// The calculator's design: R, T, X, Y, the engine's keys, amplification, branch, warnings and,
/// near X_d, branch_steps.
/// What a shot assumed: "air" ("vacuum"), g [m/s^2], theta_i_deg, the arm fraction F, the
/// release criterion (--quality) and n, and the target level [m].
nlohmann::ordered_json assumptions_json(const Engine& engine, const ShotSettings& settings);

nlohmann::ordered_json design_json(const OptimalEngine& design);

/// The design's CSV columns, keys with units (R_m, T_J, ...), branch, warnings and air (vacuum), and one
/// design's cells with `digits` significant digits, quoted where they must be and joined by commas
/// (no line feed): a batch appends them to a row.
std::vector<std::string> design_csv_header();
/// Every name the calculator's outputs use (CSV columns, JSON keys, a batch's line and error):
/// a column of a batch passed through must not take one of them.
std::vector<std::string> design_output_names();
std::string design_csv_text(const OptimalEngine& design, int digits);

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

/// Throws Error(data_file) naming `what` and the JSON path if `json` holds a number that is not
/// finite: JSON has no inf or nan, and nlohmann would write null in their place.
void require_finite_json(const nlohmann::ordered_json& json, const std::string& what);

/// An optimum: the engine's keys, start, simulations, iterations, wall_time_s (the whole
/// search's, given by the caller) and the verification's keys of its shot.
nlohmann::ordered_json optimum_json(const Optimum& optimum, double wall_time_s);

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
