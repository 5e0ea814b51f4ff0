#include "trebuchet/app/records/design_input.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "trebuchet/air.hpp"
#include "trebuchet/angles.hpp"
#include "trebuchet/app/input/csv.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {

std::string engine_key_name(const std::string& where, const std::string& key) { return where.empty() ? "{{" + key + "}}" : where + "." + key; }

namespace {

// A value a design must have: the message says what it is, with the table's example written as
// a flag ("--mb 660kg") or as a key ("mb": "660kg"), as the design was given.
double required(const DesignValues& values, std::optional<double> DesignValues::*member, const std::string& where, const std::string& what,
                const std::string& alternative = "") {
  if (values.*member) return *(values.*member);
  const InputField& field = field_of(member);
  const std::string key = field.key, example = field.example;
  throw Error(ErrorKind::usage,
              (where.empty() ? "{{" + key + "}} is missing; give " + what + ", e.g. {{" + key + "}} " + example
                             : where + ": key \"" + key + "\" is missing; give " + what + ", e.g. \"" + key + "\": \"" + example + "\"") +
                  alternative);
}

}  // namespace

std::optional<double> read_value(const nlohmann::json& object, const std::string& key, UnitDimension dimension, const std::string& where) {
  if (!object.contains(key) || object[key].is_null()) return std::nullopt;
  const nlohmann::json& value = object[key];
  const std::string name = engine_key_name(where, key);
  if (value.is_number()) {
    const double number = value.get<double>();
    if (!std::isfinite(number)) throw Error(ErrorKind::bad_number, name + ": " + brief_json(value) + " is not a finite number");
    return number;
  }
  if (value.is_string()) return parse_value(value.get<std::string>(), dimension, name);
  throw Error(ErrorKind::bad_number, name + ": " + brief_json(value) + " is neither a number nor a value with a unit like \"6.13m\"");
}

namespace {

// The settings a Monte Carlo run may spread (those with a number_slot), in the table's order.
const std::vector<const SettingRow*>& spread_setting_rows() {
  static const std::vector<const SettingRow*> rows = [] {
    std::vector<const SettingRow*> found;
    for (const SettingRow& row : setting_rows())
      if (number_slot(row.id)) found.push_back(&row);
    return found;
  }();
  return rows;
}

// A spread's place in the order of add_spread.
std::size_t draw_rank(const SpreadInput& spread) {
  std::size_t rank = 0;
  for (const bool shot : {true, false}) {
    for (const InputField& field : input_fields())
      if (static_cast<bool>(field.operations & op_shot) == shot) {
        if (spread.value == field.member) return rank;
        ++rank;
      }
    if (shot)
      for (const SettingRow* row : spread_setting_rows()) {
        if (spread.setting == number_slot(row->id)) return rank;
        ++rank;
      }
  }
  return rank;
}

}  // namespace

void add_spread(std::vector<SpreadInput>& spreads, SpreadInput spread) {
  const std::size_t rank = draw_rank(spread);
  const auto after = std::find_if(spreads.begin(), spreads.end(), [&](const SpreadInput& s) { return draw_rank(s) > rank; });
  spreads.insert(after, std::move(spread));
}

std::string spread_key(const SpreadInput& spread) {
  if (spread.value) return key_of(spread.value);
  for (const SettingRow* row : spread_setting_rows())
    if (number_slot(row->id) == spread.setting) return row->key;
  return spread.input.name;
}

std::string spread_setting_path(std::optional<double> SettingsValues::*slot) {
  for (const SettingRow* row : spread_setting_rows())
    if (number_slot(row->id) == slot) {
      for (const std::string alias : row->aliases)
        if (alias.rfind("air.", 0) == 0) return alias;
      return row->key;
    }
  return "";
}

bool replaces_spread(const SettingsValues& over, const SpreadInput& spread) {
  if (!spread.setting) return false;
  return (over.*spread.setting).has_value() || (spread.setting == &SettingsValues::cd && over.cd_of_reynolds) ||
      (over.vacuum && spread_setting_path(spread.setting).rfind("air.", 0) == 0);
}

namespace {

// Each place in `object` where a Monte Carlo run's range or spread may stand, visited as
// visit(slot, key, dimension, value, setting): the inputs of `operation` but the capacity and
// the material under their keys, and the settings a run may spread, under their key or in "air"
// (spread_setting_path). `object` may be const (to look) or not (to replace).
template <class Json, class Visit>
void each_spread_slot(Json& object, unsigned operation, const Visit& visit) {
  for (auto& [key, value] : object.items()) {
    const InputField* field = find_field(key);
    if (field && (field->operations & operation) && field->group != FieldGroup::capacity && field->group != FieldGroup::material)
      visit(value, key, field->dimension, field->member, nullptr);
  }
  for (const SettingRow* row : spread_setting_rows()) {
    const std::string path = spread_setting_path(number_slot(row->id));
    if (object.contains(row->key)) visit(object[row->key], row->key, row->dimension, nullptr, number_slot(row->id));
    if (path.rfind("air.", 0) == 0 && object.contains("air") && object["air"].is_object() && object["air"].contains(path.substr(4)))
      visit(object["air"][path.substr(4)], row->key, row->dimension, nullptr, number_slot(row->id));
  }
}

using Value = std::optional<double> DesignValues::*;
using SettingValue = std::optional<double> SettingsValues::*;

// The spread a slot holds as text, named `key` in messages; none for one value.
std::optional<Spread> spread_in(const nlohmann::json& slot, const std::string& key, UnitDimension dimension, const std::string& where) {
  return slot.is_string() ? parse_spread(slot.get<std::string>(), dimension, engine_key_name(where, key)) : std::nullopt;
}

}  // namespace

nlohmann::json take_spreads(const nlohmann::json& object, unsigned operation, const std::string& where, std::vector<SpreadInput>& spreads,
                            const std::function<double(const Spread&)>& at) {
  if (!object.is_object()) return object;
  nlohmann::json plain = object;
  each_spread_slot(plain, operation, [&](nlohmann::json& slot, const std::string& key, UnitDimension dimension, Value value, SettingValue setting) {
    const auto given = spread_in(slot, key, dimension, where);
    if (!given) return;
    slot = at ? at(*given) : given->a;
    add_spread(spreads, SpreadInput{UncertainInput{key, dimension, *given}, value, setting});
  });
  return plain;
}

std::optional<UncertainInput> first_spread(const nlohmann::json& object, unsigned operation, const std::string& where) {
  std::optional<UncertainInput> first;
  if (!object.is_object()) return first;
  each_spread_slot(object, operation, [&](const nlohmann::json& slot, const std::string& key, UnitDimension dimension, Value, SettingValue) {
    if (first) return;
    if (const auto given = spread_in(slot, key, dimension, where)) first = UncertainInput{key, dimension, *given};
  });
  return first;
}

void refuse_near_miss(const std::string& key, const std::vector<std::string>& known, const std::string& where) {
  const std::string meant = near_miss(key, known);
  if (!meant.empty())
    throw Error(ErrorKind::usage, (where.empty() ? std::string() : where + ": ") + "unknown key \"" + key + "\"; did you mean \"" + meant + "\"?");
}

