#include "trebuchet/material.hpp"

#include <cmath>

namespace trebuchet {

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

}  // namespace trebuchet
