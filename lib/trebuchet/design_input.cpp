#include "trebuchet/design_input.hpp"

#include <cmath>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/units.hpp"

namespace trebuchet {
namespace {

// How a key is named in messages: "--L4" on the command line (empty `where`), "design[2].L4" in a file.
std::string key_name(const std::string& where, const std::string& key) { return where.empty() ? "--" + key : where + "." + key; }

// A number in SI, or a string with a unit suffix.
std::optional<double> read_value(const nlohmann::json& object, const std::string& key, UnitDimension dimension,
                                 const std::string& where) {
  if (!object.contains(key) || object[key].is_null()) return std::nullopt;
  const nlohmann::json& value = object[key];
  const std::string name = key_name(where, key);
  if (value.is_number()) {
    const double number = value.get<double>();
    if (!std::isfinite(number)) throw Error(ErrorKind::bad_number, name + ": " + value.dump() + " is not a finite number");
    return number;
  }
  if (value.is_string()) return parse_value(value.get<std::string>(), dimension, name);
  throw Error(ErrorKind::bad_number, name + ": " + value.dump() + " is neither a number nor a value with a unit like \"6.13m\"");
}

double require_value(const nlohmann::json& object, const std::string& key, UnitDimension dimension,
                     const std::string& where, const std::string& hint) {
  const auto value = read_value(object, key, dimension, where);
  if (!value)
    throw Error(ErrorKind::usage, (where.empty() ? "--" + key + " is missing" : where + ": key \"" + key + "\" is missing") + "; give " + hint);
  return *value;
}

}  // namespace

void check_engine(const Engine& e, const std::string& where) {
  auto positive = [&](double value, const char* key, const char* what) {
    if (!(value > 0))
      throw Error(ErrorKind::bad_number, key_name(where, key) + " = " + format_significant(value, 6) + ": the " + what +
                                             " must be positive");
  };
  positive(e.L1, "L1", "long beam section");
  positive(e.L2, "L2", "short beam section");
  positive(e.L3, "L3", "counterweight arm (hinge to counterweight centre)");
  positive(e.L4, "L4", "sling length");
  positive(e.M, "M", "counterweight mass");
  positive(e.m, "m", "projectile mass");
  if (!(e.mb >= 0)) throw Error(ErrorKind::bad_number, key_name(where, "mb") + " = " + format_significant(e.mb, 6) + ": the beam mass must not be negative");
  if (!(e.theta_i_deg > 0 && e.theta_i_deg < 90))
    throw Error(ErrorKind::bad_number, key_name(where, where.empty() ? "theta" : "theta_i_deg") + " = " + format_significant(e.theta_i_deg, 6) +
                                           ": the initial beam angle must lie between 0 and 90 degrees");
}

DesignInput design_from_json(const nlohmann::json& object, const std::string& where) {
  if (!object.is_object())
    throw Error(ErrorKind::usage, (where.empty() ? std::string("input") : where) + ": expected a JSON object with keys L1, L2, L3 (or F), L4, M, m, mb, theta_i_deg");
  DesignInput in;
  Engine& e = in.engine;
  e.L1 = require_value(object, "L1", UnitDimension::length, where, "the long beam section, e.g. \"L1\": \"6.13m\"");
  e.L2 = require_value(object, "L2", UnitDimension::length, where, "the short beam section, e.g. \"L2\": \"1.08m\"");
  e.L4 = require_value(object, "L4", UnitDimension::length, where, "the sling length, e.g. \"L4\": \"5.80m\"");
  e.M = require_value(object, "M", UnitDimension::mass, where, "the counterweight mass, e.g. \"M\": \"14.3t\"");
  e.m = require_value(object, "m", UnitDimension::mass, where, "the projectile mass, e.g. \"m\": \"100kg\"");
  e.mb = require_value(object, "mb", UnitDimension::mass, where, "the beam mass, e.g. \"mb\": \"660kg\"");
  e.theta_i_deg = read_value(object, "theta_i_deg", UnitDimension::angle, where).value_or(30);
  e.D = read_value(object, "D", UnitDimension::length, where).value_or(0);
  if (const auto L3 = read_value(object, "L3", UnitDimension::length, where)) {
    e.L3 = *L3;
  } else if (const auto F = read_value(object, "F", UnitDimension::dimensionless, where)) {
    e.L3 = counterweight_arm(e.L1, e.L2, e.theta_i_deg, *F);
  } else {
    throw Error(ErrorKind::usage, (where.empty() ? std::string("flags") : where) +
                                      ": give the counterweight arm L3 in metres, or the fraction F = (L2 + L3)/H, e.g. F = 2/3");
  }
  check_engine(e, where);
  in.g = read_value(object, "g", UnitDimension::acceleration, where);
  if (in.g && !(*in.g > 0)) throw Error(ErrorKind::bad_number, key_name(where, "g") + " must be positive");
  in.R = read_value(object, "R", UnitDimension::length, where);
  in.T = read_value(object, "T", UnitDimension::energy, where);
  if (in.R.has_value() != in.T.has_value())
    throw Error(ErrorKind::usage, (where.empty() ? std::string("flags") : where) + ": a capacity needs both R and T; give both or neither");
  if (in.R && !(*in.R > 0 && *in.T > 0))
    throw Error(ErrorKind::bad_number, (where.empty() ? std::string("flags") : where) + ": R and T must be positive");
  return in;
}

}  // namespace trebuchet