namespace {

// Whether `value` reads as a number or a quantity of some dimension: 0.5, "0.5", "0.5kg",
// "2/3", "2t..3t", "3.5m±0.2m".
bool reads_as_quantity(const nlohmann::json& value) {
  if (value.is_number()) return true;
  if (!value.is_string()) return false;
  const std::string text = value.get<std::string>();
  static const std::vector<UnitDimension> dimensions = [] {  // every dimension a unit has, and a bare number's
    std::vector<UnitDimension> found{UnitDimension::dimensionless};
    for (const UnitFactor& unit : unit_factors())
      if (std::find(found.begin(), found.end(), unit.dimension) == found.end()) found.push_back(unit.dimension);
    return found;
  }();
  for (const UnitDimension dimension : dimensions) {
    try {
      parse_value(text, dimension, "");
      return true;
    } catch (const Error&) {
    }
    try {
      if (parse_spread(text, dimension, "")) return true;
    } catch (const Error&) {
    }
  }
  return false;
}

}  // namespace

void pass_through(const std::string& key, const nlohmann::json& value, const std::vector<std::string>& known, const std::string& where,
                  nlohmann::json* passed, bool by_program) {
  if (by_program && key == notes_key && value.is_array()) return;  // a record's own notes, written again when it is shot
  refuse_near_miss(key, known, where);
  if (!by_program && key != notes_key && reads_as_quantity(value))
    throw Error(ErrorKind::usage,
                engine_key_name(where, key) + ": " + brief_json(value) +
                    " is a number under a key that is no input or setting, so it would pass unread; give it under its "
                    "input's key (docs/inputs.md), or keep your own numbers under \"" +
                    notes_key + "\": {\"" + notes_key + "\": {\"" + key + "\": " + brief_json(value) + "}}");
  if (passed) (*passed)[key] = value;
}

bool is_calibration_record(const nlohmann::json& given) {
  return given.is_object() && given.contains("fitted") && given.contains("measured") && given["measured"].is_object() && given.contains("design") &&
      given["design"].is_object();
}

bool is_record(const nlohmann::json& given) {
  const auto holds_object = [&](const char* key) { return given.contains(key) && given[key].is_object(); };
  return given.is_object() &&
      (holds_object("engine") || (holds_object("assumptions") && given.contains("R_vacuum")) ||
       (given.contains("uncertain") && (holds_object("design") || holds_object("attested"))) || is_calibration_record(given));
}

namespace {

// Whether a record's air writes the ball's density as the one that follows from the engine's m
// and its ball's diameter, to round-off: a density edited by hand is kept, and
// refused beside the diameter.
bool written_by_diameter(const nlohmann::json& engine, const nlohmann::json& air) {
  const auto number = [](const nlohmann::json& object, const char* key) {
    return object.contains(key) && object[key].is_number() ? std::optional<double>(object[key].get<double>()) : std::nullopt;
  };
  const auto d = number(engine, "projectile_diameter"), m = number(engine, "m"), density = number(air, "projectile_density");
  if (!d || !m || !density) return d.has_value();
  return *density > 0 && *m > 0 && std::abs(sphere_diameter(*m, *density) - *d) <= 1e-9 * *d;
}

// What a record holds beside its engine and its settings ("assumptions"), taken into `design`,
// the engine's values. Its own R and T (its shot's), its check's tolerance (beside "predicted")
// and copies of its engine's values (calibrate's fitted friction; 0 for a part the engine leaves
// out) are the record's. An input or a shot's setting put beside them would not be read, so it
// is refused by name. Any other key joins the design's other keys, which read_design_values reads
// as it reads them: the records' outputs silently, the rest passed through by name.
void take_beside_engine(const nlohmann::json& record, nlohmann::json& design) {
  const nlohmann::json& engine = record["engine"];
  for (const auto& [key, value] : record.items()) {
    if (key == "engine" || key == "assumptions" || key == "passed" || key == notes_key || key == "R" || key == "T" ||
        (key == "tolerance" && record.contains("predicted")))
      continue;
    const bool input = find_field(key) != nullptr || key == machine_key;
    if (input && (engine.contains(key) ? engine[key] == value : value.is_number() && value.get<double>() == 0)) continue;
    if (input || find_setting(key, req_shot))
      throw Error(ErrorKind::usage,
                  "\"" + key + "\" beside a record's \"engine\" is not read; give it " +
                      (input ? "in the engine (\"engine\": {\"" + key + "\": ...})" : std::string("in its \"assumptions\"")) +
                      ", or over the record as a flag or a keyword (shot(record, " + key + "=...))");
    if (!find_setting(key, ~0u) && !design.contains(key)) design[key] = value;  // a contest's own settings (objective) are its record's
  }
}

// A Monte Carlo run's attested values as a front end gives them, each name in double braces
// for the front end's own word (error.hpp: a program's flag, a request's key): "{{Lb}} 9.5m {{M}}
// '2t..3t' {{air}} {{cd}} 0.3". A value that a shell would split is quoted.
std::string attested_words(const nlohmann::json& attested) {
  std::vector<std::string> words;
  const auto word = [&](const std::string& name, const nlohmann::json& value) {
    if (value.is_boolean()) {
      if (value.get<bool>()) words.push_back("{{" + name + "}}");
    } else if (value.is_string() || value.is_number()) {
      const std::string text = value.is_string() ? value.get<std::string>()
          : value.is_number_integer()            ? value.dump()  // a seed to 2^64, whole
                                                 : format_number(value.get<double>());
      const bool plain = text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.+-/%\xC2\xB1") == std::string::npos;
      words.push_back("{{" + name + "}}" + (plain ? " " + text : " '" + text + "'"));
    }
  };
  for (const auto& [key, value] : attested.items()) {
    if (const InputField* field = find_field(key)) {
      word(field->key, value);
    } else if (key == "air" && value.is_object()) {
      words.emplace_back("{{air}}");
      for (const auto& [detail, detail_value] : value.items())
        if (const SettingRow* row = find_setting("air." + detail, cmd_complete)) word(row->key, detail_value);
    } else if (const SettingRow* row = find_setting(key, cmd_complete)) {
      if (!(key == "air" && value == "vacuum")) word(row->key, value);
    }
  }
  return join(words, " ");
}

}  // namespace

