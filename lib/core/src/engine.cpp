#include "trebuchet/engine.hpp"

#include <cmath>
#include <tuple>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/angles.hpp"

namespace trebuchet {
ScaledDesign scaled_design(const Engine& engine) {  // eq:Design
  return {engine.L1 / engine.L2, engine.L4 / engine.L1, engine.mb / engine.M, engine.m / engine.M, engine.theta_i_deg,
          arm_fraction(engine), engine.psi_i_deg};
}

Engine engine_of(const ScaledDesign& design, double L2, const Material& material) {
  const ExtraScalings size = extra_scalings(design.K(), L2, material);
  Engine e;
  e.theta_i_deg = design.theta_i_deg;
  e.psi_i_deg = design.psi_i_deg;
  e.L2 = L2;
  e.L1 = design.l * L2;
  e.L3 = counterweight_arm(e.L1, L2, design.theta_i_deg, design.F);
  e.L4 = design.l4 * e.L1;
  e.M = size.M;
  e.D = size.D;
  e.m = design.mu * e.M;
  e.mb = design.mu_b * e.M;
  e.material = material;
  return e;
}

namespace {
// A beam diameter within a factor 10^3 of the beam's length either way.
void proportion_of_beam(const Engine& e) {
  const double Lb = e.L1 + e.L2;
  if (!(e.D <= 1e3 * Lb && Lb <= 1e3 * e.D))
    throw Error(ErrorKind::bad_number, "{{D}} = " + format_significant(e.D, 6) + " m and the beam's length L1 + L2 = " + format_significant(Lb, 6) +
                                           " m differ by more than a factor 10^3; give the beam's diameter in its own unit, e.g. {{D}} 25cm");
}
}  // namespace

void check_engine(const Engine& e) {
  auto positive = [&](double value, const char* key, const char* what) {
    if (!(value > 0))
      throw Error(ErrorKind::bad_number, "{{" + std::string(key) + "}} = " + format_significant(value, 6) + ": the " + what +
                                             " must be positive");
  };
  if (!(e.theta_i_deg > 0 && e.theta_i_deg < 90))
    throw Error(ErrorKind::bad_number, "{{theta_i_deg}} = " + format_significant(e.theta_i_deg, 6) +
                                           ": the initial beam angle must lie between 0 and 90 degrees");
  if (!(std::abs(e.psi_i_deg) < 90))
    throw Error(ErrorKind::bad_number, "{{psi_i_deg}} = " + format_significant(e.psi_i_deg, 6) +
                                           ": the initial counterweight angle must lie between -90 and 90 degrees (0: hanging, unpropped)");
  positive(e.L1, "L1", "long beam section");
  positive(e.L2, "L2", "short beam section");
  positive(e.L3, "L3", "counterweight arm (hinge to counterweight centre)");
  positive(e.L4, "L4", "sling length");
  positive(e.M, "M", "counterweight mass");
  positive(e.m, "m", "projectile mass");
  if (!(e.mb >= 0)) throw Error(ErrorKind::bad_number, "{{mb}} = " + format_significant(e.mb, 6) + ": the beam mass must not be negative");
  positive(e.material.beta2, "beta2", "allowed bending");
  positive(e.material.youngs_modulus, "youngs_modulus", "Young's modulus");
  positive(e.material.wood_density, "wood_density", "wood density");
  positive(e.material.g, "g", "gravitational acceleration");
  // Sizes and proportions of ordinary range: within them every product the physics and its SI
  // outputs form (M g L2, sqrt(g L2), L1/L2 ...) stays finite, and the integrator sees an engine.
  for (const auto& [value, key, what] : {std::tuple{e.L1, "L1", "long beam section"}, {e.L2, "L2", "short beam section"},
                                         {e.L3, "L3", "counterweight arm"}, {e.L4, "L4", "sling length"}})
    check_ordinary(value, 1e-6, 1e6, key, "m", what);
  for (const auto& [value, key, what] : {std::tuple{e.M, "M", "counterweight mass"}, {e.m, "m", "projectile mass"}})
    check_ordinary(value, 1e-9, 1e12, key, "kg", what);
  if (e.mb > 0) check_ordinary(e.mb, 1e-9, 1e12, "mb", "kg", "beam mass");
  if (e.D > 0) {  // the beam's diameter carries its stress: within the sizes, and a beam, not a plank or a tower
    check_ordinary(e.D, 1e-6, 1e6, "D", "m", "beam diameter");
    proportion_of_beam(e);
  }
  check_material(e.material);
  const auto proportion = [](double a, const char* key_a, double b, const char* key_b) {
    constexpr double widest = 1e6;
    if (!(a <= widest * b && b <= widest * a))
      throw Error(ErrorKind::bad_number, "{{" + std::string(key_a) + "}} = " + format_significant(a, 6) + " and {{" + key_b + "}} = " +
                                             format_significant(b, 6) + " differ by more than a factor 10^6; give an engine of ordinary proportions");
  };
  proportion(e.L1, "L1", e.L2, "L2");
  proportion(e.L4, "L4", e.L1, "L1");
  proportion(e.L3, "L3", e.L2, "L2");
  proportion(e.m, "m", e.M, "M");
  if (e.mb > 0) proportion(e.mb, "mb", e.M, "M");
}

double beam_length(const Engine& engine) { return engine.L1 + engine.L2; }

double pivot_height(const Engine& engine) { return engine.L1 * std::cos(radians(engine.theta_i_deg)); }

double arm_fraction(const Engine& engine) { return (engine.L2 + engine.L3) / pivot_height(engine); }

double counterweight_arm(double L1, double L2, double theta_i_deg, double F) {
  return F * L1 * std::cos(radians(theta_i_deg)) - L2;
}

double potential_energy_drop(const Engine& engine) {
  return scaled_design(engine).energy_drop() * engine.M * engine.material.g * engine.L2;  // in units of M g L2 (section 3)
}

Engine resized(const Engine& engine, const SizeFactors& f) {
  Engine out = engine;
  out.L1 *= f.length;
  out.L2 *= f.length;
  out.L3 *= f.length;
  out.L4 *= f.length;
  out.D *= f.diameter;
  out.M *= f.mass;
  out.m *= f.mass;
  out.mb *= f.mass;
  return out;
}

}  // namespace trebuchet
