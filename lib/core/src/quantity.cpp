#include "trebuchet/quantity.hpp"

namespace trebuchet {

std::string_view quantity_name(Quantity quantity) {
  switch (quantity) {
    case Quantity::R: return "R";
    case Quantity::T: return "T";
    case Quantity::L1: return "L1";
    case Quantity::L2: return "L2";
    case Quantity::L4: return "L4";
    case Quantity::D: return "D";
    case Quantity::M: return "M";
    case Quantity::m: return "m";
    case Quantity::mb: return "mb";
    case Quantity::Lb: return "Lb";
    case Quantity::l: return "l";
  }
  return "?";
}

std::optional<Quantity> quantity_from_name(std::string_view name) {
  for (Quantity q : all_quantities)
    if (quantity_name(q) == name) return q;
  return std::nullopt;
}

Dimension quantity_dimension(Quantity quantity) {
  switch (quantity) {
    case Quantity::T: return Dimension::energy;
    case Quantity::M:
    case Quantity::m:
    case Quantity::mb: return Dimension::mass;
    case Quantity::l: return Dimension::dimensionless;
    default: return Dimension::length;
  }
}

}  // namespace trebuchet