nlohmann::json design_object(const nlohmann::json& given) {
  if (!is_record(given)) return given;
  if (given.contains("uncertain")) {  // a Monte Carlo run's report: the run as a request gives it
    if (given.contains("design") && given["design"].is_object()) return given["design"];
    throw Error(ErrorKind::usage,
                "this is the report of complete's Monte Carlo run, which runs again from its attested values: give it to complete as "
                "its attested values (a request's or Python's attested=report), or run it again with trebuchet-verify complete " +
                    attested_words(given["attested"]));
  }
  // The engine: its own object, or (a completion's record) the record's keys, less the shot's
  // range and energy, which are no claim.
  if (is_calibration_record(given))
    throw Error(ErrorKind::usage,
                "this is the report of calibrate's run over unknowns, which runs again as a whole: give it to trebuchet-verify as its input "
                "(trebuchet-verify report.json), or shoot its engine with each unknown given one value");
  nlohmann::json design = given.contains("engine") && given["engine"].is_object() ? given["engine"] : given;
  if (given.contains("engine")) take_beside_engine(given, design);
  if (!given.contains("engine")) design.erase("R"), design.erase("T"), design.erase("assumptions"), design.erase("passed");
  // "assumptions" holds the settings under their keys, and beside them what is no setting: the
  // engine's own g, theta_i_deg and F (in "engine" too), the given release's description (the
  // engine carries its key) and the sphere's size, which follows from m and the other: its
  // density, or the diameter the engine gives its ball.
  if (given.contains("assumptions") && given["assumptions"].is_object())
    for (const auto& [key, value] : given["assumptions"].items()) {
      if (key == "g" || key == "theta_i_deg" || key == "F" || key == "release_at") continue;
      design[key] = value;
      if (key == "air" && value.is_object()) {
        design[key].erase("projectile_diameter");
        if (written_by_diameter(design, value)) design[key].erase("projectile_density");
      }
    }
  // The capacity it checked in vacuum, with the tolerance; fit's, checked as measured, is no
  // claim of the engine it wrote.
  if (given.contains("predicted") && given["predicted"].is_object() && given.value("against", "") == "vacuum") {
    for (const char* key : {"R", "T"})
      if (given["predicted"].contains(key)) design[key] = given["predicted"][key];
    if (given.contains("tolerance")) design["tol"] = given["tolerance"];
  }
  if (given.contains("passed") && given["passed"].is_object())
    for (const auto& [key, value] : given["passed"].items())
      if (!design.contains(key)) design[key] = value;
  return design;
}

bool holds_spreads(const nlohmann::json& design) { return first_spread(design_object(design), op_shot, "design").has_value(); }

SettingsValues read_settings(const nlohmann::json& object, unsigned doors, const std::string& where) {
  SettingsValues v;
  std::vector<std::pair<Setting, std::string>> given;  // each setting read, and the key that gave it
  const auto name_of = [&](const std::string& key) { return engine_key_name(where, key); };
  const auto text_of = [&](const nlohmann::json& value, const std::string& key) -> std::string {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
    if (value.is_number_integer()) return value.dump();  // 500000, not 5e+05: a whole number reads back as one
    if (value.is_number()) {
      const double x = value.get<double>();
      if (!std::isfinite(x)) throw Error(ErrorKind::bad_number, name_of(key) + ": " + brief_json(value) + " is not a finite number");
      return x == std::floor(x) && std::fabs(x) < 1e15 ? std::to_string(static_cast<long long>(x)) : format_number(x);
    }
    throw Error(ErrorKind::usage, name_of(key) + ": " + brief_json(value) + " must be a number, a text or true or false");
  };
  const auto read = [&](const SettingRow& row, const nlohmann::json& value, const std::string& key) {
    const auto first = std::find_if(given.begin(), given.end(), [&](const auto& g) { return g.first == row.id; });
    if (first != given.end()) throw Error(ErrorKind::usage, name_of(first->second) + " and " + name_of(key) + " both give " + row.key + "; keep one");
    given.emplace_back(row.id, key);
    read_setting(row.id, text_of(value, key), v, name_of(key));
  };
  if (!object.is_object()) return v;
  for (const auto& [key, value] : object.items()) {
    const SettingRow* row = find_setting(key, doors);
    if (!row || !read_by_table(row->id) || value.is_null()) continue;  // the object's own key, or the material's
    if (row->id != Setting::air || value.is_boolean()) {
      read(*row, value, key);
    } else if (value.is_object()) {
      v.air = true;
      std::vector<std::string> known;
      for (const std::string& name : setting_names(doors))
        if (name.rfind("air.", 0) == 0) known.push_back(name.substr(4));
      for (const auto& [inner, detail] : value.items()) {
        const SettingRow* detail_row = find_setting("air." + inner, doors);
        if (!detail_row) {
          refuse_near_miss(inner, known, where.empty() ? "air" : where + ".air");
          throw Error(ErrorKind::usage, name_of("air") + ": '" + inner + "' is no key of the air; use " + join(known, ", "));
        }
        read(*detail_row, detail, "air." + inner);
      }
    } else if (value == "vacuum") {
      read(*row, value, key);
    } else {
      throw Error(ErrorKind::usage,
                  name_of("air") + ": " + brief_json(value) +
                      " is no air; give false (vacuum), true (the standard air) or an object like {\"wind\": \"5m/s\"}");
    }
  }
  return v;
}

namespace {

// Every setting a caller's value replaces one for one, by its row (its key and dimension in
// settings.def) and the member that holds it, in the order the notes name them: overlay lays
// each over, settings_notes says so. The air's switch follows its own rule (overlay), and a drag
// coefficient given replaces Cd(Re) too.
template <class Base, class Visit>
void each_setting(Base& base, const SettingsValues& over, Visit visit) {
  visit(Setting::quality, base.quality, over.quality);
  visit(Setting::n, base.n, over.n);
  visit(Setting::tol, base.tol, over.tol);
  visit(Setting::stepper, base.stepper, over.stepper);
  visit(Setting::rtol, base.rtol, over.rtol);
  visit(Setting::atol, base.atol, over.atol);
  visit(Setting::target_level, base.target_level, over.target_level);
  visit(Setting::range_from, base.range_from_release, over.range_from_release);
  visit(Setting::drag_in_sling, base.drag_in_sling, over.drag_in_sling);
  visit(Setting::air_density, base.air_density, over.air_density);
  visit(Setting::cd, base.cd, over.cd);
  visit(Setting::projectile, base.projectile, over.projectile);
  visit(Setting::wind, base.wind, over.wind);
  visit(Setting::samples, base.samples, over.samples);
  visit(Setting::seed, base.seed, over.seed);
  visit(Setting::claim, base.claim, over.claim);
}

// A setting's value as a note writes it: a number with its row's unit, a word, or a count.
std::string setting_text(Setting id, double value) { return quantity_text(value, setting_row(id).dimension, UnitSystem::si, 6); }
std::string setting_text(Setting, Release value) { return release_name(value); }
std::string setting_text(Setting, Stepper value) { return stepper_name(value); }
std::string setting_text(Setting id, bool value) {
  if (id == Setting::range_from) return value ? "release" : "pivot";
  return value ? "true" : "false";
}
std::string setting_text(Setting, int value) { return std::to_string(value); }
std::string setting_text(Setting, std::uint64_t value) { return std::to_string(value); }

}  // namespace

