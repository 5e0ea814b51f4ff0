#include "trebuchet/design.hpp"

#include <cmath>

#include "trebuchet/angles.hpp"

namespace trebuchet {

double ScaledDesign::L() const { return F * l * std::cos(radians(theta_i_deg)) - 1; }  // eq:Design, section 2

double ScaledDesign::K() const { return (l + 1) / mu_b; }  // eq:kMkD

double ScaledDesign::beam_inertia() const { return mu_b * (l * l - l + 1) / 3; }

double ScaledDesign::energy_drop() const {  // eq:DU, and the propped counterweight's extra height
  return (1 - mu_b * (l - 1) / 2) * (1 + std::cos(radians(theta_i_deg))) + L() * (1 - std::cos(radians(psi_i_deg)));
}

}  // namespace trebuchet
