// An engine in absolute SI terms (eq:Parameters) with the material it is built of, and what
// follows from it: its scaled design (eq:Design), geometry and stored energy (eq:DU).
#pragma once

#include <string>

#include "trebuchet/design.hpp"
#include "trebuchet/material.hpp"

namespace trebuchet {

/// A swinging counterweight trebuchet at rest before a shot (psi_i = phi_i = 0, section 2).
/// theta_i is measured between the long beam section and the downward vertical.
struct Engine {
  double L1 = 0;           ///< long beam section, pivot to spigot [m]
  double L2 = 0;           ///< short beam section, pivot to hinge [m]
  double L3 = 0;           ///< counterweight arm, hinge to counterweight [m]
  double L4 = 0;           ///< sling, spigot to projectile [m]
  double D = 0;            ///< beam diameter [m]; not in the equations of motion
  double M = 0;            ///< counterweight mass [kg]
  double m = 0;            ///< projectile mass [kg]
  double mb = 0;           ///< beam mass [kg]
  double theta_i_deg = standard_theta_i_deg;  ///< initial beam angle theta_i [deg]
  double psi_i_deg = 0;    ///< initial counterweight angle [deg]: 0 unpropped (design.hpp gives the sign)
  Material material{};     ///< beta2, wood and g: what sized it, and the g it is shot under
};

/// The scaled design of eq:Design, with F from the counterweight arm.
ScaledDesign scaled_design(const Engine& engine);

/// The engine of a scaled design at short arm L2 [m] (eq:Design), its counterweight mass and
/// beam diameter from eq:ExtraScalings, m = mu M and mb = mu_b M.
Engine engine_of(const ScaledDesign& design, double L2, const Material& material);

/// The validation every engine passes, given or computed: lengths and masses positive (mb may
/// be 0), theta_i in (0, 90) degrees, a positive material. Throws Error(bad_number) naming the
/// parameter by its key, "{{L4}}" (error.hpp).
void check_engine(const Engine& engine);

double beam_length(const Engine& engine);    ///< Lb = L1 + L2 [m]
double pivot_height(const Engine& engine);   ///< H = L1 cos(theta_i) [m]
double arm_fraction(const Engine& engine);   ///< F = (L2 + L3)/H, section 2, scaled

/// L3 from L2 + L3 = F H, H = L1 cos(theta_i) (section 2) [m].
double counterweight_arm(double L1, double L2, double theta_i_deg, double F);

/// Delta U of eq:DU: potential energy released by a whole shot, under the engine's g [J].
double potential_energy_drop(const Engine& engine);

/// The engine with its lengths, masses and D multiplied by the size factors (eq:ExtraScalings).
Engine resized(const Engine& engine, const SizeFactors& factors);

}  // namespace trebuchet
