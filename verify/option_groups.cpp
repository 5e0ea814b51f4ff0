#include "option_groups.hpp"

#include <algorithm>
#include <cstdio>

#include "flags.hpp"
#include "program.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/records/table_json.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet::verify {
namespace {

// Where a value of a flag goes: a value of the design (--L1, --theta, ...) or a setting (--wind, ...).
struct Slot {
  std::optional<double> DesignValues::*value = nullptr;
  std::optional<double> SettingsValues::*setting = nullptr;
};
std::optional<double>& slot_in(Options& o, const Slot& slot) { return slot.value ? o.design.*slot.value : o.settings.*slot.setting; }

// A value with a unit into `slot`, read by `read`. With `spreads`, it may be a range or a spread
// (uncertainty.hpp): the slot then holds its first number, and the spread is kept for the Monte
// Carlo run.
CLI::Option* value_option(CLI::App* app, Options& o, const std::string& name, Slot slot, UnitDimension dimension, const std::string& help,
                          bool spreads, const std::function<void(const std::string&)>& read) {
  return parsed_option(
      app, name,
      [&o, name, slot, dimension, spreads, read](const std::string& text) {
        const auto spread = parse_spread(text, dimension, name);
        if (spread && !spreads)
          throw Error(ErrorKind::usage,
                      name + ": '" + text +
                          "' is a range or a spread; give one value (ranges and spreads are for the "
                          "engine's values, --theta, --psi-i, --target-level and the air, in shot and complete)");
        if (!spread) return read(text);
        slot_in(o, slot) = spread->a;
        add_spread(o.spreads, {{name, dimension, *spread}, slot.value, slot.setting});
      },
      help);
}

// A value with a unit that must be positive, into `target`.
void positive_setting(CLI::App* app, const SettingRow& row, std::optional<double>& target) {
  parsed_option(
      app, row.flag, [&target, &row](const std::string& text) { target = parse_positive(text, row.dimension, row.flag); }, setting_help(row));
}

// --format: table or json, and csv where the operation writes rows (shot, fit, compare, sweep).
void format_option(CLI::App* app, Options& o, const std::string& flag, const std::string& help, Door door) {
  const bool csv_too = door & (cmd_shot | cmd_fit | cmd_compare | cmd_sweep);
  parsed_option(
      app, flag,
      [&o, csv_too](const std::string& text) {
        if (text == "table")
          o.format = Format::table;
        else if (text == "json")
          o.format = Format::json;
        else if (text == "csv" && csv_too)
          o.format = Format::csv;
        else
          throw Error(ErrorKind::usage, "--format: '" + text + "' is not a format; use table" + (csv_too ? ", json or csv" : " or json"));
      },
      help);
}

// --machine: one machine, or contest's "all" (each machine's best).
void machine_option(CLI::App* app, Options& o, const std::string& flag, const std::string& help) {
  parsed_option(
      app, flag,
      [&o](const std::string& text) {
        o.all_machines = text == "all";  // contest's: each machine's best
        if (!o.all_machines) o.design.machine = parse_machine(text, "--machine");
      },
      help);
}

// --measured: a range with its uncertainty (34.4m±1.5m), or a range alone.
void measured_option(CLI::App* app, Options& o, const std::string& flag, const std::string& help) {
  parsed_option(
      app, flag,
      [&o](const std::string& text) {
        if (const auto spread = parse_spread(text, UnitDimension::length, "--measured")) {
          if (spread->kind != Spread::Kind::normal)
            throw Error(ErrorKind::usage, "--measured: '" + text + "' is a range; give the measured range with its uncertainty, e.g. 34.4m±1.5m");
          o.measured = MeasuredRange{spread->a, spread->b};
        } else {
          o.measured = MeasuredRange{parse_positive(text, UnitDimension::length, "--measured"), 0};
        }
      },
      help);
}

// --plausible-friction: the coefficients as a range low..high.
void plausible_friction_option(CLI::App* app, Options& o, const std::string& flag, const std::string& help) {
  parsed_option(
      app, flag,
      [&o, flag](const std::string& text) {
        const auto spread = parse_spread(text, UnitDimension::dimensionless, flag);
        if (!spread || spread->kind != Spread::Kind::uniform)
          throw Error(ErrorKind::usage, flag + ": '" + text + "' is not a range; give the plausible coefficients as low..high, e.g. 0.1..0.5");
        o.plausible_friction = {spread->a, spread->b};
      },
      help);
}

// --predict-m, --predict-M: every value given, each read and checked (CLI11 hands a std::string
// option its first only).
void mass_list_option(CLI::App* app, std::vector<double>& list, const std::string& flag, const std::string& help) {
  app->add_option_function<std::vector<std::string>>(
         flag,
         [list = &list, flag](const std::vector<std::string>& texts) {
           for (const std::string& text : texts) {
             if (text.empty()) throw Error(ErrorKind::usage, flag + " was given an empty value; give a value after it, or leave it out");
             list->push_back(parse_positive(text, UnitDimension::mass, flag));
           }
         },
         help)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

// --objective: range or eps.
void objective_option(CLI::App* app, Options& o, const std::string& flag, const std::string& help) {
  parsed_option(
      app, flag, [&o](const std::string& text) { o.efficiency = parse_efficiency_objective(text, "--objective"); }, help);
}

// --X: from:to:step.
void X_option(CLI::App* app, Options& o, const std::string& flag, const std::string& help) {
  parsed_option(
      app, flag,
      [&o](const std::string& text) {
        char c1 = 0, c2 = 0, rest = 0;
        if (std::sscanf(text.c_str(), "%lf%c%lf%c%lf%c", &o.sweep.X_from, &c1, &o.sweep.X_to, &c2, &o.sweep.X_step, &rest) != 5 || c1 != ':' ||
            c2 != ':')
          throw Error(ErrorKind::usage, "--X: '" + text + "' is not from:to:step; e.g. --X -0.55:0.55:0.05");
      },
      help);
}

// The option of a setting that only the programs take (read_by_table is false), read here.
void program_setting(CLI::App* app, Options& o, const SettingRow& row, Door door) {
  const std::string flag = row.flag, help = setting_help(row);
  const auto whole = [&](auto& target, auto lowest, auto highest) { integer_option(app, flag, target, lowest, highest, row.range, help); };
  switch (row.id) {
    case Setting::format: format_option(app, o, flag, help, door); return;
    case Setting::units:
      parsed_option(
          app, flag, [&o](const std::string& text) { o.units = parse_unit_system(text, "--units"); }, help);
      return;
    case Setting::digits:
      parsed_option(
          app, flag, [&o](const std::string& text) { o.digits = parse_digits(text, "--digits"); }, help);
      return;
    case Setting::threads: whole(o.threads, 1, 1 << 16); return;
    case Setting::series: app->add_option(flag, o.series, help); return;
    case Setting::series_dt:
      parsed_option(
          app, flag, [&o](const std::string& text) { o.series_dt_s = parse_positive(text, UnitDimension::time, "--series-dt"); }, help);
      return;
    case Setting::plot: app->add_option(flag, o.plot, help); return;
    case Setting::draws: app->add_option(flag, o.draws, help); return;
    case Setting::machine: machine_option(app, o, flag, help); return;
    case Setting::measured: measured_option(app, o, flag, help); return;
    case Setting::plausible_friction: plausible_friction_option(app, o, flag, help); return;
    case Setting::predict_m: mass_list_option(app, o.predict_m, flag, help); return;
    case Setting::predict_M: mass_list_option(app, o.predict_M, flag, help); return;
    case Setting::max_width: positive_setting(app, row, o.limits[0]); return;
    case Setting::max_height: positive_setting(app, row, o.limits[1]); return;
    case Setting::max_M: positive_setting(app, row, o.limits[2]); return;
    case Setting::max_axle_load: positive_setting(app, row, o.limits[3]); return;
    case Setting::max_acceleration: positive_setting(app, row, o.limits[4]); return;
    case Setting::mb_per_m: positive_setting(app, row, o.beam_per_m); return;
    case Setting::min_clearance:
      parsed_option(
          app, flag, [&o](const std::string& text) { o.min_clearance = parse_value(text, UnitDimension::length, "--min-clearance"); }, help);
      return;
    case Setting::objective: objective_option(app, o, flag, help); return;
    case Setting::pareto: whole(o.pareto, 2, 200); return;
    case Setting::vary:
      parsed_option(
          app, flag, [&o](const std::string& text) { o.what_if = parse_what_if(text, 21, "--vary"); }, help);
      return;
    case Setting::points: whole(o.what_if_points, 2, max_what_if_points); return;
    case Setting::X: X_option(app, o, flag, help); return;
    case Setting::shard:
      parsed_option(
          app, flag, [&o](const std::string& text) { o.shard = parse_shard(text); }, help);
      return;
    default: throw Error(ErrorKind::numerical, "internal error: " + flag + " has no reader");
  }
}

}  // namespace

void input_options(CLI::App* app, Options& o, unsigned operation, std::initializer_list<FieldGroup> groups, bool spreads) {
  for (const InputField& field : input_fields())
    if ((field.operations & operation) && std::find(groups.begin(), groups.end(), field.group) != groups.end()) {
      const std::string name = field.flag;
      const bool spread = spreads && field.group != FieldGroup::capacity;  // a capacity is never a spread
      value_option(app, o, name, Slot{field.member, nullptr}, field.dimension, option_help(field), spread,
                   [&o, name, member = field.member, dimension = field.dimension](const std::string& text) {
                     o.design.*member = parse_value(text, dimension, name);
                   });
    }
}

void material_options(CLI::App* app, Options& o, unsigned operation, bool beta2) {
  for (const InputField& field : input_fields())
    if (field.group == FieldGroup::material && (field.operations & operation) && (beta2 || field.member != &DesignValues::beta2))
      parsed_option(
          app, field.flag,
          [&o, name = std::string(field.flag), member = field.member, dimension = field.dimension](const std::string& text) {
            o.design.*member = parse_positive(text, dimension, name);
          },
          option_help(field));
}

void setting_options(CLI::App* app, Options& o, Door door, bool spreads) {
  for (const SettingRow& row : setting_rows()) {
    if (!(row.doors & door) || !*row.flag) continue;
    if (!read_by_table(row.id)) {
      program_setting(app, o, row, door);
      continue;
    }
    const std::string flag = row.flag;
    const auto read = [&o, id = row.id, flag](const std::string& text) { read_setting(id, text, o.settings, flag); };
    if (row.id == Setting::air || row.id == Setting::drag_in_sling)  // switches: --air, --air=false, --air=vacuum
      app->add_flag(flag)->description(setting_help(row))->each(read);
    else if (const auto slot = number_slot(row.id))
      value_option(app, o, flag, Slot{nullptr, slot}, row.dimension, setting_help(row), spreads, read);
    else
      parsed_option(app, flag, read, setting_help(row));
  }
}

}  // namespace trebuchet::verify