SettingsValues overlay(SettingsValues base, const SettingsValues& over) {
  // The air: off replaces the base's air with its details; otherwise each detail given replaces
  // the base's own, and the air is on if either turns it on.
  if (over.vacuum) {
    const SettingsValues none;
    base.drag_in_sling = none.drag_in_sling, base.air_density = none.air_density, base.cd = none.cd;
    base.cd_of_reynolds = none.cd_of_reynolds, base.projectile = none.projectile, base.wind = none.wind;
  }
  base.air = over.air || (base.air && !over.vacuum);
  base.vacuum = over.vacuum || (base.vacuum && !over.air);
  // A drag coefficient given replaces Cd(Re), and Cd(Re) given replaces a drag coefficient.
  if (over.cd || over.cd_of_reynolds) base.cd_of_reynolds = over.cd_of_reynolds;
  each_setting(base, over, [&](Setting id, auto& mine, const auto& theirs) {
    if (theirs || (id == Setting::cd && over.cd_of_reynolds)) mine = theirs;
  });
  return base;
}

std::vector<std::string> settings_notes(const SettingsValues& own, const SettingsValues& over, const std::string& where) {
  std::vector<std::string> notes;
  if (own.air && over.vacuum)
    notes.push_back("{{air}}=false replaces the air " + (where.empty() ? "the design" : where) + " gives: it flies in vacuum");
  each_setting(own, over, [&](Setting id, const auto& mine, const auto& theirs) {
    if (!mine || !theirs) return;
    const std::string given = setting_text(id, *theirs), replaced = setting_text(id, *mine);
    const char* key = setting_row(id).key;
    if (given != replaced) notes.push_back("{{" + std::string(key) + "}} " + given + " replaces " + engine_key_name(where, key) + " = " + replaced);
  });
  return notes;
}

DesignValues overlay_flags(DesignValues values, const DesignValues& flags, const std::string& where, std::vector<std::string>& notes) {
  using V = DesignValues;
  const auto say = [&](const InputField& flag, const InputField& replaced) {
    const auto with_unit = [](const InputField& field, double x) { return quantity_text(x, field.dimension, UnitSystem::si, 6); };
    notes.push_back("{{" + std::string(flag.key) + "}} " + with_unit(flag, *(flags.*flag.member)) + " replaces " +
                    engine_key_name(where, replaced.key) + " = " + with_unit(replaced, *(values.*replaced.member)));
  };
  for (const InputField& field : input_fields()) {
    const std::optional<double>& flag = flags.*field.member;
    if (!flag) continue;
    std::optional<double>& own = values.*field.member;
    // A record writes D = 0 for a beam given by its mass: no value to replace.
    if (own && *own != *flag && !(field.member == &V::D && *own == 0)) say(field, field);
    own = flag;
  }
  // The machine's flag over another machine is a change like a value's, and noted as one.
  const MachineKind own_machine = values.machine.value_or(MachineKind::hinged);
  if (flags.machine && *flags.machine != own_machine)
    notes.push_back("{{machine}} " + machine_name(*flags.machine) + " replaces " + engine_key_name(where, machine_key) + " = " +
                    machine_name(own_machine));
  if (flags.machine) values.machine = flags.machine;
  // A value the flag fixes another way goes with it, as a program's flags could not give both.
  const auto drop = [&](std::optional<double> V::*given, std::initializer_list<std::optional<double> V::*> others) {
    if (flags.*given)
      for (const auto other : others)
        if (!(flags.*other)) values.*other = std::nullopt;
  };
  drop(&V::L3, {&V::F});
  drop(&V::F, {&V::L3});
  // A record writes F beside its L3; F follows from L3 and the geometry (eq:Design), so the flags'
  // new geometry keeps L3, the part as built, and F goes.
  if (values.L3) drop(&V::L1, {&V::F}), drop(&V::L2, {&V::F}), drop(&V::H, {&V::F}), drop(&V::theta_i_deg, {&V::F});
  // The whipper's start is its own theta_i and H; the other machines' H follows from L1 and theta_i.
  if (values.machine.value_or(MachineKind::hinged) != MachineKind::whipper) {
    drop(&V::theta_i_deg, {&V::H});
    drop(&V::L1, {&V::H});
    if (flags.H && !flags.theta_i_deg) values.theta_i_deg = std::nullopt;
  }
  drop(&V::D_hinge, {&V::mb, &V::D});
  drop(&V::D_tip, {&V::mb, &V::D});
  drop(&V::mb, {&V::D_hinge, &V::D_tip});
  // The wood gives a taper's mass and diameter again; a round beam's mass, written beside its D,
  // stands (it may have been weighed).
  if (flags.wood_density && values.D_hinge && values.D_tip) drop(&V::wood_density, {&V::mb, &V::D});
  if (flags.wood_density && !flags.mb && !values.D_tip && values.D.value_or(0) > 0 && values.mb)
    notes.push_back("{{wood_density}} leaves " + engine_key_name(where, "mb") + " = " +
                    quantity_text(*values.mb, UnitDimension::mass, UnitSystem::si, 6) +
                    " as given; leave mb out of the file to take the beam's mass from its D in this wood");
  for (const ReleaseBy by : {ReleaseBy::time, ReleaseBy::velocity_angle, ReleaseBy::pin_angle}) {  // one release: the flags' replaces the file's
    const InputField& field = release_field(by);
    if (flags.*field.member)
      for (const ReleaseBy other : {ReleaseBy::time, ReleaseBy::velocity_angle, ReleaseBy::pin_angle})
        if (other != by && values.*release_field(other).member) {
          say(field, release_field(other));
          values.*release_field(other).member = std::nullopt;
        }
  }
  return values;
}

void refuse_spreads(const nlohmann::json& object, const std::string& where) {
  if (const std::optional<UncertainInput> first = first_spread(object, op_shot, where)) {
    const std::string text = object.contains(first->name) && object[first->name].is_string() ? object[first->name].get<std::string>()
                                                                                             : spread_text(first->spread, first->dimension);
    throw Error(ErrorKind::usage,
                engine_key_name(where, first->name) + ": '" + text +
                    "' is a range or a spread; give one value (ranges and spreads are for the Monte Carlo run of one design: "
                    "shot with one design object, or monte_carlo)");
  }
}

DesignValues read_input_values(const nlohmann::json& object, const std::string& where, unsigned operation) {
  DesignValues v;
  for (const InputField& field : input_fields()) {
    if (!(field.operations & operation)) continue;
    v.*field.member = read_value(object, field.key, field.dimension, where);
    // An alias is read too; a value given under two names is refused.
    for (const char* alias : field.aliases) {
      const std::optional<double> aliased = read_value(object, alias, field.dimension, where);
      if (!aliased) continue;
      if (v.*field.member)
        throw Error(ErrorKind::usage,
                    engine_key_name(where, field.key) + " and " + engine_key_name(where, alias) + " are one value given twice; keep one");
      v.*field.member = aliased;
    }
  }
  if ((operation & op_shot) && object.contains(machine_key) && !object[machine_key].is_null()) {
    const nlohmann::json& machine = object[machine_key];
    const std::string name = engine_key_name(where, machine_key);
    if (!machine.is_string()) throw Error(ErrorKind::usage, name + ": " + brief_json(machine) + " is not a machine's name; use " + machine_names());
    v.machine = parse_machine(machine.get<std::string>(), name);
  }
  return v;
}

