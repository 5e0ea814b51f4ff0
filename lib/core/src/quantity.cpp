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

std::string_view quantity_description(Quantity quantity) {
  switch (quantity) {
    case Quantity::R: return "range";
    case Quantity::T: return "energy at target";
    case Quantity::L1: return "long beam section";
    case Quantity::L2: return "short beam section";
    case Quantity::L4: return "sling length";
    case Quantity::D: return "beam diameter";
    case Quantity::M: return "counterweight mass";
    case Quantity::m: return "projectile mass";
    case Quantity::mb: return "beam mass";
    case Quantity::Lb: return "beam length";
    case Quantity::l: return "beam ratio L1/L2";
  }
  return "?";
}

}  // namespace trebuchet
