// Beam material, allowed bending and gravity: what ties masses to lengths (section 4), and
// eq:ExtraScalings, the one place where an engine's masses, diameter and energy follow from
// its size.
#pragma once

namespace trebuchet {

/// The paper's defaults are those of eq:kMkD.
struct Material {
  double beta2 = 1.0 / 300;  ///< allowed bending of the short beam section u2/L2, eq:bend_L2, scaled
  double youngs_modulus = 12e9;  ///< Young's modulus of the beam's wood [Pa]
  double wood_density = 700;  ///< density of the beam's wood [kg/m^3]
  double g = 9.81;  ///< gravitational acceleration [m/s^2]
  /// The stress beyond which the wood breaks [Pa]; section 4: "often near 1 % of M_e".
  double modulus_of_rupture = 120e6;
};

/// Refuses (Error(bad_number), naming {{beta2}}, {{youngs_modulus}}, {{wood_density}}, {{g}} or
/// {{rupture}}) a material outside the ordinary: beta2 1e-9 to 1, E 1e3 to 1e15 Pa, wood 1 to
/// 1e5 kg/m^3, g 1e-6 to 1e6 m/s^2, the modulus of rupture 1e3 to 1e13 Pa. Within them every factor of eq:kMkD and eq:ExtraScalings is finite.
void check_material(const Material& material);

/// k_M = (4 pi / 3) g rho_d^2 / M_e of eq:kMkD [kg/m^4].
double k_M(const Material& material);

/// k_D = (16 / 3) g rho_d / M_e of eq:kMkD [1/m].
double k_D(const Material& material);

/// eq:ExtraScalings for a scaled design with K = (l + 1)/mu_b (eq:kMkD) at short arm L2 [m]:
/// M = K^2 (k_M/beta2) L2^4, D = sqrt(K k_D/beta2) L2^(3/2), and the energy unit M g L2 of
/// section 3, so that T = M g L2 tau_e.
struct ExtraScalings {
  double M;  ///< counterweight mass [kg]
  double D;  ///< beam diameter [m]
  double energy_unit;  ///< M g L2 [J]
};

ExtraScalings extra_scalings(double K, double L2, const Material& material);

/// The short arm L2 [m] at which eq:ExtraScalings gives a counterweight of `M` [kg] for K: its inverse.
double short_arm_for(double M, double K, const Material& material);

/// The beam diameter [m] that bends the short section by beta2 under the counterweight `M` [kg]
/// at short arm `L2` [m]: eq:bend_L2, beta2 = M g L2^2/(3 E I) with I = pi D^4/64. At the
/// optimum's M it is eq:ExtraScalings' D.
double bending_diameter(double M, double L2, const Material& material);

/// eq:BeamMass: the mass [kg] of a round beam of diameter `D` [m] and length `Lb` [m] in the
/// material's wood, rho_d (pi/4) D^2 Lb; and its inverse, the diameter of a beam of mass `mb` [kg].
double beam_mass(double D, double Lb, const Material& material);
double beam_diameter(double mb, double Lb, const Material& material);

/// How hard the counterweight bends a round beam of diameter D (section 4), and how close the
/// wood comes to breaking.
struct BeamStrength {
  double D = 0;  ///< beam diameter [m]
  double beta2 = 0;  ///< u2/L2 of eq:bend_L2 that the counterweight gives it, scaled
  double strain_at_rest =
      0;  ///< eq:Strain at the pivot, the beam level under the counterweight (being cocked; the beam's own weight left out, as there), scaled
  double stress_at_rest = 0;  ///< M_e times it [Pa]
  double strain_peak = 0;  ///< from the largest bending moment at the pivot during the shot, scaled
  double stress_peak = 0;  ///< [Pa]
  double margin = 0;  ///< the modulus of rupture over the larger stress, scaled
};
/// The strength of a beam of diameter `D` [m] at short arm `L2` [m] under a counterweight `M`
/// [kg], whose largest bending moment at the pivot in the shot is `peak_moment` [N m]: the
/// stress of a moment is its moment over the section modulus pi D^3/32. `lever` places the
/// counterweight's weight at rest, in L2 (ScaledDesign::counterweight_lever: 1 + L3/L2 for the
/// fixed counterweight, whose centre lies beyond the arm's end, 1 for those hung from it).
BeamStrength beam_strength(double D, double L2, double M, double peak_moment, const Material& material, double lever = 1);
/// Factors that carry an optimal engine from one size and material to another at the same
/// scaled design, by eq:ExtraScalings: lengths and R with the length ratio, masses with the
/// ratio of M, D with that of D, energies with that of M g L2. Section 7: beta2 from 1/300 to
/// 1/200 at equal lengths gives mass = energy = 2/3 and diameter^2 = 2/3.
struct SizeFactors {
  double length = 1;
  double mass = 1;
  double diameter = 1;
  double energy = 1;
};

/// From (L2_from, from) to (L2_to, to) [m]; K cancels.
SizeFactors size_factors(double L2_from, const Material& from, double L2_to, const Material& to);

}  // namespace trebuchet
