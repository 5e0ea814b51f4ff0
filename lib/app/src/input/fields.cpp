#include "trebuchet/app/input/fields.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "trebuchet/error.hpp"

namespace trebuchet {

const std::vector<InputField>& input_fields() {
  using D = UnitDimension;
  using G = FieldGroup;
  static const std::vector<InputField> fields = {
#define TREBUCHET_INPUT(key, flag, dimension, unit, group, operations, label, help, example, fallback, range, material, ...) \
  {&DesignValues::key, #key, flag, {__VA_ARGS__}, D::dimension, unit, G::group, operations, label, help, example, fallback, range, material},
#include "trebuchet/app/input/inputs.def"
#undef TREBUCHET_INPUT
  };
  return fields;
}

const InputField& field_of(std::optional<double> DesignValues::*member) {
  // The rows by their member's place in DesignValues: a batch writes every engine's keys.
  constexpr std::size_t members = sizeof(DesignValues) / sizeof(std::optional<double>);
  static const DesignValues probe{};
  const auto place = [](std::optional<double> DesignValues::*m) {
    return static_cast<std::size_t>(reinterpret_cast<const char*>(&(probe.*m)) - reinterpret_cast<const char*>(&probe)) /
        sizeof(std::optional<double>);
  };
  static const std::array<const InputField*, members> rows = [&] {
    std::array<const InputField*, members> out{};
    for (const InputField& field : input_fields()) out[place(field.member)] = &field;
    return out;
  }();
  const InputField* row = rows[place(member)];
  if (!row) throw Error(ErrorKind::numerical, "internal error: a member of DesignValues has no row in input_fields()");
  return *row;
}

const InputField& release_field(ReleaseBy by) {
  switch (by) {
    case ReleaseBy::velocity_angle: return field_of(&DesignValues::release_angle_deg);
    case ReleaseBy::pin_angle: return field_of(&DesignValues::pin_angle_deg);
    case ReleaseBy::time: break;
  }
  return field_of(&DesignValues::release_time);
}

const InputField* find_field(std::string_view name) {
  for (const InputField& field : input_fields()) {
    if (name == field.key) return &field;
    for (const char* alias : field.aliases)
      if (name == alias) return &field;
  }
  return nullptr;
}

std::string option_help(const InputField& field) {
  std::string help = field.help;
  if (*field.fallback) help += std::string(" (default ") + field.fallback + ")";
  if (field.dimension != UnitDimension::dimensionless && field.dimension != UnitDimension::angle) help += " [" + unit_list(field.dimension) + "]";
  if (field.dimension == UnitDimension::angle) help += " [deg]";
  return help;
}

std::vector<const char*> names_of(const InputField& field) {
  std::vector<const char*> names{field.key};
  names.insert(names.end(), field.aliases.begin(), field.aliases.end());
  return names;
}

Material material_of(const DesignValues& values, Material base) {
  for (const InputField& field : input_fields())
    if (field.material && values.*field.member) base.*field.material = *(values.*field.member);
  return base;
}

std::string csv_column_of(const InputField& field) { return *field.unit ? std::string(field.key) + "_" + field.unit : field.key; }

std::size_t edit_distance(std::string_view a, std::string_view b) {
  auto same = [](char x, char y) { return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y)); };
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
      if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1])) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

bool near_name(std::string_view word, std::string_view name) {
  const std::size_t allowed = name.size() <= 2 ? 0 : name.size() <= 4 ? 1 : 2;
  return edit_distance(word, name) <= allowed;
}

namespace {

// A name as a hand may vary it: without blanks, underscores and hyphens, in lower case ("L_4 ",
// "l4" and "L-4" are all "l4").
std::string plain(std::string_view name) {
  std::string out;
  for (char c : name)
    if (c != ' ' && c != '_' && c != '-' && c != '\t') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Whether `rest` is a unit: "ft", "kg", "m_s2" (a CSV column's "m/s2"), or, for an angle,
// a word for degrees ("deg", "degree", "degrees").
bool unit_words(std::string_view rest, UnitDimension dimension) {
  std::string unit(rest);
  std::replace(unit.begin(), unit.end(), '_', '/');
  return is_unit_word(unit) || (dimension == UnitDimension::angle && unit.rfind("deg", 0) == 0);
}

}  // namespace

bool unit_column_of(std::string_view name, const InputField& field) {
  const std::string_view key = field.key;
  return name.size() > key.size() + 1 && name.substr(0, key.size()) == key && name[key.size()] == '_' &&
      unit_words(name.substr(key.size() + 1), field.dimension);
}

std::string near_miss(std::string_view word, const std::vector<std::string>& known) {
  // An input's name as a hand varies it ("L_4", "L4 ", "m_b"), with its unit left off ("theta_i"
  // for theta_i_deg), or with a unit put on ("L4_ft", "M_kg", "L4m", "theta_degrees").
  for (const InputField& field : input_fields()) {
    if (std::find(known.begin(), known.end(), field.key) == known.end()) continue;  // not this reader's
    const std::string_view key = field.key;
    const std::string_view stem = field.dimension == UnitDimension::angle ? key.substr(0, key.rfind("_deg")) : key;
    std::vector<std::string_view> names{key, stem};
    for (const char* alias : field.aliases) names.emplace_back(alias);
    for (std::string_view name : names) {
      if (word != key && plain(word) == plain(name)) return field.key;
      for (const std::size_t gap : {std::size_t{0}, std::size_t{1}}) {  // "L4m", "L4_m", "r_m"
        if (word.size() <= name.size() + gap || plain(word.substr(0, name.size())) != plain(name) || (gap && word[name.size()] != '_')) continue;
        if (unit_words(word.substr(name.size() + gap), field.dimension)) return field.key;
      }
    }
  }
  std::string best;
  std::size_t best_distance = 0;
  for (const std::string& name : known) {
    const std::size_t distance = edit_distance(word, name);
    if (near_name(word, name) && name != word && (best.empty() || distance < best_distance)) best = name, best_distance = distance;
  }
  return best;
}

const char* dimension_name(UnitDimension dimension) {
  switch (dimension) {
    case UnitDimension::length: return "length";
    case UnitDimension::mass: return "mass";
    case UnitDimension::energy: return "energy";
    case UnitDimension::dimensionless: return "dimensionless";
    case UnitDimension::angle: return "angle";
    case UnitDimension::acceleration: return "acceleration";
    case UnitDimension::pressure: return "pressure";
    case UnitDimension::density: return "density";
    case UnitDimension::time: return "time";
    case UnitDimension::speed: return "speed";
    case UnitDimension::force: return "force";
    case UnitDimension::moment: return "moment";
    case UnitDimension::inertia: return "inertia";
  }
  return "dimensionless";
}

std::vector<std::string> input_names(unsigned operations) {
  std::vector<std::string> names;
  for (const InputField& field : input_fields()) {
    if (!(field.operations & operations)) continue;
    names.emplace_back(field.key);
    for (const char* alias : field.aliases) names.emplace_back(alias);
  }
  return names;
}

}  // namespace trebuchet
