#include "trebuchet/app/input/request.hpp"

#include "trebuchet/air.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {

Given parse_given(std::string_view name, std::string_view text) {
  auto quantity = quantity_from_name(name);
  if (!quantity) {
    std::string names;
    for (Quantity q : all_quantities) names += (names.empty() ? "" : ", ") + std::string(quantity_name(q));
    throw Error(ErrorKind::usage, "'" + std::string(name) + "' is not a quantity; use two of " + names);
  }
  return {*quantity, parse_positive(text, unit_dimension(quantity_dimension(*quantity)), name)};
}

BranchChoice parse_branch_choice(std::string_view text) {
  if (text == "auto") return BranchChoice::automatic;
  if (text == "lower") return BranchChoice::lower;
  if (text == "upper") return BranchChoice::upper;
  throw Error(ErrorKind::usage, "branch: '" + std::string(text) + "' is not a branch; use auto, lower or upper");
}

double parse_theta(std::string_view text, std::string_view name) {
  const double degrees = parse_positive(text, UnitDimension::angle, name);
  if (degrees >= 90)
    throw Error(ErrorKind::bad_number,
                std::string(name) + ": '" + std::string(text) + "' must lie between 0 and 90 degrees (the beam angle from the vertical)");
  return degrees;
}

double parse_projectile_density(std::string_view text, std::string_view name) {
  if (const ProjectileMaterial* material = find_projectile_material(std::string(text))) return material->density;
  if (text.find_first_of("0123456789") == std::string_view::npos) {
    std::string names;
    for (const ProjectileMaterial& m : projectile_materials()) names += std::string(m.name) + ", ";
    throw Error(ErrorKind::usage,
                std::string(name) + ": '" + std::string(text) + "' is not a projectile's material; give " + names + "or a density, e.g. 7870kg/m3");
  }
  return parse_positive(text, UnitDimension::density, name);
}

}  // namespace trebuchet
