// The named quantities a user can give or read: capacity, engine parameters, beam shape.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace trebuchet {

/// Physical dimension of a value, which decides the unit suffixes it accepts.
enum class Dimension { length, mass, energy, dimensionless };

/// Quantities the calculator accepts as givens (any two of them).
enum class Quantity {
  R,  ///< range in vacuum, pivot to impact at the engine's base level [m]
  T,  ///< kinetic energy at the target, eq:T [J]
  L1,  ///< long beam section [m]
  L2,  ///< short beam section [m]
  L4,  ///< sling length [m]
  D,  ///< beam diameter [m]
  M,  ///< counterweight mass [kg]
  m,  ///< projectile mass [kg]
  mb,  ///< beam mass [kg]
  Lb,  ///< beam length L1 + L2 [m]
  l,  ///< beam ratio L1/L2, scaled
};

inline constexpr std::array<Quantity, 11> all_quantities = {Quantity::R, Quantity::T, Quantity::L1, Quantity::L2, Quantity::L4, Quantity::D,
                                                            Quantity::M, Quantity::m, Quantity::mb, Quantity::Lb, Quantity::l};

/// The name used on the command line, in CSV headers and JSON keys ("R", "mb", ...).
std::string_view quantity_name(Quantity quantity);

/// The quantity with this name, if any; names are case-sensitive (M is not m).
std::optional<Quantity> quantity_from_name(std::string_view name);

Dimension quantity_dimension(Quantity quantity);

}  // namespace trebuchet