namespace {

// The keys an engine object is read for: the inputs a shot takes, the machine, and a shot's settings (read_settings).
const std::vector<std::string>& known_keys() {
  static const std::vector<std::string> known = [] {
    std::vector<std::string> names = input_names(op_shot);
    names.push_back(machine_key);
    for (const SettingRow& row : setting_rows())  // a shot's settings, read by read_settings
      if ((row.doors & req_shot) && read_by_table(row.id)) {
        names.emplace_back(row.key);
        for (const char* alias : row.aliases)
          if (std::string_view(alias).find('.') == std::string_view::npos) names.emplace_back(alias);
      }
    return names;
  }();
  return known;
}

// The programs' JSON keys: their CSV columns that are an input's key with a unit ("L4_m") are
// near misses in JSON, where a value carries its unit in its text.
const std::vector<std::string>& written_keys() {
  static const std::vector<std::string> written = [] {
    std::vector<std::string> names;
    for (const auto& list : {design_output_names(), verification_output_names()})
      for (const std::string& name : list)
        if (name != notes_key &&  // a record's notes are its own (pass_through drops them); a user's are passed through
            std::none_of(input_fields().begin(), input_fields().end(), [&](const InputField& field) { return unit_column_of(name, field); }))
          names.push_back(name);
    names.insert(names.end(),
                 {version_key,
                  "passed",
                  "simulations",
                  "start",
                  "iterations",
                  "wall_time_s",
                  "note",
                  "attested",
                  "implied",
                  "chosen",
                  "calculator",
                  "calculator_note",
                  "longest_range",
                  "longest_range_note",
                  "warnings",
                  "theta_release_deg",
                  "optima_found",
                  "predicted",
                  "deviation",
                  "against",
                  "pass",
                  "energy",
                  "clearance",
                  "pin_tolerance",
                  "pin_to_bend_by_friction",
                  "objective",
                  "shots",
                  "search",
                  "limits",
                  "measured",
                  "steps",
                  "fitted",
                  "value",
                  "value_low",
                  "value_high",
                  "band_clipped",
                  "jams_at",
                  "R_frictionless",
                  "T_frictionless",
                  "shot",
                  "predictions",
                  "series",
                  "line",
                  "error"});
    return names;
  }();
  return written;
}

// The other keys: what the programs write (read back, as CSV columns are), a near miss, or the
// caller's own (a site's name), passed through; a Monte Carlo run's settings refused.
void pass_other_keys(const nlohmann::json& object, const std::string& where, nlohmann::json* passed, bool by_program) {
  const std::vector<std::string>& known = known_keys();
  const std::vector<std::string>& written = written_keys();
  for (const auto& [key, value] : object.items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    if (std::find(written.begin(), written.end(), key) != written.end()) continue;  // the records' own outputs, read back silently
    for (const Setting id : {Setting::samples, Setting::seed, Setting::claim})  // a run's, read where a value is a range or a spread
      if (key == setting_row(id).key)
        throw Error(ErrorKind::usage,
                    engine_key_name(where, key) +
                        " belongs to a Monte Carlo run; give a value of the design as a range (2.5t..3.5t) or a spread "
                        "(3.5m±0.2m), or drop it");
    pass_through(key, value, known, where, passed, by_program);
  }
}

}  // namespace

DesignValues read_design_values(const nlohmann::json& given, const std::string& where, nlohmann::json* passed, SettingsValues* settings) {
  const bool record = is_record(given);
  const bool by_program = given.is_object() && given.contains(version_key);  // a record the programs wrote (written_by_program)
  const nlohmann::json unwrapped = record ? design_object(given) : nlohmann::json();
  const nlohmann::json& object = record ? unwrapped : given;
  if (!object.is_object())
    throw Error(ErrorKind::usage,
                (where.empty() ? std::string("input") : where) + ": expected a JSON object with keys L1, L2, L3 (or F), L4, M, m, mb, theta_i_deg");
  refuse_spreads(object, where);
  const DesignValues v = read_input_values(object, where, op_shot);
  pass_other_keys(object, where, passed, by_program);
  if (settings) *settings = read_settings(object, req_shot, where);
  return v;
}

EngineParts independent_parts(const DesignValues& v) {
  EngineParts p;
  p.counterweight_inertia = v.counterweight_inertia.value_or(0);
  p.axle = {v.axle_friction.value_or(0), v.axle_radius.value_or(0)};
  p.hinge = {v.hinge_friction.value_or(0), v.hinge_radius.value_or(0)};
  p.trough_friction = v.trough_friction.value_or(0);
  p.rope_diameter = v.rope_diameter.value_or(0);
  p.rope_cd = v.rope_cd.value_or(p.rope_cd);
  p.rope_mass = v.rope_mass.value_or(0);
  p.pouch_mass = v.pouch_mass.value_or(0);
  p.pin_friction = v.pin_friction.value_or(0);
  return p;
}

namespace {

// The parts of an engine as built from the values given (EngineParts); check_engine checks them.
void engine_parts(const DesignValues& v, const std::string& where, EngineRecord& in) {
  Engine& e = in.engine;
  EngineParts& p = e.parts;
  p = independent_parts(v);
  const auto name = [&](const char* key) { return engine_key_name(where, key); };
  // The taper gives mb and D; flags may not give them too, and a file may only as the programs
  // write them, agreeing with the taper (checked in engine_record, once the taper is known).
  if ((v.D_tip || v.D_hinge) && where.empty()) {
    if (v.mb)
      throw Error(ErrorKind::usage,
                  name("D_hinge") + " and " + name("D_tip") + " give the beam's mass from its wood; leave out " + name("mb") + " (or the taper)");
    if (v.D)
      throw Error(ErrorKind::usage, name("D_hinge") + " and " + name("D_tip") + " give the beam's diameter at the pivot; leave out " + name("D"));
  }
  p.beam_cm = v.beam_cm;
  p.beam_inertia = v.beam_inertia;
  p.beam_gyration = v.beam_gyration;  // I = mb k^2 with mb as the run has it (given_beam_inertia)
  p.D_hinge = v.D_hinge, p.D_tip = v.D_tip;
  if (v.box_width || v.box_height) {
    if (!v.box_width || !v.box_height)
      throw Error(ErrorKind::usage, "a box counterweight needs both " + name("box_width") + " and " + name("box_height"));
    if (v.counterweight_inertia)
      throw Error(ErrorKind::usage,
                  name("counterweight_inertia") + " and the box " + name("box_width") + " both give the counterweight's inertia; give one");
    for (const auto& [value, key] : {std::pair{*v.box_width, "box_width"}, {*v.box_height, "box_height"}}) {
      if (!(value > 0)) throw Error(ErrorKind::bad_number, name(key) + " = " + format_significant(value, 6) + ": a side of the box must be positive");
      check_ordinary(value, 1e-6, 1e6, key, "m", "side of the counterweight's box");
    }
    give_box(e, *v.box_width, *v.box_height);
  }
}

}  // namespace

