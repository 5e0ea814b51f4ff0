#include "trebuchet/engine.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "trebuchet/air.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/angles.hpp"

namespace trebuchet {
bool EngineParts::any() const {
  return beam_cm || beam_inertia || beam_gyration || D_hinge || D_tip || counterweight_inertia > 0 || axle.friction > 0 || hinge.friction > 0 ||
      trough_friction > 0 || rope_diameter > 0 || rope_mass > 0 || pouch_mass > 0;
}

TaperedBeam tapered_beam(double L1, double L2, double D_hinge, double D_tip, double wood_density) {
  // Along the beam x runs from -L2 (the hinge) to L1 (the tip); D(x) is linear, the mass per
  // length rho pi D^2/4. A slice of length dx turns about the pivot with x^2 dm, and about its
  // own diameter with dm D^2/16 (a thin disc). Three-point Gauss-Legendre quadrature on each
  // section is exact: the integrands are polynomials of degree 4 in x.
  auto diameter = [&](double x) { return D_hinge + (D_tip - D_hinge) * (x + L2) / (L1 + L2); };
  auto section = [&](double a, double b) {
    constexpr double node[3] = {-0.774596669241483377, 0, 0.774596669241483377};
    constexpr double weight[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    BuiltParts::Section out;
    double first_moment = 0;
    for (int k = 0; k < 3; ++k) {
      const double x = (a + b) / 2 + (b - a) / 2 * node[k], D = diameter(x);
      const double dm = wood_density * M_PI / 4 * D * D * weight[k] * (b - a) / 2;
      out.mass += dm;
      first_moment += x * dm;
      out.inertia += (x * x + D * D / 16) * dm;
    }
    out.cm = first_moment / out.mass;
    return out;
  };
  TaperedBeam beam;
  beam.short_section = section(-L2, 0);
  const BuiltParts::Section long_section = section(0, L1);
  beam.whole.mass = beam.short_section.mass + long_section.mass;
  beam.whole.cm = (beam.short_section.mass * beam.short_section.cm + long_section.mass * long_section.cm) / beam.whole.mass;
  beam.whole.inertia = beam.short_section.inertia + long_section.inertia;
  beam.D_pivot = diameter(0);
  return beam;
}

std::optional<double> given_beam_inertia(const Engine& e) {
  if (e.parts.beam_gyration) return e.mb * *e.parts.beam_gyration * *e.parts.beam_gyration;
  return e.parts.beam_inertia;
}

double wood_beam_mass(const Engine& e) {
  if (e.parts.D_hinge && e.parts.D_tip) return tapered_beam(e.L1, e.L2, *e.parts.D_hinge, *e.parts.D_tip, e.material.wood_density).whole.mass;
  return beam_mass(e.D, beam_length(e), e.material);
}

ScaledDesign scaled_design(const Engine& engine) {  // eq:Design
  ScaledDesign out{engine.L1 / engine.L2,
                   engine.L4 / engine.L1,
                   engine.mb / engine.M,
                   engine.m / engine.M,
                   engine.theta_i_deg,
                   arm_fraction(engine),
                   engine.psi_i_deg,
                   {},
                   MachineKind::hinged,
                   std::nullopt,
                   0};
  out.machine = engine.machine;
  if (engine.machine == MachineKind::whipper) {  // its beam's and rope's start in the angles of dynamics.hpp
    const Engine::WhipperStart& w = engine.whipper;
    out.psi_i_deg = engine.theta_i_deg - w.rope_angle_deg;
    out.H = w.H / engine.L2;
    out.projectile_radius = engine.projectile_diameter.value_or(sphere_diameter(engine.m, Air{}.projectile_density)) / 2 / engine.L2;
  }
  const EngineParts& p = engine.parts;
  const double L2 = engine.L2, M = engine.M, inertia_unit = M * L2 * L2;  // section 3
  BuiltParts& b = out.parts;
  if (p.D_hinge && p.D_tip) {
    const TaperedBeam beam = tapered_beam(engine.L1, L2, *p.D_hinge, *p.D_tip, engine.material.wood_density);
    b.beam = BuiltParts::Beam{beam.whole.cm / L2, beam.whole.inertia / inertia_unit};
    b.short_section = BuiltParts::Section{beam.short_section.mass / M, beam.short_section.cm / L2, beam.short_section.inertia / inertia_unit};
  } else if (const auto inertia = given_beam_inertia(engine); p.beam_cm && inertia) {
    b.beam = BuiltParts::Beam{*p.beam_cm / L2, *inertia / inertia_unit};
  }
  b.counterweight_inertia = p.counterweight_inertia / inertia_unit;
  // A journal turning in its bearing under a load F is held back at the friction circle: the
  // torque is F r sin(atan mu) = F r mu/sqrt(1 + mu^2), mu r to first order in mu.
  const auto friction_radius = [](const Pin& pin) { return pin.friction / std::sqrt(1 + pin.friction * pin.friction) * pin.radius; };
  b.axle_friction = friction_radius(p.axle) / L2;
  b.hinge_friction = friction_radius(p.hinge) / L2;
  b.trough_friction = p.trough_friction;
  b.sling = {p.rope_mass / M, p.pouch_mass / M};
  return out;
}

Engine engine_of(const ScaledDesign& design, double L2, const Material& material) {
  const ExtraScalings size = extra_scalings(design.K(), L2, material);
  Engine e;
  e.theta_i_deg = design.theta_i_deg;
  e.psi_i_deg = design.psi_i_deg;
  e.L2 = L2;
  e.L1 = design.l * L2;
  e.L3 = design.machine == MachineKind::hinged ? counterweight_arm(e.L1, L2, design.theta_i_deg, design.F) : design.L() * L2;
  e.L4 = design.l4 * e.L1;
  e.M = size.M;
  e.D = size.D;
  e.m = design.mu * e.M;
  e.mb = design.mu_b * e.M;
  e.material = material;
  e.machine = design.machine;
  if (design.machine == MachineKind::whipper) {  // its frame, rope and ball at the same scale (scaled_design's inverse)
    e.L3 = design.L() * L2;
    e.psi_i_deg = 0;
    e.whipper.H = design.H.value_or(0) * L2;
    e.whipper.rope_angle_deg = design.theta_i_deg - design.psi_i_deg;
    e.projectile_diameter = 2 * design.projectile_radius * L2;
  }
  return e;
}

namespace {
// A beam diameter within a factor 10^3 of the beam's length either way.
void proportion_of_beam(const Engine& e) {
  const double Lb = e.L1 + e.L2;
  if (!(e.D <= 1e3 * Lb && Lb <= 1e3 * e.D))
    throw Error(ErrorKind::bad_number,
                "{{D}} = " + format_significant(e.D, 6) + " m and the beam's length L1 + L2 = " + format_significant(Lb, 6) +
                    " m differ by more than a factor 10^3; give the beam's diameter in its own unit, e.g. {{D}} 25cm");
}
// The counterweight's moment of inertia about its centre (EngineParts::counterweight_inertia),
// given or from its box: not negative, and of a counterweight that could swing under the beam.
void check_counterweight_inertia(const Engine& e) {
  const EngineParts& p = e.parts;
  const auto say = [](double value) { return format_significant(value, 6); };
  if (!(p.counterweight_inertia >= 0))
    throw Error(ErrorKind::bad_number, "{{counterweight_inertia}} = " + say(p.counterweight_inertia) + ": a moment of inertia must not be negative");
  // Its radius of gyration sqrt(I/M) beyond twice the arm: a counterweight that could not swing under the beam.
  // A counterweight bolted on is no larger than the beam it rides on. The message names what the user gave: the inertia, or its box.
  const bool box = p.box_width && p.box_height;
  const std::string inertia_given = box ? "the box {{box_width}} = " + say(*p.box_width) + " m by {{box_height}} = " + say(*p.box_height) +
          " m (a moment of inertia M (w^2 + h^2)/12 = " + say(p.counterweight_inertia) + " kg m^2)"
                                        : "{{counterweight_inertia}} = " + say(p.counterweight_inertia) + " kg m^2";
  const std::string smaller = box ? "; give a smaller box" : "; a box of width w and height h has M (w^2 + h^2)/12";
  if (e.machine == MachineKind::fixed && !(p.counterweight_inertia <= e.M * beam_length(e) * beam_length(e)))
    throw Error(ErrorKind::bad_number,
                inertia_given + " gives the counterweight a radius of gyration of " + say(std::sqrt(p.counterweight_inertia / e.M)) +
                    " m, more than the beam's length Lb = " + say(beam_length(e)) + " m" + smaller);
  if (e.machine != MachineKind::fixed && e.machine != MachineKind::floating_arm && !(p.counterweight_inertia <= e.M * 4 * e.L3 * e.L3))
    throw Error(ErrorKind::bad_number,
                inertia_given + " gives the counterweight a radius of gyration of " + say(std::sqrt(p.counterweight_inertia / e.M)) +
                    " m, more than twice its arm L3 = " + say(e.L3) + " m" + smaller);
}

// The parts of an engine as built (EngineParts), each within what a real engine can have.
void check_parts(const Engine& e) {
  const EngineParts& p = e.parts;
  const auto say = [](double value) { return format_significant(value, 6); };
  // 0 is none; a coefficient below 1e-6 is none too in effect (the best bearings have 1e-3), and
  // calibrate scales the coefficients up to 2 by their ratio, which must stay finite.
  const auto coefficient = [&](double mu, const char* key, const char* what) {
    if (!(mu == 0 || (mu >= 1e-6 && mu <= 2)))
      throw Error(ErrorKind::bad_number,
                  "{{" + std::string(key) + "}} = " + say(mu) + ": the coefficient of friction of " + what +
                      " must be 0 (none) or lie from 1e-06 to 2 (greased iron on iron is near 0.1, dry oak on iron near 0.5)");
  };
  coefficient(p.axle.friction, "axle_friction", "the axle at the pivot");
  coefficient(p.hinge.friction, "hinge_friction", "the counterweight's hinge pin");
  coefficient(p.trough_friction, "trough_friction", "the projectile on the trough");
  coefficient(p.pin_friction, "pin_friction", "the sling's loop on the release pin");
  const auto pin = [&](const Pin& pin, const char* friction_key, const char* radius_key, const char* what, double largest, const char* largest_text) {
    if (!(pin.radius >= 0))
      throw Error(ErrorKind::bad_number,
                  "{{" + std::string(radius_key) + "}} = " + say(pin.radius) + ": the radius of " + what + " must be positive");
    if (pin.friction > 0 && !(pin.radius > 0))
      throw Error(
          ErrorKind::usage,
          "{{" + std::string(friction_key) + "}} needs the radius of " + what + " its friction acts at; give it, e.g. {{" + radius_key + "}} 5cm");
    if (pin.radius > 0) {
      check_ordinary(pin.radius, 1e-6, 1e6, radius_key, "m", std::string("radius of ") + what);
      if (!(pin.radius < largest))
        throw Error(ErrorKind::bad_number,
                    "{{" + std::string(radius_key) + "}} = " + say(pin.radius) + " m: the radius of " + what + " must be smaller than " +
                        largest_text + ", " + say(largest) + " m");
    }
  };
  pin(p.axle, "axle_friction", "axle_radius", "the axle", std::min(e.L1, e.L2), "the shorter beam section");
  pin(p.hinge, "hinge_friction", "hinge_radius", "the hinge pin", std::min(e.L2, e.L3), "the short beam section and the counterweight arm");
  if (p.beam_inertia && p.beam_gyration)
    throw Error(ErrorKind::usage, "{{beam_inertia}} and {{beam_gyration}} both give the beam's inertia (I = mb k^2); give one");
  if (p.beam_gyration && !(*p.beam_gyration > 0))
    throw Error(ErrorKind::bad_number, "{{beam_gyration}} = " + say(*p.beam_gyration) + ": a radius of gyration must be positive");
  if (p.beam_gyration) check_ordinary(*p.beam_gyration, 1e-6, 1e6, "beam_gyration", "m", "beam's radius of gyration about the pivot");
  const std::optional<double> inertia = given_beam_inertia(e);
  if (p.beam_cm.has_value() != inertia.has_value())
    throw Error(ErrorKind::usage,
                std::string(p.beam_cm ? "{{beam_cm}} needs the beam's moment of inertia about the pivot too: give {{beam_inertia}}"
                                      : "{{beam_inertia}} needs the beam's centre of mass too: give {{beam_cm}}") +
                    " (or describe a tapered beam by {{D_hinge}} and {{D_tip}})");
  if (p.D_hinge.has_value() != p.D_tip.has_value())
    throw Error(ErrorKind::usage, "a tapered beam needs both end diameters: give {{D_hinge}} and {{D_tip}}");
  if (p.beam_cm && p.D_tip)
    throw Error(ErrorKind::usage, "{{beam_cm}} and {{D_tip}} both describe the beam as built; give its centre of mass and inertia, or its taper");
  if (p.beam_cm) {
    if (!(e.mb > 0)) throw Error(ErrorKind::usage, "{{beam_cm}} describes a beam of mass {{mb}} = 0; give the beam's mass");
    if (!(*p.beam_cm > -e.L2 && *p.beam_cm < e.L1))
      throw Error(ErrorKind::bad_number,
                  "{{beam_cm}} = " + say(*p.beam_cm) + " m: the beam's centre of mass must lie on it, between -L2 = " + say(-e.L2) +
                      " m (toward the hinge) and L1 = " + say(e.L1) + " m (toward the tip)");
    // About the pivot I = I_cm + mb c^2 >= mb c^2; and no part of the beam reaches beyond its
    // longer section (its thickness adds a few per cent at most).
    const double least = e.mb * *p.beam_cm * *p.beam_cm, most = 1.1 * e.mb * std::max(e.L1 * e.L1, e.L2 * e.L2);
    if (!(*inertia >= least && *inertia <= most))
      throw Error(ErrorKind::bad_number,
                  std::string(p.beam_gyration ? "{{beam_gyration}} = " + say(*p.beam_gyration) + " m gives I = mb k^2 = " : "{{beam_inertia}} = ") +
                      say(*inertia) + " kg m^2: a beam of " + say(e.mb) + " kg with its centre of mass " + say(*p.beam_cm) +
                      " m from the pivot has one from mb c^2 = " + say(least) + " to " + say(most) +
                      " kg m^2 about the pivot (a uniform beam: mb (L1^2 - L1 L2 + L2^2)/3)");
  }
  if (p.D_tip) {
    for (const auto& [value, key] : {std::pair{*p.D_hinge, "D_hinge"}, {*p.D_tip, "D_tip"}}) {
      if (!(value > 0))
        throw Error(ErrorKind::bad_number, "{{" + std::string(key) + "}} = " + say(value) + ": a diameter of the beam must be positive");
      check_ordinary(value, 1e-6, 1e6, key, "m", "diameter at the beam's end");
      if (!(value <= beam_length(e)))
        throw Error(ErrorKind::bad_number,
                    "{{" + std::string(key) + "}} = " + say(value) + " m is thicker than the beam is long, " + say(beam_length(e)) +
                        " m; give the diameter in its own unit, e.g. 30cm");
    }
  }
  check_counterweight_inertia(e);
  if (!(p.rope_diameter >= 0 && p.rope_diameter <= e.L4 / 2))
    throw Error(ErrorKind::bad_number,
                "{{rope_diameter}} = " + say(p.rope_diameter) + " m: the sling's rope must have a diameter from 0 (no drag) to half its length, " +
                    say(e.L4 / 2) + " m; a rope is a few centimetres thick");
  check_ordinary(p.rope_cd, 1e-3, 1e2, "rope_cd", "", "drag coefficient of the rope");
  for (const auto& [mass, key, what] : {std::tuple{p.rope_mass, "rope_mass", "the sling's rope"}, {p.pouch_mass, "pouch_mass", "the sling's pouch"}})
    if (!(mass >= 0 && mass <= e.M))
      throw Error(ErrorKind::bad_number,
                  "{{" + std::string(key) + "}} = " + say(mass) + " kg: the mass of " + what + " must lie from 0 (none) to the counterweight's, " +
                      say(e.M) + " kg; a sling weighs grams to a few kg");
}

// The whipper's start besides theta_i: a frame of ordinary height, the rope off the arm on its
// upper side, less than square to it.
void check_whipper(const Engine::WhipperStart& w) {
  if (!(w.H > 0))
    throw Error(ErrorKind::bad_number,
                "{{H}} = " + format_significant(w.H, 6) + ": the whipper stands on a frame: give its pivot's height above the base, e.g. 5m");
  check_ordinary(w.H, 1e-6, 1e6, "H", "m", "pivot height");
  // At 0 the rope would lie along the arm, its counterweight on the arm's line rather than off
  // its upper side, where the whipper's start (whipper.hpp) rests it.
  if (!(w.rope_angle_deg > 0 && w.rope_angle_deg < 90))
    throw Error(ErrorKind::bad_number,
                "{{rope_angle_deg}} = " + format_significant(w.rope_angle_deg, 6) +
                    ": the counterweight's rope lies off the arm by above 0 to below 90 deg, on its upper side; pytrebuchet's is 10");
}

}  // namespace

void check_engine(const Engine& e) {
  auto positive = [&](double value, const char* key, const char* what) {
    if (!(value > 0))
      throw Error(ErrorKind::bad_number, "{{" + std::string(key) + "}} = " + format_significant(value, 6) + ": the " + what + " must be positive");
  };
  if (e.projectile_diameter) check_ordinary(*e.projectile_diameter, 1e-6, 1e6, "projectile_diameter", "m", "projectile's diameter");
  if (e.machine == MachineKind::whipper && e.projectile_diameter && !(*e.projectile_diameter < e.L1))
    throw Error(ErrorKind::bad_number,
                "{{projectile_diameter}} = " + format_significant(*e.projectile_diameter, 6) +
                    " m: the whipper's ball rests on its long arm, L1 = " + format_significant(e.L1, 6) + " m; give a ball smaller than the arm");
  if (e.machine == MachineKind::whipper) {
    if (!(e.theta_i_deg > -180 && e.theta_i_deg <= -90))
      throw Error(ErrorKind::bad_number,
                  "{{theta_i_deg}} = " + format_significant(e.theta_i_deg, 6) +
                      ": the whipper's long arm starts forward, from level (-90 deg) to below upright (-180 deg): "
                      "theta_i = -90 deg less its angle above the horizontal; pytrebuchet's 60 deg is -150");
  } else if (!(e.theta_i_deg > 0 && e.theta_i_deg < 90)) {
    throw Error(ErrorKind::bad_number,
                "{{theta_i_deg}} = " + format_significant(e.theta_i_deg, 6) + ": the initial beam angle must lie between 0 and 90 degrees");
  }
  if (!(std::abs(e.psi_i_deg) < 90))
    throw Error(ErrorKind::bad_number,
                "{{psi_i_deg}} = " + format_significant(e.psi_i_deg, 6) +
                    ": the initial counterweight angle must lie between -90 and 90 degrees (0: hanging, unpropped)");
  positive(e.L1, "L1", "long beam section");
  positive(e.L2, "L2", "short beam section");
  // The hinged engine and the whipper hang their counterweight on an arm; the others may set its
  // centre at the short arm's end.
  const bool hinged = e.machine == MachineKind::hinged, hangs = hinged || e.machine == MachineKind::whipper;
  if (hangs)
    positive(e.L3, "L3", "counterweight arm (hinge to counterweight centre)");
  else if (!(e.L3 >= 0))
    throw Error(ErrorKind::bad_number,
                "{{L3}} = " + format_significant(e.L3, 6) +
                    ": the counterweight's centre beyond the short arm's end (or below its pin) must not be negative");
  if (!hinged && e.psi_i_deg != 0)
    throw Error(
        ErrorKind::bad_number,
        "{{psi_i_deg}} = " + format_significant(e.psi_i_deg, 6) + ": only the hinged counterweight can be propped; leave it out for this machine");
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
  for (const auto& [value, key, what] :
       {std::tuple{e.L1, "L1", "long beam section"}, {e.L2, "L2", "short beam section"}, {e.L4, "L4", "sling length"}})
    check_ordinary(value, 1e-6, 1e6, key, "m", what);
  if (hangs || e.L3 > 0) check_ordinary(e.L3, 1e-6, 1e6, "L3", "m", "counterweight arm");
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
      throw Error(ErrorKind::bad_number,
                  "{{" + std::string(key_a) + "}} = " + format_significant(a, 6) + " and {{" + key_b + "}} = " + format_significant(b, 6) +
                      " differ by more than a factor 10^6; give an engine of ordinary proportions");
  };
  proportion(e.L1, "L1", e.L2, "L2");
  proportion(e.L4, "L4", e.L1, "L1");
  if (hangs || e.L3 > 0) proportion(e.L3, "L3", e.L2, "L2");
  if (e.machine == MachineKind::whipper) check_whipper(e.whipper);
  proportion(e.m, "m", e.M, "M");
  if (e.mb > 0) proportion(e.mb, "mb", e.M, "M");
  check_parts(e);
}

double beam_length(const Engine& engine) { return engine.L1 + engine.L2; }

double pivot_height(const Engine& engine) {
  return engine.machine == MachineKind::whipper ? engine.whipper.H : engine.L1 * std::cos(radians(engine.theta_i_deg));
}

double arm_fraction(const Engine& engine) { return (engine.L2 + engine.L3) / pivot_height(engine); }

void give_box(Engine& engine, double width, double height) {
  engine.parts.box_width = width, engine.parts.box_height = height;
  engine.parts.counterweight_inertia = engine.machine == MachineKind::floating_arm ? 0 : engine.M * (width * width + height * height) / 12;
}

double counterweight_arm(double L1, double L2, double theta_i_deg, double F) { return F * L1 * std::cos(radians(theta_i_deg)) - L2; }

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
  out.whipper.H *= f.length;  // the whipper's frame and the ball keep their shape
  if (out.projectile_diameter) *out.projectile_diameter *= f.length;
  return out;
}

}  // namespace trebuchet
