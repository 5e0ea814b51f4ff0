// The engines the tests and benchmarks share, each once, as the paper prints them.
#pragma once

#include <cmath>

#include "trebuchet/design.hpp"
#include "trebuchet/engine.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet::testing {

/// How far `a` lies from `b`, relative to b: |a/b - 1|.
inline double relative(double a, double b) { return std::abs(a / b - 1); }

/// A row of tab:Alcala_la_Vieja as printed: theta_i = 30 deg, F = 2/3, m = 50 kg stones;
/// lengths [m], M [t], mb [kg].
inline Engine alcala_row(double L1, double L2, double L4, double M_t, double mb) {
  Engine e;
  e.L1 = L1, e.L2 = L2, e.L4 = L4, e.M = M_t * 1000, e.m = 50, e.mb = mb, e.theta_i_deg = 30;
  e.L3 = counterweight_arm(L1, L2, 30, 2.0 / 3);
  return e;
}

/// tab:Alcala_la_Vieja row Ca (150 m, 50 kg).
inline Engine alcala_ca() { return alcala_row(4.13, 0.88, 3.55, 3.11, 174); }
/// tab:Alcala_la_Vieja row Ma aimed at 480 m.
inline Engine alcala_ma_480() { return alcala_row(5.50, 0.71, 5.15, 11.5, 334); }
/// tab:Alcala_la_Vieja row Ma aimed at 426 m (the target lies 54 m below).
inline Engine alcala_ma_426() { return alcala_row(5.36, 0.75, 4.96, 9.70, 320); }
/// tab:Alcala_la_Vieja row Sa (Saone, 250 m).
inline Engine alcala_sa() { return alcala_row(4.72, 0.85, 4.19, 5.16, 242); }

/// tab:Denny "Present": Denny's standard engine, Lb = 12 m, M = 10 t, m = 100 kg, mb = 2 t
/// (bold), H = 6.15 m, L4 = 7.9 m at theta_i = 45 deg and F = 0.93 as printed.
inline Engine denny_standard() {
  Engine e;
  e.theta_i_deg = 45, e.L1 = 6.15 / std::cos(radians(45)), e.L2 = 12 - e.L1, e.L4 = 7.9, e.M = 1e4, e.m = 100, e.mb = 2000;
  e.L3 = counterweight_arm(e.L1, e.L2, 45, 0.93);
  return e;
}

/// The laboratory engine of arXiv 2502.19442, as the peer Trebuchator takes its dimensions from
/// the paper: the beam as built (4.86 kg, its centre of mass 0.465 m toward the tip, 1.85 kg m2
/// about the pivot) and the 717 g projectile (the light shot's is 68.5 g).
inline Engine laboratory_engine(double m = 0.717) {
  Engine e;
  e.L1 = 0.975, e.L2 = 0.25, e.L3 = 0.515, e.L4 = 0.87, e.theta_i_deg = 31.513, e.M = 53.9, e.m = m, e.mb = 4.86;
  e.parts.beam_cm = 0.465, e.parts.beam_inertia = 1.85;
  return e;
}

/// pytrebuchet's WhipperTrebuchet.default(): an arm of 2 m (the weight's side) and 4 m, 10 kg; a
/// 100 kg weight on a 4 m rope, 10 deg off the arm; a 3 kg ball 0.2 m across in a 4 m sling; the
/// pivot 5 m up, the arm 60 deg above the horizontal (theta_i = -150 deg here).
inline Engine pytrebuchet_default() {
  Engine e;
  e.machine = MachineKind::whipper;
  e.L1 = 4, e.L2 = 2, e.L3 = 4, e.L4 = 4, e.M = 100, e.m = 3, e.mb = 10;
  e.theta_i_deg = whipper_theta_i_deg;
  e.whipper.H = 5, e.whipper.rope_angle_deg = 10, e.projectile_diameter = 0.2;
  return e;
}

/// A scaled design given by L = L3/L2 rather than F, as appendix A writes the equations.
inline ScaledDesign design_with_L(double l, double l4, double L, double mu, double mu_b, double theta_i_deg) {
  return {l, l4, mu_b, mu, theta_i_deg, (L + 1) / (l * std::cos(radians(theta_i_deg)))};
}

/// The settings of a shot released at its range optimum (Denny's criterion), in vacuum.
inline ShotSettings range_optimum() {
  ShotSettings range;
  range.criterion.release = Release::range;
  return range;
}

}  // namespace trebuchet::testing