std::optional<SetRelease> release_of(const DesignValues& v, const std::string& where) {
  std::optional<SetRelease> out;
  std::vector<std::string> given;
  for (const ReleaseBy by : {ReleaseBy::time, ReleaseBy::velocity_angle, ReleaseBy::pin_angle}) {
    const InputField& field = release_field(by);
    if (!(v.*field.member)) continue;
    given.push_back(engine_key_name(where, field.key));
    out = SetRelease{by, *(v.*field.member)};
  }
  if (given.size() > 1) throw Error(ErrorKind::usage, join(given, " and ") + " each set the release; give one of them");
  if (out) {
    ShotSettings settings;
    settings.release_at = out;
    try {
      check_shot_settings(settings);
    } catch (const Error& error) {
      throw Error(error.kind(), error.message([&](std::string_view key) { return engine_key_name(where, std::string(key)); }));
    }
  }
  return out;
}

namespace {

// theta_i (or the pivot height H that sets it, the tip on the ground) and psi_i; the whipper's frame.
void read_start(const DesignValues& v, const std::string& where, Engine& e) {
  using V = DesignValues;
  const bool whipper = e.machine == MachineKind::whipper;
  e.theta_i_deg = v.theta_i_deg.value_or(whipper ? whipper_theta_i_deg : standard_theta_i_deg);
  e.psi_i_deg = v.psi_i_deg.value_or(0);
  if (whipper) {  // its frame and where its bodies rest (whipper.hpp)
    e.whipper.H = required(v, &V::H, where, "the whipper's pivot height over the base (its frame)");
    e.whipper.rope_angle_deg = v.rope_angle_deg.value_or(e.whipper.rope_angle_deg);
  } else {
    // A pivot height without theta_i sets it, the tip on the ground: H = L1 cos(theta_i), as
    // VirtualTrebuchet and pytrebuchet give an engine.
    if (v.H && !v.theta_i_deg && e.L1 > 0) {
      check_ordinary(*v.H, 1e-6, 1e6, "H", "m", "pivot height");
      if (!(*v.H < e.L1))
        throw Error(ErrorKind::bad_number,
                    engine_key_name(where, "H") + " = " + format_significant(*v.H, 6) +
                        " m: the pivot must stand lower than the long arm's length L1 = " + format_significant(e.L1, 6) +
                        " m, so that its tip rests on the ground; give a lower H or a longer L1");
      e.theta_i_deg = degrees(std::acos(*v.H / e.L1));
    }
    if (v.rope_angle_deg)
      throw Error(
          ErrorKind::usage,
          engine_key_name(where, "rope_angle_deg") + " is the whipper's start; leave it out, or give the machine as whipper (docs/machines.md)");
  }
}

// The counterweight's arm: L3, or the fraction F = (L2 + L3)/H; a given H agrees with L1 cos(theta_i).
void read_counterweight_arm(const DesignValues& v, const std::string& where, Engine& e) {
  const bool whipper = e.machine == MachineKind::whipper;
  const std::string named = where.empty() ? std::string("flags") : where;
  // A program's options give one of them; a file may carry both, as the programs write them (below).
  if (where.empty() && v.L3 && v.F)
    throw Error(ErrorKind::usage, "{{L3}} and {{F}} both fix the counterweight arm (L2 + L3 = F H); give one of them");
  if (v.L3) {
    e.L3 = *v.L3;
  } else if (const auto F = v.F) {
    if (!(*F > 0))
      throw Error(ErrorKind::bad_number,
                  engine_key_name(where, "F") + " = " + format_significant(*F, 6) +
                      ": the counterweight arm fraction (L2 + L3)/H must be positive; the paper's are 1, 2/3 and 1/2");
    e.L3 = whipper ? *F * e.whipper.H - e.L2 : counterweight_arm(e.L1, e.L2, e.theta_i_deg, *F);
    const bool at_arm_end = e.machine != MachineKind::hinged && std::abs(e.L3) <= 1e-12 * e.L2;  // F = L2/H, within its rounding
    if (at_arm_end) e.L3 = 0;
    // The angle as the user gave it: theta_i, or the pivot height H that set it (theta_i = acos(H/L1)).
    const bool by_height = v.H && !v.theta_i_deg;
    const std::string angle = by_height ? "H = " + format_significant(*v.H, 4) + " m (theta_i = " + format_significant(e.theta_i_deg, 4) + " deg)"
                                        : "theta_i = " + format_significant(e.theta_i_deg, 4) + " deg";
    if (e.theta_i_deg > 0 && e.theta_i_deg < 90 && e.L1 > 0 && e.L2 > 0 && !(e.L3 > 0) && !at_arm_end)
      throw Error(ErrorKind::bad_number,
                  named + ": with F = " + format_significant(*F, 4) + " and " + angle + ", L2 + L3 = F L1 cos(theta_i) = " +
                      format_significant(*F * pivot_height(e), 4) + " m is not longer than L2 = " + format_significant(e.L2, 4) +
                      " m: no room for the counterweight arm; " + (by_height ? "raise H" : "lower theta_i") + ", raise F or lengthen L1");
  } else {
    throw Error(ErrorKind::usage, named + ": give the counterweight arm L3 in metres, or the fraction F = (L2 + L3)/H, e.g. F = 2/3");
  }
  // The others' pivot height is L1 cos(theta_i): a given one, as the programs write it (6 digits
  // in CSV), must agree with it.
  if (!whipper && v.H && e.L1 > 0 && e.theta_i_deg > 0 && e.theta_i_deg < 90 && !(std::abs(*v.H - pivot_height(e)) <= 1e-4 * pivot_height(e)))
    throw Error(ErrorKind::usage,
                engine_key_name(where, "H") + " = " + format_significant(*v.H, 6) + " m, but this machine's pivot height is L1 cos(theta_i) = " +
                    format_significant(pivot_height(e), 6) + " m; give H or theta_i, not both (H alone sets theta_i = acos(H/L1))");
}

// The beam as given: tapered (D_hinge and D_tip), or round of diameter D (eq:BeamMass), whose mass follows.
void read_beam(const DesignValues& v, const std::string& where, EngineRecord& in) {
  Engine& e = in.engine;
  const Material& material = e.material;
  if (e.parts.D_tip && e.parts.D_hinge && *e.parts.D_tip > 0 && *e.parts.D_hinge > 0 && e.L1 > 0 &&
      e.L2 > 0) {  // the tapered beam's mass and its diameter at the pivot
    e.mb = wood_beam_mass(e);
    e.D = tapered_beam(e.L1, e.L2, *e.parts.D_hinge, *e.parts.D_tip, material.wood_density).D_pivot;
    in.mb_from_D = true;
    // A file's mb and D (as the programs write them) must be the taper's, to round-off of text.
    const auto name = [&](const char* key) { return engine_key_name(where, key); };
    for (const auto& [given, derived, key] : {std::tuple{v.mb, e.mb, "mb"}, {v.D, e.D, "D"}})
      if (given && !(std::abs(*given - derived) <= 1e-9 * derived))
        throw Error(ErrorKind::usage,
                    name("D_hinge") + " and " + name("D_tip") + " give " + name(key) + " = " + format_significant(derived, 9) +
                        " from the wood, but the input says " + format_significant(*given, 9) + "; leave out " + name(key) + " (or the taper)");
  }
  if (v.D && !v.mb && !v.D_tip) {  // eq:BeamMass: a round beam of the material's wood
    if (!(e.D > 0))
      throw Error(ErrorKind::bad_number,
                  engine_key_name(where, "D") + " = 0 gives no beam; give the beam's diameter, or its mass " + engine_key_name(where, "mb"));
    if (!(e.D <= 1e6))
      throw Error(ErrorKind::bad_number,
                  engine_key_name(where, "D") + " = " + format_significant(e.D, 6) +
                      " m is not of ordinary size for the beam diameter; give one from 1e-06 to 1e+06 m");
    e.mb = beam_mass(e.D, beam_length(e), material);
    in.mb_from_D = true;
  }
}

// The engine checked in the words of its record, L3 and F in agreement, the release and the capacity.
void check_record(const DesignValues& v, const std::string& where, EngineRecord& in) {
  Engine& e = in.engine;
  const std::string named = where.empty() ? std::string("flags") : where;
  try {
    check_engine(e);
  } catch (const Error& error) {
    const std::string said = error.message([&](std::string_view key) { return engine_key_name(where, std::string(key)); });
    throw Error(error.kind(),
                in.mb_from_D && said.find(engine_key_name(where, "mb")) != std::string::npos
                    ? said + " (mb = " + format_significant(e.mb, 4) + " kg follows from " + engine_key_name(where, "D") + " = " +
                        format_significant(e.D, 4) + " m by eq:BeamMass; give another " + engine_key_name(where, "D") + ")"
                    : said);
  }
  // L3 and F both, as the programs write them: L3 is used, and F must agree with it to the
  // rounding of values written to 3 significant digits or more (2e-3, with room to spare).
  if (v.L3 && v.F && !(std::abs(arm_fraction(e) / *v.F - 1) <= 2e-2))
    throw Error(ErrorKind::usage,
                named + ": L3 = " + format_significant(e.L3, 6) + " m gives F = (L2 + L3)/H = " + format_significant(arm_fraction(e), 6) +
                    ", not F = " + format_significant(*v.F, 6) + "; both fix the counterweight arm, give one of them");
  if (v.R.has_value() != v.T.has_value()) throw Error(ErrorKind::usage, named + ": a capacity needs both R and T; give both or neither");
  in.release_at = release_of(v, where);
  if (v.R && !(*v.R > 0 && *v.T > 0))
    throw Error(ErrorKind::bad_number,
                named + ": R = " + format_significant(*v.R, 6) + " m, T = " + format_significant(*v.T, 6) +
                    " J: R and T must be positive; give the predicted range and energy, e.g. R = 150 m and T = 40 kJ");
  if (v.R) in.capacity = Capacity{*v.R, *v.T, 0};
}

}  // namespace

