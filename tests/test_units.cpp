// Values with unit suffixes: what users type, and each way it can be wrong.
#include <catch2/catch.hpp>

#include "trebuchet/error.hpp"
#include "trebuchet/app/units.hpp"

using namespace trebuchet;

namespace {
ErrorKind kind_of(std::string_view text, UnitDimension dimension) {
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
    CHECK(kind_of(text, UnitDimension::mass) == ErrorKind::bad_number);
}

TEST_CASE("unknown suffixes and suffixes of another dimension are unknown_unit", "[units]") {
  CHECK(kind_of("150x", UnitDimension::length) == ErrorKind::unknown_unit);
  CHECK(kind_of("150kg", UnitDimension::length) == ErrorKind::unknown_unit);
  CHECK(kind_of("40kW", UnitDimension::energy) == ErrorKind::unknown_unit);
  try {
    parse_value("150kg", UnitDimension::length, "--R");
    FAIL("a mass was accepted as a length");
  } catch (const Error& e) {
    CHECK(std::string(e.what()) == "--R: '150kg' is a mass, but --R is a length; use m, cm, mm, km or a bare number in metres");
  }
}
