// Values with unit suffixes: what users type, and each way it can be wrong.
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>

#include "trebuchet/error.hpp"
#include "trebuchet/app/input/units.hpp"

using namespace trebuchet;

namespace {
ErrorKind unit_error_kind(std::string_view text, UnitDimension dimension) {
  try {
    parse_positive(text, dimension, "--x");
  } catch (const Error& e) {
    return e.kind();
  }
  FAIL("no error for " << text);
  return ErrorKind::usage;
}
}  // namespace

TEST_CASE("unit suffixes convert to SI base units", "[units]") {
  CHECK(parse_value("150m", UnitDimension::length, "R") == 150);
  CHECK(parse_value("150", UnitDimension::length, "R") == 150);
  CHECK(parse_value("150 m", UnitDimension::length, "R") == 150);  // as spreadsheets and people write it
  CHECK(parse_value("25cm", UnitDimension::length, "D") == Approx(0.25).epsilon(1e-15));
  CHECK(parse_value("3.1t", UnitDimension::mass, "M") == Approx(3100).epsilon(1e-15));
  CHECK(parse_value("500g", UnitDimension::mass, "m") == Approx(0.5).epsilon(1e-15));
  CHECK(parse_value("40kJ", UnitDimension::energy, "T") == 40000);
  CHECK(parse_value("1.2MJ", UnitDimension::energy, "T") == Approx(1.2e6).epsilon(1e-15));
  CHECK(parse_value("9.7e3kg", UnitDimension::mass, "M") == Approx(9700).epsilon(1e-15));
  CHECK(parse_value("2/3", UnitDimension::dimensionless, "F") == 2.0 / 3);
  CHECK(parse_value("1/300", UnitDimension::dimensionless, "beta2") == 1.0 / 300);
  CHECK(parse_value("12GPa", UnitDimension::pressure, "E") == 12e9);
  CHECK(parse_value("1.62m/s2", UnitDimension::acceleration, "g") == 1.62);
  CHECK(parse_value("30deg", UnitDimension::angle, "theta") == 30);
}

TEST_CASE("malformed, non-finite and non-positive numbers are bad_number", "[units]") {
  for (const char* text : {"abc", "", "m", "1/0", "inf", "nan", "1e999", "-5", "0", "-2kg"})
    CHECK(unit_error_kind(text, UnitDimension::mass) == ErrorKind::bad_number);
}

TEST_CASE("unknown suffixes and suffixes of another dimension are unknown_unit", "[units]") {
  CHECK(unit_error_kind("150x", UnitDimension::length) == ErrorKind::unknown_unit);
  CHECK(unit_error_kind("150kg", UnitDimension::length) == ErrorKind::unknown_unit);
  CHECK(unit_error_kind("40kW", UnitDimension::energy) == ErrorKind::unknown_unit);
  try {
    parse_value("150kg", UnitDimension::length, "--R");
    FAIL("a mass was accepted as a length");
  } catch (const Error& e) {
    CHECK(std::string(e.what()) == "--R: '150kg' is a mass, but --R is a length; use m, cm, mm, km, ft, in, yd, mi or a bare number in metres");
  }
}

namespace {
// GNU units' value of `expression` in `si` (e.g. "ft", "m"), to 15 digits; nullopt when the
// program is missing or does not know it.
std::optional<double> gnu_units(const std::string& expression, const std::string& si) {
  const std::string command = "units -t -d 15 '" + expression + "' '" + si + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return std::nullopt;
  char buffer[256] = {};
  const bool read = std::fgets(buffer, sizeof buffer, pipe) != nullptr;
  pclose(pipe);
  char* end = nullptr;
  const double value = read ? std::strtod(buffer, &end) : 0;
  if (!read || end == buffer) return std::nullopt;
  return value;
}
}  // namespace

// Every suffix's factor against GNU units (Debian `units`, installed by scripts/install-deps.sh),
// an independent table of definitions. GNU units prints 15 significant digits, so they agree
// to 1e-14 relative; the imperial factors are exact by definition in both.
TEST_CASE("every unit's factor agrees with GNU units", "[units]") {
  const std::map<UnitDimension, std::string> si = {
      {UnitDimension::length, "m"},        {UnitDimension::mass, "kg"},        {UnitDimension::energy, "J"},
      {UnitDimension::dimensionless, "1"}, {UnitDimension::angle, "deg"},      {UnitDimension::acceleration, "m/s^2"},
      {UnitDimension::pressure, "Pa"},     {UnitDimension::density, "kg/m^3"}, {UnitDimension::time, "s"},
      {UnitDimension::speed, "m/s"},       {UnitDimension::force, "N"},        {UnitDimension::moment, "N*m"},
      {UnitDimension::inertia, "kg*m^2"}};
  // Our spellings that GNU units writes otherwise.
  const std::map<std::string, std::string> spelled = {{"ftlbf", "ft*lbf"}, {"km/h", "km/hr"}};
  for (const UnitFactor& unit : unit_factors()) {
    const std::string expression = spelled.count(unit.suffix) ? spelled.at(unit.suffix) : unit.suffix;
    const std::optional<double> theirs = gnu_units(expression, si.at(unit.dimension));
    INFO(unit.suffix << ": ours " << unit.to_si << ", GNU units " << (theirs ? std::to_string(*theirs) : "none (is units installed?)"));
    REQUIRE(theirs);
    CHECK(std::abs(unit.to_si / *theirs - 1) < 1e-14);
  }
}

TEST_CASE("imperial values are read in every dimension a design has", "[units]") {
  CHECK(parse_value("12ft", UnitDimension::length, "--L1") == Approx(3.6576).epsilon(1e-15));
  CHECK(parse_value("6 in", UnitDimension::length, "--D") == Approx(0.1524).epsilon(1e-15));
  CHECK(parse_value("220lb", UnitDimension::mass, "--m") == Approx(99.7903214).epsilon(1e-12));
  CHECK(parse_value("3.11 tonnes", UnitDimension::mass, "--M") == Approx(3110).epsilon(1e-15));
  CHECK(parse_value("100ft*lbf", UnitDimension::energy, "--T") == Approx(135.58179483314004).epsilon(1e-15));
  CHECK(unit_error_kind("12 feet", UnitDimension::length) == ErrorKind::unknown_unit);
}

// A report reads in units that suit the size: the issue's classroom model (22.4 J, 30.6 N, a
// 10 kg counterweight), and imperial with SI beside.
TEST_CASE("reports print values in units that suit their size", "[units]") {
  CHECK(quantity_text(22.419, UnitDimension::energy) == "22.42 J");
  CHECK(quantity_text(30.57, UnitDimension::force) == "30.57 N");
  CHECK(quantity_text(10, UnitDimension::mass) == "10 kg");
  CHECK(quantity_text(3110, UnitDimension::mass) == "3.11 t");
  CHECK(quantity_text(0.5, UnitDimension::mass) == "500 g");
  CHECK(quantity_text(227000, UnitDimension::energy) == "227 kJ");
  CHECK(quantity_text(0.88, UnitDimension::length) == "0.88 m");
  CHECK(quantity_text(0.004, UnitDimension::length) == "4 mm");
  CHECK(quantity_text(3.6576, UnitDimension::length, UnitSystem::imperial) == "12 ft (3.658 m)");
  CHECK(quantity_text(0.1524, UnitDimension::length, UnitSystem::imperial) == "6 in (0.1524 m)");
  CHECK(quantity_text(4448.2216152605, UnitDimension::force, UnitSystem::imperial) == "1000 lbf (4.448 kN)");
}