EngineRecord engine_record(const DesignValues& v, const std::string& where) {
  EngineRecord in;
  Engine& e = in.engine;
  using V = DesignValues;
  e.L1 = required(v, &V::L1, where, "the long beam section");
  e.L2 = required(v, &V::L2, where, "the short beam section");
  e.L4 = required(v, &V::L4, where, "the sling length");
  e.M = required(v, &V::M, where, "the counterweight mass");
  e.m = required(v, &V::m, where, "the projectile mass");
  // Without mb, a beam diameter gives it from the wood (eq:BeamMass), below.
  if ((v.mb && !v.D_tip && !v.D_hinge) || (!v.mb && !v.D && !v.D_tip && !v.D_hinge))
    e.mb = required(v, &V::mb, where, "the beam mass",
                    where.empty() ? ", or the beam's diameter {{D}}, from which it follows" : ", or \"D\", the beam's diameter");
  e.machine = v.machine.value_or(MachineKind::hinged);
  read_start(v, where, e);
  e.projectile_diameter = v.projectile_diameter;
  // D = 0 is how the outputs write "not given" (they read back); below 0 it is a mistake.
  if (v.D && !(*v.D >= 0))
    throw Error(ErrorKind::bad_number,
                engine_key_name(where, "D") + " = " + format_significant(*v.D, 6) +
                    ": the beam diameter must not be negative; give it, or leave it out (0: not given)");
  e.D = v.D.value_or(0);
  read_counterweight_arm(v, where, e);
  e.material = material_of(v, e.material);  // eq:kMkD's where not given
  engine_parts(v, where, in);
  read_beam(v, where, in);
  check_record(v, where, in);
  return in;
}

EngineRecord read_engine(const nlohmann::json& object, const std::string& where, const DesignValues* flags) {
  nlohmann::json passed = nlohmann::json::object();
  SettingsValues settings;
  std::vector<std::string> notes;
  DesignValues values = read_design_values(object, where, &passed, &settings);
  if (flags) values = overlay_flags(values, *flags, where, notes);
  EngineRecord record = engine_record(values, where);
  record.passed = std::move(passed);
  record.settings = settings;
  record.notes = std::move(notes);
  return record;
}

std::string row_refusal(const DesignRows::Row& row, const SettingsValues& given) {
  if (!row.error.empty() || row.air_described.empty() || given.air || given.vacuum) return row.error;
  return "its shot flew through " + row.air_described +
      ", which the CSV describes but does not give; give the air ({{air}} and its details) or vacuum ({{air}}=false), or shoot its JSON "
      "record, which reads back in its air";
}

