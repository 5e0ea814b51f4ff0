// The constants tables (tab:CPNC and its re-derivations), the sweep parts of derive-table
// --shard and the derived tables, as JSON: what data/cpnc.json and the calculator's --table hold.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "trebuchet/scaling_table.hpp"
#include "trebuchet/sweep.hpp"
#include "trebuchet/table_derivation.hpp"

namespace trebuchet {

/// Parses and validates a constants table. Throws Error(data_file) naming `origin` and the
/// key: a missing key, a wrong type, a non-finite or non-positive number where one must be
/// positive, an empty interval, overlapping segments without distinct branch labels, two
/// blocks for one (theta_i, F), or a segment whose p_Z + 5 q_Z misses n_Z (eq:ZRT) by more
/// than one unit of the last printed digit of p_Z plus five of q_Z.
ScalingTable parse_scaling_table(std::string_view json_text, const std::string& origin);

/// A value per parameter as a JSON object with keys L1 ... mb.
nlohmann::ordered_json param_json(const ParamVector& values);

/// The material as the JSON object "reference_material" of tables and sweep parts.
nlohmann::ordered_json material_json(const Material& material);

/// The table as JSON, in the schema parse_scaling_table reads (data/cpnc.json).
nlohmann::ordered_json scaling_table_json(const ScalingTable& table);

/// Reads and parses a constants file (Error(data_file) if it cannot be read).
ScalingTable load_scaling_table(const std::string& path);

/// The text of data/cpnc.json as compiled in.
std::string_view builtin_scaling_table_json();

/// Parses "k/N" with 1 <= k <= N; Error(usage) names the text and the fix.
Shard parse_shard(const std::string& text);

/// One point as JSON: X, R, T, then the optimum's engine (schema.hpp) with Q, eps,
/// force_factor, theta_release_deg, optima_found and simulations, or the error.
nlohmann::ordered_json sweep_point_json(const SweepPoint& point);

/// A sweep part as JSON: the spec, the shard and its points (engines in the schema of
/// schema.hpp), numbers written to round-trip.
nlohmann::ordered_json sweep_part_json(const SweepPart& part);

/// Reads a part written by sweep_part_json. Throws Error(data_file) naming `origin`, the
/// JSON path and the fix.
SweepPart read_sweep_part(const nlohmann::json& json, const std::string& origin);

/// The table in the schema of data/cpnc.json, which the calculator reads with --table; each
/// segment also carries "points" and "fit_max_deviation", each block its "sweep".
nlohmann::ordered_json derived_table_json(const DerivedTable& derived);

}  // namespace trebuchet
