// Values with SI unit suffixes, as users type them: "150m", "3.1t", "40kJ", "2/3", "9.7e3kg".
#pragma once

#include <cmath>
#include <string>
#include <string_view>

#include "trebuchet/quantity.hpp"

namespace trebuchet {

/// Degrees to radians and back: the one conversion of the library.
inline double radians(double degrees) { return degrees * M_PI / 180.0; }
inline double degrees(double radians) { return radians * 180 / M_PI; }

/// Dimensions of option values; the first four are those of Quantity.
enum class UnitDimension { length, mass, energy, dimensionless, angle, acceleration, pressure, density, time, speed };

UnitDimension unit_dimension(Dimension dimension);

/// Parses a number with an optional unit suffix (blanks between them allowed: "150 m") into SI base units (m, kg, J, rad stays deg:
/// angles are returned in degrees). A bare number is taken in SI base units (degrees for
/// angles). "a/b" is a fraction. Throws Error(bad_number) for a malformed or non-finite number
/// and Error(unknown_unit) for a suffix that is unknown or of another dimension; `name` is the
/// option or column the text came from and appears in the message.
double parse_value(std::string_view text, UnitDimension dimension, std::string_view name);

/// As parse_value, and the value must be strictly positive (Error(bad_number) otherwise).
double parse_positive(std::string_view text, UnitDimension dimension, std::string_view name);

/// The accepted suffixes, for messages and help: "m, cm, mm, km".
std::string unit_list(UnitDimension dimension);

}  // namespace trebuchet
