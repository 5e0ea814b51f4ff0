#include "trebuchet/app/input/settings.hpp"

#include <algorithm>
#include <charconv>
#include <map>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/input/request.hpp"

namespace trebuchet {

const std::vector<SettingRow>& setting_rows() {
  using D = UnitDimension;
  static const std::vector<SettingRow> rows = {
#define TREBUCHET_SETTING(id, key, flag, dimension, doors, help, fallback, range, ...) \
  {Setting::id, key, flag, {__VA_ARGS__}, D::dimension, doors, help, fallback, range},
#include "trebuchet/app/input/settings.def"
#undef TREBUCHET_SETTING
  };
  return rows;
}

const SettingRow& setting_row(Setting id) { return setting_rows()[static_cast<std::size_t>(id)]; }

const SettingRow* find_setting(std::string_view name, unsigned doors) {
  for (const SettingRow& row : setting_rows()) {
    if (!(row.doors & doors) || !*row.key) continue;
    if (name == row.key) return &row;
    for (const char* alias : row.aliases)
      if (name == alias) return &row;
  }
  return nullptr;
}

std::string setting_help(const SettingRow& row) {
  std::string help = row.help;
  if (*row.fallback) help += std::string(" (default ") + row.fallback + ")";
  if (row.dimension != UnitDimension::dimensionless) help += " [" + unit_list(row.dimension) + "]";
  return help;
}

std::vector<std::string> setting_names(unsigned doors) {
  std::vector<std::string> names;
  for (const SettingRow& row : setting_rows()) {
    if (!(row.doors & doors) || !*row.key) continue;
    names.emplace_back(row.key);
    names.insert(names.end(), row.aliases.begin(), row.aliases.end());
  }
  return names;
}

ShotSettings shot_settings(const SettingsValues& v) {
  ShotSettings settings;
  settings.criterion.release = v.quality.value_or(settings.criterion.release);
  settings.criterion.n = v.n.value_or(settings.criterion.n);
  settings.integrator.stepper = v.stepper.value_or(settings.integrator.stepper);
  settings.integrator.rtol = v.rtol.value_or(settings.integrator.rtol);
  settings.integrator.atol = v.atol.value_or(settings.integrator.atol);
  settings.range_from_release = v.range_from_release.value_or(false);
  settings.target_level = v.target_level.value_or(0);
  const bool air_details = v.air_density || v.cd || v.cd_of_reynolds || v.projectile || v.wind;
  if (air_details && !v.air)
    throw Error(ErrorKind::usage,
                "{{air_density}}, {{cd}}, {{projectile}} and {{wind}} describe the air; add {{air}} to fly through it (vacuum is the default)");
  if (v.drag_in_sling.value_or(false) && !v.air)
    throw Error(ErrorKind::usage, "{{drag_in_sling}} lets the air act before the release; add {{air}} (vacuum is the default)");
  settings.drag_in_sling = v.drag_in_sling.value_or(false);
  if (v.air) {
    Air air;
    if (v.air_density && !(*v.air_density > 0))
      throw Error(ErrorKind::bad_number, "{{air_density}}: " + format_significant(*v.air_density, 6) + " kg/m3 must be positive");
    air.density = v.air_density.value_or(air.density);
    if (v.cd_of_reynolds)
      air.drag_coefficient.reset();
    else if (v.cd)
      air.drag_coefficient = v.cd;
    air.projectile_density = v.projectile.value_or(air.projectile_density);
    air.wind = v.wind.value_or(0);
    settings.air = air;
  }
  check_shot_settings(settings);
  return settings;
}

ShotSettings shot_settings_over_designs(SettingsValues v) {
  // A detail of the air alone may change a design's own air (a record's, check_design): it is
  // refused there, laid over a design in vacuum.
  if (!v.vacuum) v.air = v.air || v.drag_in_sling.value_or(false) || v.air_density || v.cd || v.cd_of_reynolds || v.projectile || v.wind;
  return shot_settings(v);
}

std::optional<double> SettingsValues::*number_slot(Setting id) {
  switch (id) {
    case Setting::target_level: return &SettingsValues::target_level;
    case Setting::wind: return &SettingsValues::wind;
    case Setting::air_density: return &SettingsValues::air_density;
    case Setting::cd: return &SettingsValues::cd;
    default: return nullptr;
  }
}

namespace {

// A whole number from `lowest` to `highest`, read as written ("10000"); the message names the
// setting and its row's range.
template <class Integer>
Integer whole_number(std::string_view text, std::string_view name, Integer lowest, Integer highest, const char* range) {
  Integer value{};
  const bool negative = !text.empty() && text.front() == '-';
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if ((negative && lowest >= 0) || (ec == std::errc() && end == text.data() + text.size() && (value < lowest || value > highest)) ||
      ec == std::errc::result_out_of_range)
    throw Error(ErrorKind::usage, std::string(name) + ": " + std::string(text) + " must be " + range);
  if (ec != std::errc() || end != text.data() + text.size())
    throw Error(ErrorKind::usage, std::string(name) + ": '" + std::string(text) + "' is not a whole number; give " + range);
  return value;
}

// A switch's value: a flag given, or a request's true or false.
bool switch_value(std::string_view text, std::string_view name) {
  if (text == "true") return true;
  if (text == "false") return false;
  throw Error(ErrorKind::usage,
              std::string(name) + ": '" + std::string(text) +
                  "' is neither true nor false; give true or false (on the command line: the flag alone, or =false)");
}

// Each setting a request takes as the programs' flag does, read from its text into its member.
using Reader = void (*)(SettingsValues&, std::string_view text, std::string_view name);
const std::map<Setting, Reader>& readers() {
  using D = UnitDimension;
  using V = SettingsValues;
  using T = std::string_view;
  static const std::map<Setting, Reader> all = {
      {Setting::quality, [](V& v, T text, T name) { v.quality = parse_release(text, name); }},
      {Setting::n,
       [](V& v, T text, T name) {
         v.n = parse_value(text, D::dimensionless, name);
         if (!(*v.n >= 0)) throw Error(ErrorKind::bad_number, std::string(name) + ": '" + std::string(text) + "' must be 0 or more (eq:Q_n)");
       }},
      {Setting::tol, [](V& v, T text, T name) { v.tol = parse_positive(text, D::dimensionless, name); }},
      {Setting::stepper, [](V& v, T text, T name) { v.stepper = parse_stepper(text, name); }},
      {Setting::rtol, [](V& v, T text, T name) { v.rtol = parse_positive(text, D::dimensionless, name); }},
      {Setting::atol, [](V& v, T text, T name) { v.atol = parse_positive(text, D::dimensionless, name); }},
      {Setting::target_level, [](V& v, T text, T name) { v.target_level = parse_value(text, D::length, name); }},
      {Setting::range_from, [](V& v, T text, T name) { v.range_from_release = parse_range_from(text, name); }},
      {Setting::air,
       [](V& v, T text, T name) {
         v.air = text != "vacuum" && switch_value(text, name);
         v.vacuum = !v.air;
       }},
      {Setting::drag_in_sling, [](V& v, T text, T name) { v.drag_in_sling = switch_value(text, name); }},
      {Setting::air_density, [](V& v, T text, T name) { v.air_density = parse_positive(text, D::density, name); }},
      {Setting::cd,
       [](V& v, T text, T name) {
         if (text == "Re" || text == "Cd(Re)") {
           v.cd_of_reynolds = true;
           return;
         }
         if (text.find_first_of("0123456789") == std::string_view::npos)
           throw Error(ErrorKind::usage,
                       std::string(name) + ": '" + std::string(text) + "' is not a drag coefficient; give a number, e.g. 0.47, or Re for Cd(Re)");
         v.cd = parse_positive(text, D::dimensionless, name);
       }},
      {Setting::projectile, [](V& v, T text, T name) { v.projectile = parse_projectile_density(text, name); }},
      {Setting::wind, [](V& v, T text, T name) { v.wind = parse_value(text, D::speed, name); }},
      {Setting::samples,
       [](V& v, T text, T name) {
         v.samples = whole_number<int>(text, name, 1, static_cast<int>(max_run_shots), setting_row(Setting::samples).range);
       }},
      {Setting::seed,
       [](V& v, T text, T name) { v.seed = whole_number<std::uint64_t>(text, name, 0, UINT64_MAX, setting_row(Setting::seed).range); }},
      {Setting::claim,
       [](V& v, T text, T name) {
         v.claim = parse_positive(text, D::length, name);
         check_ordinary(*v.claim, 1e-6, 1e6, "claim", "m", "claimed range");
       }},
  };
  return all;
}

}  // namespace

bool read_by_table(Setting id) { return readers().count(id) > 0; }

void read_setting(Setting id, std::string_view text, SettingsValues& values, std::string_view name) {
  const auto reader = readers().find(id);
  if (reader == readers().end())
    throw Error(ErrorKind::numerical, "internal error: the setting " + std::string(setting_row(id).key) + " has no reader");
  reader->second(values, text, name);
}

}  // namespace trebuchet
