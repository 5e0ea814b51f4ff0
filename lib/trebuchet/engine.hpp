// An engine in absolute SI terms (eq:Parameters) and what follows from it: its scaled design
// (eq:Design), geometry, stored energy (eq:DU) and model scaling (eq:ExtraScalings).
#pragma once

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
  double theta_i_deg = 0;  ///< initial beam angle theta_i [deg]
};

/// Dimensionless parameters of eq:Design and K of eq:kMkD (lengths in L2, masses in M).
struct ScaledDesign {
  double l;     ///< L1/L2
  double l4;    ///< L4/L1
  double L;     ///< L3/L2 = F l cos(theta_i) - 1
  double mu;    ///< m/M
  double mu_b;  ///< mb/M
  double K;     ///< (l + 1)/mu_b
};

ScaledDesign scaled_design(const Engine& engine);

double beam_length(const Engine& engine);    ///< Lb = L1 + L2 [m]
double pivot_height(const Engine& engine);   ///< H = L1 cos(theta_i) [m]
double arm_fraction(const Engine& engine);   ///< F = (L2 + L3)/H, section 2, scaled

/// L3 from L2 + L3 = F H, H = L1 cos(theta_i) (section 2) [m].
double counterweight_arm(double L1, double L2, double theta_i_deg, double F);

/// Delta U of eq:DU: potential energy released by a whole shot [J]; g in m/s^2.
double potential_energy_drop(const Engine& engine, double g);

/// The same scaled design at lambda times the size: lengths * lambda, D * lambda^1.5,
/// masses * lambda^4 (eq:ExtraScalings); energies then scale with lambda^5.
Engine scale_engine(const Engine& engine, double lambda);

}  // namespace trebuchet
