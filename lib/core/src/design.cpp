#include "trebuchet/design.hpp"

#include <cmath>

#include "trebuchet/angles.hpp"

namespace trebuchet {

double ScaledDesign::pivot_height() const { return H ? *H : l * std::cos(radians(theta_i_deg)); }

double ScaledDesign::L() const {  // eq:Design, section 2
  // F (l cos theta_i), multiplied in the order the paper's engines were always given (bit for bit).
  const double L = (H ? F * *H : F * l * std::cos(radians(theta_i_deg))) - 1;
  // The other machines' counterweight at the short arm's end, F = 1/(l cos theta_i), within rounding.
  const bool at_arm_end = machine == MachineKind::fixed || machine == MachineKind::floating_arm;
  return at_arm_end && std::abs(L) <= 1e-12 ? 0 : L;
}

double ScaledDesign::K() const { return (l + 1) / mu_b; }  // eq:kMkD

double ScaledDesign::beam_inertia() const { return parts.beam ? parts.beam->inertia : mu_b * (l * l - l + 1) / 3; }

double ScaledDesign::beam_cm() const { return parts.beam ? parts.beam->cm : (l - 1) / 2; }

std::optional<BuiltParts::Section> ScaledDesign::short_section() const {
  if (parts.beam) return parts.short_section;
  const double mass = mu_b / (l + 1);  // a uniform rod of length l + 1
  return BuiltParts::Section{mass, -0.5, mass / 3};
}

double ScaledDesign::counterweight_lever() const { return machine == MachineKind::fixed ? 1 + L() : 1; }

// Delta U (eq:DU) of the beam's lever `lever` less its own weight's, and the propped counterweight's
// extra height: the counterweight's fall with the beam's rise (energy_drop), or without it.
double ScaledDesign::fall_with_lever(double lever) const {
  const double drop = lever * (1 + std::cos(radians(theta_i_deg)));
  const bool hangs = machine == MachineKind::hinged || machine == MachineKind::whipper;
  return hangs ? drop + L() * (1 - std::cos(radians(psi_i_deg))) : drop;
}

double ScaledDesign::energy_drop() const { return fall_with_lever(counterweight_lever() - mu_b * beam_cm()); }

double ScaledDesign::counterweight_fall() const { return fall_with_lever(counterweight_lever()); }

}  // namespace trebuchet
