// The one table of an engine's inputs (its rows: inputs.def): every value a user gives the calculator, a shot, a
// completion or an optimum, declared once with its names, dimension, unit, default, range and
// help. The programs' flags, the JSON keys and CSV columns, the Python module's dicts, the
// page's inputs (api::fields), the workbook's labels and docs/inputs.md all come from it.
// An unknown key near one of its names is refused with that name (near_miss).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "trebuchet/design.hpp"
#include "trebuchet/quality.hpp"
#include "trebuchet/material.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {

/// The values of a design as given (a JSON object, a CSV row or a program's options), in SI
/// units, angles in degrees; a value not given is empty. One member per row of inputs.def.
struct DesignValues {
#define TREBUCHET_INPUT(key, ...) std::optional<double> key;
#include "trebuchet/app/input/inputs.def"
#undef TREBUCHET_INPUT
  /// The machine, a name rather than a number (names.hpp): --machine, the JSON key and CSV
  /// column "machine"; empty: the paper's hinged counterweight.
  std::optional<MachineKind> machine;
};

/// The key, CSV column and Python key of DesignValues::machine; its flag is "--machine".
inline constexpr const char* machine_key = "machine";

/// The operations that take an input, a bit each.
enum Operation : unsigned {
  op_given = 1,  ///< a given of trebuchet-calc and api::design (two of them)
  op_calculator = 2,  ///< a setting of the calculator (theta_i, F, the material)
  op_shot = 4,  ///< an engine: shot, fit, calibrate, a Monte Carlo run of shots
  op_complete = 8,  ///< an attested value of complete
  op_optimize = 16,  ///< the capacity and the settings of optimize
};

/// What an input describes: the engine's values of eq:Parameters and its initial angles; a value
/// that stands in for one of them (F for L3, D for mb, Lb, H and l for L1 and L2); the material;
/// a capacity; a release the builder sets; or a part of the engine as built. A Monte Carlo run
/// may spread all but the material and the capacity.
enum class FieldGroup { engine, alternative, material, capacity, release, part };

struct InputField {
  std::optional<double> DesignValues::*member;
  const char* key;  ///< the JSON key, the CSV column's stem and the Python key: "theta_i_deg"
  const char* flag;  ///< the programs' option: "--theta"
  std::vector<const char*> aliases;  ///< other names it is read under ("theta"): every one documented stays
  UnitDimension dimension;
  const char* unit;  ///< its SI unit in a CSV column ("m": "L4_m"), "" for a pure number or an angle in degrees
  FieldGroup group;
  unsigned operations;  ///< Operation bits
  const char* label;  ///< a few words, for the page and the workbook: "sling"
  const char* help;  ///< one line, for --help and the docs
  const char* example;  ///< a value as typed: "5.80m"
  const char* fallback;  ///< the value taken when it is not given, in words; "" for none
  const char* range;  ///< the values the library takes, in words (the core checks them)
  double Material::*material;  ///< the member of Material it sets; nullptr for none
};

/// The input that sets a release in the form `by` (quality.hpp): release_time, release_angle_deg or pin_angle_deg.
const InputField& release_field(ReleaseBy by);

/// Every input, in the order the programs list them (inputs.def).
const std::vector<InputField>& input_fields();

/// The row of a member of DesignValues.
const InputField& field_of(std::optional<double> DesignValues::*member);

/// The row whose key or one of whose aliases is `name` exactly; nullptr for none.
const InputField* find_field(std::string_view name);

/// A row's names: its key, then its aliases.
std::vector<const char*> names_of(const InputField& field);

/// The key of a member: key_of(&DesignValues::L4) is the text the table gives it.
inline const char* key_of(std::optional<double> DesignValues::*member) { return field_of(member).key; }

/// A row's help for a program's option: the help, its default and the units it takes
/// ("sling length, spigot to projectile [m, cm, mm, km, ft, in]").
std::string option_help(const InputField& field);

/// `base` with the material values given in `values` (the rows with a Material member).
Material material_of(const DesignValues& values, Material base);

/// The CSV column of a row written in SI: the key with its unit ("L4_m"; "theta_i_deg").
std::string csv_column_of(const InputField& field);

/// The distance between two words in single-letter edits (insert, delete, replace, or swap two
/// neighbours: "plto" is one from "plot"), letters compared without case.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// Whether `word` is near `name`: the same but for the case for names of one or two letters, one
/// edit for names of up to 4 letters, two for longer ones (the flags' rule for their suggestions).
bool near_name(std::string_view word, std::string_view name);

/// The name a key `word` that no reader knows was meant as, or empty: an input of `known` whose
/// key or alias it is but for blanks, underscores, hyphens and case ("L_4", "L4 ", "m_b"), or with
/// its unit left off or put on ("theta_i", "L4_ft", "M_kg", "L4m", "theta_degrees"); else the
/// name of `known` nearest to it within near_name.
std::string near_miss(std::string_view word, const std::vector<std::string>& known);

/// "length", "mass", ...: a dimension's name, as fields_json writes it.
const char* dimension_name(UnitDimension dimension);

/// Whether `name` is the row's key with a unit put on, as a CSV column names it ("L4_m", "L4_ft",
/// "g_m_s2"): in JSON, a near miss of the key.
bool unit_column_of(std::string_view name, const InputField& field);

/// The keys and aliases of the inputs that `operations` take (any of its bits).
std::vector<std::string> input_names(unsigned operations);

}  // namespace trebuchet
