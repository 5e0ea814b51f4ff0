// Turning user text (command-line values, CSV cells) into a DesignRequest.
#pragma once

#include <string_view>

#include "trebuchet/calculator.hpp"

namespace trebuchet {

/// A given from its name ("R", "mb", ...) and text ("150m"); Error(usage) for an unknown
/// name, and the errors of parse_positive for the value.
Given parse_given(std::string_view name, std::string_view text);

/// "auto", "lower" or "upper"; Error(usage) otherwise.
BranchChoice parse_branch_choice(std::string_view text);

/// The initial beam angle: "30", "30deg" [deg]; must lie in (0, 90).
double parse_theta(std::string_view text, std::string_view name);

/// A projectile's density [kg/m^3] from a material's name (stone, iron, lead, clay: air.hpp's
/// projectile_materials) or a density with its unit ("7870kg/m3"); Error(usage) naming `name`
/// for a word that is neither, the errors of parse_positive for the number.
double parse_projectile_density(std::string_view text, std::string_view name);

}  // namespace trebuchet
