#include "api_input.hpp"

#include <algorithm>

#include "trebuchet/format.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/input/text_input.hpp"

namespace trebuchet::api {

using json = nlohmann::json;

std::optional<double> positive_value(const json& request, const std::string& key, UnitDimension dimension, bool zero_allowed) {
  const auto value = read_value(request, key, dimension, "");
  if (value && !(zero_allowed ? *value >= 0 : *value > 0))
    throw Error(ErrorKind::bad_number,
                "{{" + key + "}} = " + format_significant(*value, 6) + " must be " + (zero_allowed ? "0 or more" : "positive") + "; give a value " +
                    (zero_allowed ? ">= 0" : "> 0"));
  return value;
}

void require_keys(const json& request, const std::vector<std::string>& known, const std::string& what) {
  if (!request.is_object()) throw Error(ErrorKind::usage, what + ": expected a JSON object, got " + brief_json(request));
  for (const auto& [key, value] : request.items())
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      refuse_near_miss(key, known, what);
      throw Error(ErrorKind::usage, what + ": '" + key + "' is no key of this request; use " + join(known, ", "));
    }
}

std::vector<std::string> keys_of(unsigned door, unsigned material_operation) {
  std::vector<std::string> keys;
  for (const std::string& name : setting_names(door))
    if (name.find('.') == std::string::npos) keys.push_back(name);  // "air.density" is a key of "air"
  for (const InputField& field : input_fields())
    if (field.group == FieldGroup::material && (field.operations & material_operation))
      for (const char* name : names_of(field)) keys.emplace_back(name);
  return keys;
}

DesignValues over_of(const json& request, unsigned operation, std::vector<SpreadInput>* spreads, const std::function<double(const Spread&)>& at) {
  if (!request.contains("over")) return {};
  const json& over = request["over"];
  if (!over.is_object())
    throw Error(ErrorKind::usage, "{{over}}: " + brief_json(over) + " must be an object of the engine's inputs, e.g. {\"L4\": \"4.5m\"}");
  for (const auto& [key, value] : over.items()) {
    const InputField* field = find_field(key);
    if ((!field || !(field->operations & operation)) && key != machine_key)
      throw Error(ErrorKind::usage,
                  "over." + key + " is no input of the engine that this request takes (fields()); give a setting beside " +
                      "the design, an input of the engine in over");
  }
  if (!spreads && !at) {  // one shot's values: a range is refused, as in the design itself
    refuse_spreads(over, "over");
    return read_input_values(over, "over", operation);
  }
  std::vector<SpreadInput> completed_at;  // complete's: each range at `at`, not kept
  return read_input_values(take_spreads(over, operation, "over", spreads ? *spreads : completed_at, at), "over", operation);
}

std::string text_of(const json& value, const std::string& key) {
  if (!value.is_string()) throw Error(ErrorKind::usage, "{{" + key + "}}: " + brief_json(value) + " must be a string");
  return value.get<std::string>();
}

SettingsValues settings_values_of(const json& request, unsigned door) { return read_settings(request, door, ""); }

ShotSettings settings_of(const json& request, unsigned door) { return shot_settings(settings_values_of(request, door)); }

DesignValues material_of_request(const json& request, unsigned operation) {
  DesignValues v;
  for (const InputField& field : input_fields())
    if (field.group == FieldGroup::material && (field.operations & operation))
      for (const char* name : names_of(field))
        if (const auto value = positive_value(request, name, field.dimension)) {
          if (v.*field.member)
            throw Error(ErrorKind::usage, std::string("{{") + field.key + "}} and {{" + name + "}} are one value given twice; keep one");
          v.*field.member = value;
        }
  return v;
}

}  // namespace trebuchet::api
