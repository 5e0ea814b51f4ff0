#include "trebuchet/material.hpp"

#include <algorithm>
#include <cmath>

#include "trebuchet/error.hpp"

namespace trebuchet {

void check_material(const Material& m) {
  check_ordinary(m.beta2, 1e-9, 1, "beta2", "", "allowed bending u2/L2");
  check_ordinary(m.youngs_modulus, 1e3, 1e15, "youngs_modulus", "Pa", "Young's modulus");
  check_ordinary(m.wood_density, 1, 1e5, "wood_density", "kg/m3", "wood density");
  check_ordinary(m.g, 1e-6, 1e6, "g", "m/s2", "gravitational acceleration");
  check_ordinary(m.modulus_of_rupture, 1e3, 1e13, "rupture", "Pa", "modulus of rupture");
}

double k_M(const Material& material) {  // eq:kMkD
  return 4.0 * M_PI / 3.0 * material.g * material.wood_density * material.wood_density / material.youngs_modulus;
}

double k_D(const Material& material) {  // eq:kMkD
  return 16.0 / 3.0 * material.g * material.wood_density / material.youngs_modulus;
}

ExtraScalings extra_scalings(double K, double L2, const Material& material) {
  const double M = K * K * k_M(material) / material.beta2 * std::pow(L2, 4);  // eq:ExtraScalings [kg]
  return {M, std::sqrt(K * k_D(material) / material.beta2) * std::pow(L2, 1.5), M * material.g * L2};
}

SizeFactors size_factors(double L2_from, const Material& from, double L2_to, const Material& to) {
  const ExtraScalings a = extra_scalings(1, L2_from, from), b = extra_scalings(1, L2_to, to);
  return {L2_to / L2_from, b.M / a.M, b.D / a.D, b.energy_unit / a.energy_unit};
}

double short_arm_for(double M, double K, const Material& material) {  // eq:ExtraScalings, solved for L2
  return std::pow(M * material.beta2 / (K * K * k_M(material)), 0.25);
}

double bending_diameter(double M, double L2, const Material& material) {  // eq:bend_L2
  return std::pow(64 * M * material.g * L2 * L2 / (3 * M_PI * material.youngs_modulus * material.beta2), 0.25);
}

double beam_mass(double D, double Lb, const Material& material) {  // eq:BeamMass
  return material.wood_density * M_PI / 4 * D * D * Lb;
}

double beam_diameter(double mb, double Lb, const Material& material) {  // eq:BeamMass, solved for D
  return std::sqrt(4 * mb / (material.wood_density * M_PI * Lb));
}

BeamStrength beam_strength(double D, double L2, double M, double peak_moment, const Material& material, double lever) {
  BeamStrength out;
  out.D = D;
  const double second_moment = M_PI / 64 * std::pow(D, 4);  // I of eq:bend_L2 [m^4]
  out.beta2 = M * material.g * L2 * L2 / (3 * material.youngs_modulus * second_moment);  // eq:bend_L2
  out.strain_at_rest = 3 * D / (2 * L2) * out.beta2 * lever;  // eq:Strain, M g L2 lever at the pivot
  out.stress_at_rest = material.youngs_modulus * out.strain_at_rest;
  out.stress_peak = peak_moment * (D / 2) / second_moment;
  out.strain_peak = out.stress_peak / material.youngs_modulus;
  out.margin = material.modulus_of_rupture / std::max(out.stress_at_rest, out.stress_peak);
  return out;
}

}  // namespace trebuchet
