#include "trebuchet/design.hpp"

#include <cmath>

#include "trebuchet/angles.hpp"

namespace trebuchet {

double ScaledDesign::L() const { return F * l * std::cos(radians(theta_i_deg)) - 1; }  // eq:Design, section 2

double ScaledDesign::K() const { return (l + 1) / mu_b; }  // eq:kMkD

double ScaledDesign::beam_inertia() const { return parts.beam ? parts.beam->inertia : mu_b * (l * l - l + 1) / 3; }

double ScaledDesign::beam_cm() const { return parts.beam ? parts.beam->cm : (l - 1) / 2; }

std::optional<BuiltParts::Section> ScaledDesign::short_section() const {
  if (parts.beam) return parts.short_section;
  const double mass = mu_b / (l + 1);  // a uniform rod of length l + 1
  return BuiltParts::Section{mass, -0.5, mass / 3};
}

double ScaledDesign::energy_drop() const {  // eq:DU, and the propped counterweight's extra height
  return (1 - mu_b * beam_cm()) * (1 + std::cos(radians(theta_i_deg))) + L() * (1 - std::cos(radians(psi_i_deg)));
}

}  // namespace trebuchet
