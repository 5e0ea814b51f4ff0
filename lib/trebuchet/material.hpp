// Beam material, allowed bending and gravity: what ties masses to lengths (section 4).
#pragma once

namespace trebuchet {

/// The paper's defaults are those of eq:kMkD.
struct Material {
  double beta2 = 1.0 / 300;        ///< allowed bending of the short beam section u2/L2, eq:bend_L2, scaled
  double youngs_modulus = 12e9;    ///< Young's modulus of the beam's wood [Pa]
  double wood_density = 700;       ///< density of the beam's wood [kg/m^3]
  double g = 9.81;                 ///< gravitational acceleration [m/s^2]
};

/// k_M = (4 pi / 3) g rho_d^2 / M_e of eq:kMkD [kg/m^4].
double k_M(const Material& material);

/// k_D = (16 / 3) g rho_d / M_e of eq:kMkD [1/m].
double k_D(const Material& material);

/// Factors that carry an optimal design from one material (and g, beta2) to another at equal
/// lengths and scaled design: eq:ExtraScalings gives M = K^2 (k_M/beta2) L2^4,
/// T = M g L2 tau_e and D = sqrt(K k_D/beta2) L2^(3/2). Section 7: beta2 from 1/300 to 1/200
/// gives mass = energy = 2/3 and diameter^2 = 2/3, lengths and R unchanged.
struct MaterialScaling {
  double mass;      ///< factor on M, m, mb
  double energy;    ///< factor on T and Delta U
  double diameter;  ///< factor on D
};

MaterialScaling material_scaling(const Material& from, const Material& to);

}  // namespace trebuchet
