#include "trebuchet/app/input/units.hpp"

#include <array>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include <fast_float/fast_float.h>
#include <fmt/format.h>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {
namespace {

struct Unit {
  std::string_view suffix;
  UnitDimension dimension;
  double to_si;  // multiply by this to get SI base units (degrees for angles)
};

// The imperial units are those of the international yard and pound (1959): the foot is
// 0.3048 m and the pound 0.45359237 kg exactly; the pound-force is a pound under standard
// gravity, 9.80665 m/s^2. tests/test_units.cpp checks every factor against GNU units.
constexpr double foot = 0.3048, pound = 0.45359237, pound_force = pound * 9.80665;
constexpr std::array<Unit, 49> units = {{
    {"m", UnitDimension::length, 1.0},
    {"cm", UnitDimension::length, 1e-2},
    {"mm", UnitDimension::length, 1e-3},
    {"km", UnitDimension::length, 1e3},
    {"ft", UnitDimension::length, foot},
    {"in", UnitDimension::length, foot / 12},
    {"yd", UnitDimension::length, 3 * foot},
    {"mi", UnitDimension::length, 5280 * foot},
    {"kg", UnitDimension::mass, 1.0},
    {"g", UnitDimension::mass, 1e-3},
    {"t", UnitDimension::mass, 1e3},
    {"tonne", UnitDimension::mass, 1e3},
    {"tonnes", UnitDimension::mass, 1e3},
    {"lb", UnitDimension::mass, pound},
    {"lbs", UnitDimension::mass, pound},
    {"oz", UnitDimension::mass, pound / 16},
    {"J", UnitDimension::energy, 1.0},
    {"kJ", UnitDimension::energy, 1e3},
    {"MJ", UnitDimension::energy, 1e6},
    {"ft*lbf", UnitDimension::energy, foot* pound_force},
    {"ftlbf", UnitDimension::energy, foot* pound_force},
    {"deg", UnitDimension::angle, 1.0},
    {"m/s2", UnitDimension::acceleration, 1.0},
    {"m/s^2", UnitDimension::acceleration, 1.0},
    {"ft/s2", UnitDimension::acceleration, foot},
    {"Pa", UnitDimension::pressure, 1.0},
    {"kPa", UnitDimension::pressure, 1e3},
    {"MPa", UnitDimension::pressure, 1e6},
    {"GPa", UnitDimension::pressure, 1e9},
    {"psi", UnitDimension::pressure, pound_force / (foot / 12 * foot / 12)},
    {"kg/m3", UnitDimension::density, 1.0},
    {"kg/m^3", UnitDimension::density, 1.0},
    {"t/m3", UnitDimension::density, 1e3},
    {"g/cm3", UnitDimension::density, 1e3},  // the school unit: water is 1 g/cm3
    {"lb/ft3", UnitDimension::density, pound / (foot * foot * foot)},
    {"%", UnitDimension::dimensionless, 1e-2},
    {"s", UnitDimension::time, 1.0},
    {"ms", UnitDimension::time, 1e-3},
    {"m/s", UnitDimension::speed, 1.0},
    {"km/h", UnitDimension::speed, 1 / 3.6},
    {"ft/s", UnitDimension::speed, foot},
    {"mph", UnitDimension::speed, 5280 * foot / 3600},
    {"N", UnitDimension::force, 1.0},
    {"kN", UnitDimension::force, 1e3},
    {"lbf", UnitDimension::force, pound_force},
    {"N*m", UnitDimension::moment, 1.0},
    {"kg*m2", UnitDimension::inertia, 1.0},
    {"kg*m^2", UnitDimension::inertia, 1.0},
    {"lb*ft2", UnitDimension::inertia, pound* foot* foot},
}};

// How messages speak of each dimension.
struct DimensionText {
  std::string_view word;  // "a length"
  std::string_view bare;  // unit of a bare number: "metres"
  std::string_view example;  // a valid value: "150m"
};

DimensionText dimension_text(UnitDimension dimension) {
  switch (dimension) {
    case UnitDimension::length: return {"a length", "metres", "150m"};
    case UnitDimension::mass: return {"a mass", "kilograms", "50kg"};
    case UnitDimension::energy: return {"an energy", "joules", "40kJ"};
    case UnitDimension::dimensionless: return {"a pure number", "a plain number", "2/3"};
    case UnitDimension::angle: return {"an angle", "degrees", "30deg"};
    case UnitDimension::acceleration: return {"an acceleration", "m/s^2", "9.81m/s2"};
    case UnitDimension::pressure: return {"a pressure", "pascals", "12GPa"};
    case UnitDimension::density: return {"a density", "kg/m^3", "700kg/m3"};
    case UnitDimension::time: return {"a time", "seconds", "5ms"};
    case UnitDimension::speed: return {"a speed", "m/s", "5m/s"};
    case UnitDimension::force: return {"a force", "newtons", "30kN"};
    case UnitDimension::moment: return {"a moment", "N m", "300N*m"};
    case UnitDimension::inertia: return {"a moment of inertia", "kg m^2", "45kg*m2"};
  }
  return {"?", "?", "?"};
}

// A value as a message quotes it; a long one by its ends, so that a message stays a line.
// Cut only between UTF-8 characters, never inside one.
std::string quoted(std::string_view text) {
  if (text.size() <= 80) return "'" + std::string(text) + "'";
  auto boundary = [&](std::size_t at) {
    while (at > 0 && at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) --at;
    return at;
  };
  const std::size_t head = boundary(40), tail = boundary(text.size() - 20);
  return "'" + std::string(text.substr(0, head)) + "…" + std::string(text.substr(tail)) + "' (" + std::to_string(text.size()) + " bytes)";
}

// Parses the longest leading number of `text`; returns the number of characters used (0: none).
// A number beyond the range of a double is reported as such, naming `what`.
std::size_t parse_number_prefix(std::string_view text, double& value, const std::string& what) {
  const char* first = text.data();
  const char* last = first + text.size();
  if (first != last && *first == '+') ++first;  // from_chars rejects a leading '+'
  // fast_float: std::from_chars's correctly rounded parse, also where a standard library lacks
  // it for doubles (Emscripten's, for the browser page).
  auto [end, ec] = fast_float::from_chars(first, last, value, fast_float::chars_format::general);
  if (ec != std::errc()) return 0;
  // fast_float rounds digits beyond the doubles to infinity or zero where std::from_chars
  // reports them ("inf" and "nan" are words, not digits, and pass as from_chars passes them).
  const std::string_view mantissa(first, static_cast<std::size_t>(std::find_if(first, end, [](char c) { return c == 'e' || c == 'E'; }) - first));
  const bool overflow = std::isinf(value) && mantissa.find_first_of("0123456789") != std::string_view::npos;
  const bool underflow = value == 0 && mantissa.find_first_of("123456789") != std::string_view::npos;
  if (overflow || underflow)
    throw Error(ErrorKind::bad_number, what + " is beyond the range of numbers (about 1e-308 to 1e308); give a value of ordinary size");
  return static_cast<std::size_t>(end - text.data());
}

// `text` without the blanks it starts with: spaces, tabs, U+00A0 and U+202F.
std::string_view skip_blanks(std::string_view text) {
  while (true) {
    if (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
      text.remove_prefix(1);
    else if (text.rfind("\u00a0", 0) == 0)
      text.remove_prefix(2);
    else if (text.rfind("\u202f", 0) == 0)
      text.remove_prefix(3);
    else
      return text;
  }
}

// The number `text` starts with, a fraction a/b included ("2/3"), and how many characters it
// takes (0: none). A '/' takes the number after it when there is one; the fraction is
// malformed when there is none, or it is 0.
struct LeadingNumber {
  double value = 0;
  std::size_t length = 0;
  bool malformed_fraction = false;
};
LeadingNumber leading_number(std::string_view text, const std::string& what) {
  LeadingNumber n;
  n.length = parse_number_prefix(text, n.value, what);
  if (n.length == 0 || n.length >= text.size() || text[n.length] != '/') return n;
  double denominator = 0;
  const std::size_t more = parse_number_prefix(text.substr(n.length + 1), denominator, what);
  n.malformed_fraction = more == 0 || denominator == 0;
  if (more > 0) n.value /= denominator, n.length += 1 + more;
  return n;
}

// Whether `text` is a finite number and nothing else (blanks around it aside): "4", "2/3".
bool bare_number(std::string_view text) {
  text = skip_blanks(text);
  try {
    const LeadingNumber n = leading_number(text, "");
    return n.length > 0 && !n.malformed_fraction && std::isfinite(n.value) && skip_blanks(text.substr(n.length)).empty();
  } catch (const Error&) {
    return false;
  }
}

// The unit written after the number of `text` ("t" of "4t", "" of "4" or "2/3"); "" when the text is not a number.
std::string unit_of(std::string_view text, std::string_view name) {
  const LeadingNumber n = leading_number(text, std::string(name));
  return n.length == 0 ? "" : std::string(skip_blanks(text.substr(n.length)));
}

}  // namespace

UnitDimension unit_dimension(Dimension dimension) {
  switch (dimension) {
    case Dimension::length: return UnitDimension::length;
    case Dimension::mass: return UnitDimension::mass;
    case Dimension::energy: return UnitDimension::energy;
    case Dimension::dimensionless: return UnitDimension::dimensionless;
  }
  return UnitDimension::dimensionless;
}

std::string unit_list(UnitDimension dimension) {
  std::string list;
  for (const Unit& unit : units) {
    if (unit.dimension != dimension) continue;
    if (!list.empty()) list += ", ";
    list += unit.suffix;
  }
  return list.empty() ? "no suffix" : list;
}

double parse_value(std::string_view text, UnitDimension dimension, std::string_view name) {
  const std::string fix = "write a number with an optional unit, e.g. " + std::string(dimension_text(dimension).example);
  const std::string what = std::string(name) + ": " + quoted(text);

  const LeadingNumber number = leading_number(text, what);  // a fraction a/b too, e.g. 2/3 or 1/300
  if (number.length == 0) throw Error(ErrorKind::bad_number, what + " is not a number; " + fix);
  if (number.malformed_fraction) throw Error(ErrorKind::bad_number, what + " is not a valid fraction; " + fix);
  const double value = number.value;
  std::string_view rest = text.substr(number.length);
  if (!std::isfinite(value)) throw Error(ErrorKind::bad_number, what + " is not a finite number; " + fix);

  if (rest.empty()) return value;
  if (text.find("..") != std::string_view::npos || text.find("\u00b1") != std::string_view::npos || text.find("+-") != std::string_view::npos)
    throw Error(ErrorKind::bad_number, what + " is a range or a spread, and " + std::string(name) + " takes one value; " + fix);
  // "150 m" as spreadsheets and people write it: blanks between the number and its unit, the
  // no-break spaces of French and other locales (U+00A0, U+202F) too.
  rest = skip_blanks(rest);
  if (rest.empty()) return value;  // "150 "
  for (const Unit& unit : units) {
    if (unit.suffix != rest) continue;
    if (unit.dimension != dimension)
      throw Error(ErrorKind::unknown_unit,
                  what + " is " + std::string(dimension_text(unit.dimension).word) + ", but " + std::string(name) + " is " +
                      std::string(dimension_text(dimension).word) + "; use " + unit_list(dimension) + " or a bare number in " +
                      std::string(dimension_text(dimension).bare));
    const double si = value * unit.to_si;
    if (!std::isfinite(si) || (si == 0 && value != 0))
      throw Error(ErrorKind::bad_number, what + " is beyond the range of numbers in SI units (about 1e-308 to 1e308); give a value of ordinary size");
    return si;
  }
  throw Error(ErrorKind::unknown_unit,
              what + " has the unknown unit " + quoted(rest) + "; use " + unit_list(dimension) + " or a bare number in " +
                  std::string(dimension_text(dimension).bare));
}

double parse_positive(std::string_view text, UnitDimension dimension, std::string_view name) {
  double value = parse_value(text, dimension, name);
  if (!(value > 0)) throw Error(ErrorKind::bad_number, std::string(name) + ": " + quoted(text) + " must be positive; give a value > 0");
  return value;
}

std::optional<Spread> parse_spread(std::string_view text, UnitDimension dimension, std::string_view name) {
  const std::string what = std::string(name) + ": '" + std::string(text) + "'";
  // The two sides of a range or spread, each a value; a unit written at one side only is the
  // unit of both (3..4t is 3 t to 4 t, 3.5±0.2m is 3.5 m ± 0.2 m). A side's error quotes the whole text.
  const auto sides = [&](std::string_view separator, const char* form) {
    const auto at = text.find(separator);
    const auto trimmed = [](std::string_view side) {
      side = skip_blanks(side);
      while (!side.empty() && (side.back() == ' ' || side.back() == '\t')) side.remove_suffix(1);
      return std::string(side);
    };
    std::string first = trimmed(text.substr(0, at)), second = trimmed(text.substr(at + separator.size()));
    if (second.find(separator) != std::string::npos || text.find(separator == ".." ? "\u00b1" : "..") != std::string_view::npos)
      throw Error(ErrorKind::bad_number, what + " has more than one '..' or '±'; write " + form);
    if (first.empty() || second.empty()) throw Error(ErrorKind::bad_number, what + " lacks a side; write " + form);
    const std::string first_unit = unit_of(first, name), second_unit = unit_of(second, name);
    if (bare_number(first) && !second_unit.empty()) first += second_unit;
    if (bare_number(second) && !first_unit.empty()) second += first_unit;
    try {
      return std::pair{parse_value(first, dimension, name), parse_value(second, dimension, name)};
    } catch (const Error& e) {
      throw Error(e.kind(), std::string(e.named_message()) + " (in " + what + ")");
    }
  };
  if (text.find("..") != std::string_view::npos) {
    const auto [a, b] = sides("..", "low..high, e.g. 2.5t..3.5t");
    if (!(a < b)) throw Error(ErrorKind::bad_number, what + " is not a range from low to high; write it as low..high, e.g. 2.5t..3.5t");
    return Spread{Spread::Kind::uniform, a, b};
  }
  for (std::string_view sign : {std::string_view("\u00b1"), std::string_view("+-")}) {
    if (text.find(sign) == std::string_view::npos) continue;
    const auto [mean, deviation] = sides(sign, "mean±deviation, e.g. 3.5m±0.2m");
    if (!(deviation >= 0)) throw Error(ErrorKind::bad_number, what + " has a negative deviation; write mean±deviation, e.g. 3.5m±0.2m");
    return Spread{Spread::Kind::normal, mean, deviation};
  }
  return std::nullopt;
}

std::string spread_text(const Spread& spread, UnitDimension dimension) {
  std::string_view unit;  // the dimension's first SI suffix; none for a number
  for (const Unit& u : units)
    if (u.dimension == dimension && u.to_si == 1.0) {
      unit = u.suffix;
      break;
    }
  const auto side = [&](double x) { return format_number(x) + std::string(unit); };
  return side(spread.a) + (spread.kind == Spread::Kind::uniform ? ".." : "\u00b1") + side(spread.b);
}

std::vector<UnitFactor> unit_factors() {
  std::vector<UnitFactor> out;
  for (const Unit& unit : units) out.push_back({std::string(unit.suffix), unit.dimension, unit.to_si});
  return out;
}

bool is_unit_word(std::string_view text) {
  for (const Unit& unit : units)
    if (unit.suffix == text) return true;
  return false;
}

namespace {

// The unit a report prints a value in: its suffix and size in SI, chosen so that the number
// reads plainly (22.4 J, not 0.0224 kJ).
struct PrintUnit {
  const char* suffix;
  double to_si;
};

PrintUnit print_unit(double si, UnitDimension dimension, UnitSystem system) {
  const double size = std::abs(si);
  // SI: the largest of the dimension's units the value reaches 1 of (the smallest below them all).
  auto largest_reached = [&](std::initializer_list<PrintUnit> ladder) {
    PrintUnit chosen = *ladder.begin();
    for (const PrintUnit& unit : ladder)
      if (size >= unit.to_si) chosen = unit;
    return chosen;
  };
  if (system == UnitSystem::imperial) {
    switch (dimension) {
      case UnitDimension::length: return size < foot ? PrintUnit{"in", foot / 12} : PrintUnit{"ft", foot};
      case UnitDimension::mass: return size < pound ? PrintUnit{"oz", pound / 16} : PrintUnit{"lb", pound};
      case UnitDimension::energy:
      case UnitDimension::moment: return {"ft·lbf", foot * pound_force};
      case UnitDimension::force: return {"lbf", pound_force};
      case UnitDimension::pressure: return {"psi", pound_force / (foot / 12 * foot / 12)};
      case UnitDimension::speed: return {"ft/s", foot};
      case UnitDimension::density: return {"lb/ft3", pound / (foot * foot * foot)};
      case UnitDimension::acceleration: return {"ft/s2", foot};
      case UnitDimension::inertia: return {"lb·ft2", pound * foot * foot};
      default: break;
    }
  }
  switch (dimension) {
    case UnitDimension::length: return size >= 1e-2 ? PrintUnit{"m", 1} : PrintUnit{"mm", 1e-3};  // metres down to a centimetre
    case UnitDimension::mass: return largest_reached({{"g", 1e-3}, {"kg", 1}, {"t", 1e3}});
    case UnitDimension::energy: return largest_reached({{"J", 1}, {"kJ", 1e3}, {"MJ", 1e6}, {"GJ", 1e9}});
    case UnitDimension::force: return largest_reached({{"N", 1}, {"kN", 1e3}, {"MN", 1e6}});
    case UnitDimension::moment: return largest_reached({{"N m", 1}, {"kN m", 1e3}, {"MN m", 1e6}});
    case UnitDimension::pressure: return largest_reached({{"Pa", 1}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}});
    case UnitDimension::speed: return {"m/s", 1};
    case UnitDimension::density: return {"kg/m3", 1};
    case UnitDimension::acceleration: return {"m/s2", 1};
    case UnitDimension::time: return {"s", 1};
    case UnitDimension::inertia: return {"kg m2", 1};
    case UnitDimension::angle: return {"deg", 1};
    case UnitDimension::dimensionless: return {"", 1};
  }
  return {"", 1};
}

// `value` rounded to `digits` significant digits (at most 7), written without an exponent
// when the rounded value lies in [1, 1e7): "17260", not "1.726e+04"; otherwise as printf's %g.
// The digits are {fmt}'s correctly rounded ones, placed about the decimal point as text, so that
// no number goes through text and back (a subnormal would not come back: issue 34).
std::string rounded_plainly(double value, int digits) {
  const std::string scientific = fmt::format("{:.{}e}", value, digits - 1);  // "-1.846e+04"
  const std::size_t e = scientific.find('e');
  const int exponent = std::atoi(scientific.c_str() + e + 1);
  if (!std::isfinite(value) || exponent < 0 || exponent >= 7 || digits > 7) return format_significant(value, digits);
  const bool negative = scientific.front() == '-';
  std::string mantissa;  // the significant digits, "1846"
  for (std::size_t k = negative ? 1 : 0; k < e; ++k)
    if (scientific[k] != '.') mantissa += scientific[k];
  const std::size_t integer_digits = static_cast<std::size_t>(exponent) + 1;
  if (mantissa.size() < integer_digits) mantissa.append(integer_digits - mantissa.size(), '0');
  std::string fraction = mantissa.substr(integer_digits);
  while (!fraction.empty() && fraction.back() == '0') fraction.pop_back();
  return (negative ? "-" : "") + mantissa.substr(0, integer_digits) + (fraction.empty() ? "" : "." + fraction);
}

}  // namespace

std::string quantity_text(double si, UnitDimension dimension, UnitSystem system, int digits) {
  auto in = [&](UnitSystem s) {
    const PrintUnit unit = print_unit(si, dimension, s);
    std::string text = rounded_plainly(si / unit.to_si, digits);
    if (*unit.suffix) text += std::string(" ") + unit.suffix;
    return text;
  };
  const std::string si_text = in(UnitSystem::si);
  if (system == UnitSystem::si) return si_text;
  const std::string imperial = in(UnitSystem::imperial);
  return imperial == si_text ? si_text : imperial + " (" + si_text + ")";
}

}  // namespace trebuchet
