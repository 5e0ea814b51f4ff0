// Values with SI unit suffixes, as users type them: "150m", "3.1t", "40kJ", "2/3", "9.7e3kg".
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "trebuchet/angles.hpp"
#include "trebuchet/quantity.hpp"
#include "trebuchet/uncertainty.hpp"

namespace trebuchet {

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

/// The spread of `text` ("2.5t..3.5t", "3.5m±0.2m", "3.5m+-0.2m"; each side with an optional
/// unit, a bare number in SI units), or nullopt for a plain value. Throws Error(bad_number) for
/// an empty or reversed range or a negative deviation, naming `name`.
std::optional<Spread> parse_spread(std::string_view text, UnitDimension dimension, std::string_view name);

}  // namespace trebuchet
