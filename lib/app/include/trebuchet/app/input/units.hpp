// Values with SI unit suffixes, as users type them: "150m", "3.1t", "40kJ", "2/3", "9.7e3kg".
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "trebuchet/angles.hpp"
#include "trebuchet/quantity.hpp"
#include "trebuchet/uncertainty.hpp"

namespace trebuchet {

/// Dimensions of option values; the first four are those of Quantity.
enum class UnitDimension { length, mass, energy, dimensionless, angle, acceleration, pressure, density, time, speed, force, moment, inertia };

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

/// `spread` as parse_spread reads it back, to the last bit: each side's shortest exact digits
/// with the SI unit of `dimension` ("1900kg..2100kg", "3.55m±0.2m"; degrees for angles).
std::string spread_text(const Spread& spread, UnitDimension dimension);

/// One accepted suffix and its size in SI base units (degrees for angles).
struct UnitFactor {
  std::string suffix;
  UnitDimension dimension;
  double to_si;
};
std::vector<UnitFactor> unit_factors();

/// Whether `text` is one of the accepted suffixes ("t", "tonnes", "ft").
bool is_unit_word(std::string_view text);

/// How the text reports print values: SI, or imperial with SI beside (--units imperial).
enum class UnitSystem { si, imperial };

/// `si` (in SI base units) with `digits` significant digits in a unit that reads plainly: SI
/// prefixed so that the number is at least 1 ("22.4 J", "30.6 N", "3.11 t", "4.5 mm", "0.88 m"
/// down to a centimetre); imperial "12.3 ft (3.75 m)": ft or in, lb or oz, lbf, ft·lbf, psi, ft/s.
std::string quantity_text(double si, UnitDimension dimension, UnitSystem system = UnitSystem::si, int digits = 4);

}  // namespace trebuchet
