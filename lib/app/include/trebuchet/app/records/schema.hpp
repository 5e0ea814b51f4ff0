// The one JSON and CSV form of an engine, as every record that carries one writes it: the
// engine's keys (the paper's symbols in SI base units: m, kg, J, Pa, kg/m^3, m/s^2; angles carry
// _deg), its parts as built, and the CSV helpers. Each operation's record lives with it:
// design_record.hpp (the calculator), shot_record.hpp (a shot), search_records.hpp (optimize,
// complete, calibrate); design_input.hpp reads them back. docs/schema.md lists every key.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/engine.hpp"
#include "trebuchet/app/input/fields.hpp"

namespace trebuchet {

/// The project's version in PEP 440 form ("0.1.0"): every JSON record carries it as "version",
/// to say what computed it (the commit is --version's and Python's __commit__, not a record's).
const char* project_version();
inline constexpr const char* version_key = "version";

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

/// Throws Error(bad_number) naming the first field that is not finite.
void require_finite(const std::vector<Field>& fields);

/// The parts as built (FieldGroup::part): their CSV columns in SI, the last of the verifier's,
/// and an engine's cells under them (empty where it has no such part).
std::vector<std::string> part_columns();
std::vector<std::string> part_cells(const Engine& engine, int digits);

/// Throws Error(data_file) naming `what` and the JSON path if `json` holds a number that is not
/// finite: JSON has no inf or nan, and nlohmann would write null in their place.
void require_finite_json(const nlohmann::ordered_json& json, const std::string& what);

}  // namespace trebuchet
