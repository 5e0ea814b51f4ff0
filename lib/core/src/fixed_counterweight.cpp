#include "trebuchet/fixed_counterweight.hpp"

#include <cmath>

#include "trebuchet/angles.hpp"
#include "trebuchet/error.hpp"

namespace trebuchet {

// From the Lagrangian (docs/verifier.md, "The fixed counterweight"), with the projectile
// p = l (sin th - l4 cos phi, -cos th - l4 sin phi) and the sling's length s = l l4 in L2:
//   T = J th'^2/2 + mu |p'|^2/2,   V = G cos th + mu p_y.
// Phase I: the trough holds p_y (cos th + l4 sin phi = cos th_i), one degree of freedom; with
// k = dp_x/dth = l (cos th + sin th tan phi): (J + mu k^2) th'' + mu k k_th th'^2 = G sin th.
// Phase II: with sn = sin(phi - th), cs = cos(phi - th),
//   (J + mu l^2) th'' + mu l s sn phi'' = (G - mu l) sin th - mu l s cs phi'^2
//   l sn th'' + s phi'' = l cs th'^2 + cos phi.
// Phase III: the rigid body alone, J th'' = G sin th.
std::array<double, 3> FixedCounterweight::accelerations_of(Phase phase, const State& s) const {
  const double l = design_.l, l4 = design_.l4, mu = design_.mu, J = inertia_, G = weight_, th = s.theta;
  if (phase == Phase::released) {
    const double th_dd = G * std::sin(th) / J;
    return {th_dd, th_dd, 0};
  }
  if (phase == Phase::trough) {
    const double sin_phi = std::sin(s.phi), cos_phi = std::cos(s.phi), tan_phi = sin_phi / cos_phi;
    const double k = l * (std::cos(th) + std::sin(th) * tan_phi);
    const double k_th = l * (-std::sin(th) + std::cos(th) * tan_phi + std::sin(th) * std::sin(th) / (l4 * cos_phi * cos_phi * cos_phi));
    const double th_dd = (G * std::sin(th) - mu * k * k_th * s.theta_dot * s.theta_dot) / (J + mu * k * k);
    const double phi_dd = (std::cos(th) * s.theta_dot * s.theta_dot + std::sin(th) * th_dd + l4 * sin_phi * s.phi_dot * s.phi_dot) / (l4 * cos_phi);
    return {th_dd, th_dd, phi_dd};
  }
  const double sling = l * l4, sn = std::sin(s.phi - th), cs = std::cos(s.phi - th);
  const double a11 = J + mu * l * l, a12 = mu * l * sling * sn, a21 = l * sn, a22 = sling;
  const double b1 = (G - mu * l) * std::sin(th) - mu * l * sling * cs * s.phi_dot * s.phi_dot;
  const double b2 = l * cs * s.theta_dot * s.theta_dot + std::cos(s.phi);
  const double det = a11 * a22 - a12 * a21;
  const double th_dd = (b1 * a22 - a12 * b2) / det, phi_dd = (a11 * b2 - a21 * b1) / det;
  return {th_dd, th_dd, phi_dd};
}

FixedCounterweight::FixedCounterweight(const ScaledDesign& design) : design_(design), theta_i_(radians(design.theta_i_deg)) {
  if (design.parts.dissipates())
    throw Error(ErrorKind::usage, "the fixed counterweight takes no friction or drag before the release yet; leave them out");
  design_.psi_i_deg = 0;  // the counterweight turns with the beam: nothing to prop
  inertia_ = design_.beam_inertia() + 1 + design_.parts.counterweight_inertia;
  weight_ = 1 - design_.mu_b * design_.beam_cm();
}

double FixedCounterweight::trough_cos_phi(double theta) const {
  const double sin_phi = (std::cos(theta_i_) - std::cos(theta)) / design_.l4;
  return sin_phi * sin_phi < 1 ? std::sqrt(1 - sin_phi * sin_phi) : 0;
}

double FixedCounterweight::complete_trough_state(State& s) const {
  const double cos_phi = trough_cos_phi(s.theta);
  if (!(cos_phi > 0)) return 0;
  s.phi = std::asin((std::cos(theta_i_) - std::cos(s.theta)) / design_.l4);  // eq:EOM_I_3
  s.phi_dot = std::sin(s.theta) * s.theta_dot / (design_.l4 * cos_phi);
  return cos_phi;
}

bool FixedCounterweight::accelerations(Phase phase, const State& given, std::array<double, 3>& out, Losses*) const {
  State state = given;
  if (phase == Phase::trough && !(complete_trough_state(state) > 0)) return false;  // the seam's contract: phi follows from theta there
  out = accelerations_of(phase, state);
  return std::isfinite(out[0]) && std::isfinite(out[2]);
}

Snapshot FixedCounterweight::snapshot(Phase phase, const State& given) const {
  State s = given;
  if (phase == Phase::trough) complete_trough_state(s);
  const ScaledDesign& e = design_;
  const double l = e.l, l4 = e.l4, mu = e.mu, th = s.theta, th_d = s.theta_dot, st = std::sin(th), ct = std::cos(th);
  const auto a = accelerations_of(phase, s);
  Snapshot out;
  out.theta_ddot = a[0], out.psi_ddot = a[1], out.phi_ddot = a[2];
  out.hinge = out.counterweight = {-st, ct};
  out.tip = {l * st, -l * ct};
  // A point at r (sin th, -cos th) of the beam accelerates by r times this.
  const Vec2 along{ct * a[0] - st * th_d * th_d, st * a[0] + ct * th_d * th_d};
  out.hinge_force = {-along.x, -along.y + 1};  // what the beam gives the counterweight (at r = -1): all but its weight
  const double base = -l * std::cos(theta_i_);
  out.counterweight_height = ct - base;
  out.tip_height = -l * ct - base;
  const double c = e.beam_cm(), I_c = e.parts.counterweight_inertia;
  out.energies.beam = e.beam_inertia() * th_d * th_d / 2 - e.mu_b * c * ct;
  out.energies.counterweight = (1 + I_c) * th_d * th_d / 2 + ct;
  if (phase != Phase::released) {
    const double sp = std::sin(s.phi), cp = std::cos(s.phi), phi_d = s.phi_dot;
    out.projectile = {l * (st - l4 * cp), l * (-ct - l4 * sp)};
    out.projectile_velocity = {l * (ct * th_d + l4 * sp * phi_d), l * (st * th_d - l4 * cp * phi_d)};
    const Vec2 p_dd{l * (along.x + l4 * sp * a[2] + l4 * cp * phi_d * phi_d), l * (along.y - l4 * cp * a[2] + l4 * sp * phi_d * phi_d)};
    // The sling pulls the projectile toward the tip along u = (cos phi, sin phi); in the trough
    // the trough's normal force holds its height.
    out.sling_tension = phase == Phase::trough ? mu * p_dd.x / cp : mu * (p_dd.x * cp + p_dd.y * sp + sp);
    out.normal_force = phase == Phase::trough ? mu - out.sling_tension * sp : 0;
    out.sling_on_tip = {-out.sling_tension * cp, -out.sling_tension * sp};
    // The tip moves along (cos th, sin th) as theta grows; the sling pulls against that.
    out.sling_perpendicular = -(out.sling_on_tip.x * ct + out.sling_on_tip.y * st);
    const Vec2& v = out.projectile_velocity;
    out.energies.projectile_kinetic = mu * (v.x * v.x + v.y * v.y) / 2;
    out.energies.projectile_potential = mu * out.projectile.y;
  }
  // The frame holds the beam (its centre c along it) and the counterweight against their
  // motion, their weights and the sling's pull.
  out.pivot_reaction = {out.hinge_force.x + e.mu_b * c * along.x - out.sling_on_tip.x,
                        out.hinge_force.y + e.mu_b * (c * along.y + 1) - out.sling_on_tip.y};
  // The short section passes the long one what turns the counterweight (its pull at the hinge and
  // its own turn) and the section itself, as in the paper's engine (dynamics.cpp).
  if (const auto section = e.short_section())
    out.beam_moment = st * out.hinge_force.y + ct * out.hinge_force.x + section->mass * -section->cm * st - (section->inertia + I_c) * a[0];
  out.energy = out.energies.beam + out.energies.counterweight + out.energies.projectile_kinetic + out.energies.projectile_potential;
  return out;
}

}  // namespace trebuchet
