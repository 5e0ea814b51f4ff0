#include "trebuchet/material.hpp"

#include <cmath>

namespace trebuchet {

double k_M(const Material& material) {
  return 4.0 * M_PI / 3.0 * material.g * material.wood_density * material.wood_density / material.youngs_modulus;
}

double k_D(const Material& material) {
  return 16.0 / 3.0 * material.g * material.wood_density / material.youngs_modulus;
}

MaterialScaling material_scaling(const Material& from, const Material& to) {
  const double mass = (k_M(to) / to.beta2) / (k_M(from) / from.beta2);
  return {mass, mass * to.g / from.g, std::sqrt((k_D(to) / to.beta2) / (k_D(from) / from.beta2))};
}

}  // namespace trebuchet