namespace {

// The verifier's own CSV's results (all but its inputs, parts, machine and given release): dropped when read back.
std::vector<std::string> own_result_columns() {
  std::vector<std::string> results;
  std::vector<std::string> inputs = part_columns();
  inputs.push_back("psi_i_deg");
  inputs.push_back(machine_key);
  inputs.push_back(csv_column_of(field_of(&DesignValues::modulus_of_rupture)));
  for (const InputField& field : input_fields())  // a given release reads back
    if (field.group == FieldGroup::release) inputs.push_back(csv_column_of(field));
  for (const Field& field : engine_fields(Engine{})) inputs.push_back(csv_column(field));
  for (const std::string& column : verification_csv_header())
    if (std::find(inputs.begin(), inputs.end(), column) == inputs.end()) results.push_back(column);
  return results;
}

// What a column of designs' CSV holds: an input of the engine (with its unit), the machine, a
// setting of the verifier's own CSV, its air described, a result dropped, a cell passed through,
// or a row's error.
struct RowsColumn {
  enum { engine, machine, setting, air, dropped, passed, error } role;
  ColumnName name;
};

// The role of the column `header` after `columns` (refused where it names an input in no unit,
// or an input a column before it gives). The verifier's own CSV (`own_output`) has its results
// dropped and the settings its shot was made with read back under their keys; its air is
// described, not given, so a row shot in air is refused rather than shot again in vacuum.
RowsColumn column_of(const std::string& header, bool own_output, const std::vector<std::string>& results, const std::vector<RowsColumn>& columns,
                     const std::vector<std::string>& header_cells, const std::string& source) {
  static const std::vector<std::string> inputs = input_names(op_shot);
  static const std::vector<std::string_view> engine_keys(inputs.begin(), inputs.end());
  static const std::vector<std::string_view> dropped = {"X",      "Y",        "Lb", "H", "l", "l4", "L", "mu", "mu_b", "K", "DeltaU", "amplification",
                                                        "branch", "warnings", "air"};
  static const std::vector<std::pair<std::string, ColumnName>> settings_columns = {
      {"release", {"release", ""}}, {"n", {"n", ""}}, {"target_level_m", {"target_level", "m"}}, {"range_from", {"range_from", ""}}};
  const auto setting = std::find_if(settings_columns.begin(), settings_columns.end(), [&](const auto& c) { return c.first == header; });
  if (own_output && setting != settings_columns.end()) {
    return {RowsColumn::setting, setting->second};
  } else if (own_output && header == "air") {
    return {RowsColumn::air, {header, ""}};
  } else if (own_output && (header == "predicted_R_m" || header == "predicted_T_J")) {
    return {RowsColumn::engine, {header == "predicted_R_m" ? "R" : "T", header == "predicted_R_m" ? "m" : "J"}};
  } else if (own_output && std::find(results.begin(), results.end(), header) != results.end()) {
    return {RowsColumn::dropped, {header, ""}};
  } else if (const auto name = split_column_name(header, engine_keys)) {
    const InputField& field = *find_field(name->key);
    const std::string key = field.key;  // an alias ("theta") read as its key
    if (!name->unit.empty() && !is_unit_word(name->unit)) {  // "theta_i", "L4_fet": the header's fault, not each row's
      refuse_near_miss(header, inputs, source);
      throw Error(ErrorKind::unknown_unit,
                  source + ": the column '" + header + "' gives " + key + " in '" + name->unit + "', which is no unit of " +
                      dimension_name(field.dimension) + "; name it " + key + " with one of " + unit_list(field.dimension) + " (e.g. " +
                      csv_column_of(field) + "), or " + key + " alone");
    }
    for (std::size_t k = 0; k < columns.size(); ++k)
      if (columns[k].role == RowsColumn::engine && columns[k].name.key == key)
        throw Error(ErrorKind::usage, source + ": the columns '" + header_cells[k] + "' and '" + header + "' both give " + key + "; keep one");
    return {RowsColumn::engine, {key, name->unit}};
  } else if (split_column_name(header, dropped)) {
    return {RowsColumn::dropped, {header, ""}};
  } else if (header == "error") {
    return {RowsColumn::error, {header, ""}};
  } else if (header == machine_key) {
    return {RowsColumn::machine, {header, ""}};
  } else {
    refuse_near_miss(header, inputs, source);  // "theta_i", "L_4": meant as an input, not passed through
    return {RowsColumn::passed, {header, ""}};
  }
}

// A column every design needs is a fault of the file, not of each row.
void require_columns(const std::vector<RowsColumn>& columns, const std::string& source) {
  auto has = [&](const char* key) {
    return std::any_of(columns.begin(), columns.end(), [&](const RowsColumn& c) { return c.role == RowsColumn::engine && c.name.key == key; });
  };
  std::string missing;
  using V = DesignValues;
  for (auto member : {&V::L1, &V::L2, &V::L4, &V::M, &V::m})
    if (!has(key_of(member))) missing += (missing.empty() ? "" : ", ") + std::string(key_of(member));
  if (!has("mb") && !has("D") && !has("D_tip")) missing += (missing.empty() ? "" : ", ") + std::string("mb or D");
  if (!has("L3") && !has("F")) missing += (missing.empty() ? "" : ", ") + std::string("L3 or F");
  if (!missing.empty())
    throw Error(ErrorKind::usage,
                source + " is neither JSON nor CSV of designs: its header lacks " + missing +
                    "; give a design object, an array of them, or CSV such as trebuchet-calc --batch writes");
}

// The next row of designs' CSV, or none at its end: its design object, its passed-through cells
// (first, so that a bad value leaves them in the row) and its error; a cell that cannot be read
// is the row's error.
std::optional<DesignRows::Row> read_row(CsvReader& reader, const std::vector<RowsColumn>& columns, std::size_t passed_count) {
  DesignRows::Row row;
  row.passed.assign(passed_count, "");
  CsvRow cells;
  try {
    if (!reader.next(cells)) return std::nullopt;
    row.line = cells.line;
    row.design = nlohmann::json::object();
    // The pass-through cells first, so that a bad value leaves them in the row.
    for (std::size_t k = 0, p = 0; k < columns.size(); ++k) {
      if (columns[k].role == RowsColumn::passed) row.passed[p++] = cells.cells[k];
      if (columns[k].role == RowsColumn::error) row.error = cells.cells[k];
    }
    for (std::size_t k = 0; k < columns.size(); ++k)
      if (columns[k].role == RowsColumn::engine && !cells.cells[k].empty())
        row.design[columns[k].name.key] = cell_value(cells.cells[k], columns[k].name.unit, reader.header()[k]);
      else if (columns[k].role == RowsColumn::machine && !cells.cells[k].empty())
        row.design[machine_key] = cells.cells[k];
      else if (columns[k].role == RowsColumn::setting && !cells.cells[k].empty())
        row.design[columns[k].name.key] = columns[k].name.unit.empty()
            ? nlohmann::json(cells.cells[k])
            : nlohmann::json(cell_value(cells.cells[k], columns[k].name.unit, reader.header()[k]));
      else if (columns[k].role == RowsColumn::air && !cells.cells[k].empty() && cells.cells[k] != "vacuum")
        row.air_described = cells.cells[k];
  } catch (const Error& e) {
    row.line = cells.line;
    row.error = e.what();
  }
  return row;
}

}  // namespace

DesignRows read_design_rows(std::istream& input, const std::string& source) {
  CsvReader reader(input, source);
  // The verifier's own CSV (it alone has R_vacuum_m): its results are dropped, and the capacity
  // it checked, predicted_R_m and predicted_T_J, is the one to check again.
  const std::vector<std::string>& header_cells = reader.header();
  const bool own_output = std::find(header_cells.begin(), header_cells.end(), "R_vacuum_m") != header_cells.end();
  const std::vector<std::string> results = own_output ? own_result_columns() : std::vector<std::string>();
  std::vector<RowsColumn> columns;
  DesignRows out;
  for (const std::string& header : header_cells) {
    columns.push_back(column_of(header, own_output, results, columns, header_cells, source));
    if (columns.back().role == RowsColumn::passed) out.passed_columns.push_back(header);
  }
  require_columns(columns, source);
  while (std::optional<DesignRows::Row> row = read_row(reader, columns, out.passed_columns.size())) out.rows.push_back(std::move(*row));
  return out;
}

}  // namespace trebuchet
