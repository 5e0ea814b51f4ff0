#include "pendulum_sling.hpp"

#include <cmath>

namespace trebuchet::testing {
namespace {

// The accelerations of each phase, from the Lagrangian
//   T = theta'^2/2 + mu |p'|^2/2,  V = cos(theta) + mu p_y,
//   hinge (-sin th, cos th), tip l (sin th, -cos th), projectile p = l (sin th - l4 cos phi, -cos th - l4 sin phi).
// Phase I: the trough holds p_y (cos th + l4 sin phi = cos th_i), one degree of freedom; with
// k = dp_x/dth = l (cos th + sin th tan phi): (1 + mu k^2) th'' + mu k k_th th'^2 = sin th.
// Phase II: with s = sin(phi - th), c = cos(phi - th),
//   (1 + mu l^2) th'' + mu l^2 l4 s phi'' = (1 - mu l) sin th - mu l^2 l4 c phi'^2
//   l s th'' + l l4 phi'' = l c th'^2 + cos phi.
// Phase III: the pendulum alone, th'' = sin th.
std::array<double, 3> accelerations_of(const ScaledDesign& d, Phase phase, const State& s) {
  const double l = d.l, l4 = d.l4, mu = d.mu, th = s.theta;
  if (phase == Phase::released) return {std::sin(th), std::sin(th), 0};
  if (phase == Phase::trough) {
    const double sin_phi = std::sin(s.phi), cos_phi = std::cos(s.phi), tan_phi = sin_phi / cos_phi;
    const double k = l * (std::cos(th) + std::sin(th) * tan_phi);
    const double k_th = l * (-std::sin(th) + std::cos(th) * tan_phi + std::sin(th) * std::sin(th) / (l4 * cos_phi * cos_phi * cos_phi));
    const double th_dd = (std::sin(th) - mu * k * k_th * s.theta_dot * s.theta_dot) / (1 + mu * k * k);
    const double phi_dd = (std::cos(th) * s.theta_dot * s.theta_dot + std::sin(th) * th_dd + l4 * sin_phi * s.phi_dot * s.phi_dot) / (l4 * cos_phi);
    return {th_dd, th_dd, phi_dd};
  }
  const double sn = std::sin(s.phi - th), cs = std::cos(s.phi - th);
  const double a11 = 1 + mu * l * l, a12 = mu * l * l * l4 * sn, a21 = l * sn, a22 = l * l4;
  const double b1 = (1 - mu * l) * std::sin(th) - mu * l * l * l4 * cs * s.phi_dot * s.phi_dot;
  const double b2 = l * cs * s.theta_dot * s.theta_dot + std::cos(s.phi);
  const double det = a11 * a22 - a12 * a21;
  const double th_dd = (b1 * a22 - a12 * b2) / det, phi_dd = (a11 * b2 - a21 * b1) / det;
  return {th_dd, th_dd, phi_dd};
}

}  // namespace

PendulumSling::PendulumSling(const ScaledDesign& design) : design_(design), theta_i_(design.theta_i_deg * M_PI / 180) {
  design_.mu_b = 0;  // no beam: Delta U of eq:DU is the counterweight's fall alone
  design_.psi_i_deg = 0;
}

double PendulumSling::trough_cos_phi(double theta) const {
  const double sin_phi = (std::cos(theta_i_) - std::cos(theta)) / design_.l4;
  return sin_phi * sin_phi < 1 ? std::sqrt(1 - sin_phi * sin_phi) : 0;
}

double PendulumSling::complete_trough_state(State& s) const {
  const double sin_phi = (std::cos(theta_i_) - std::cos(s.theta)) / design_.l4;
  const double cos_phi = std::sqrt(1 - sin_phi * sin_phi);
  s.phi = std::asin(sin_phi);
  s.phi_dot = std::sin(s.theta) * s.theta_dot / (design_.l4 * cos_phi);
  return cos_phi;
}

bool PendulumSling::accelerations(Phase phase, const State& given, std::array<double, 3>& out, Losses*) const {
  State state = given;
  if (phase == Phase::trough) complete_trough_state(state);  // the seam's contract: phi follows from theta there
  out = accelerations_of(design_, phase, state);
  return std::isfinite(out[0]) && std::isfinite(out[2]);
}

Snapshot PendulumSling::snapshot(Phase phase, const State& given) const {
  State s = given;
  if (phase == Phase::trough) complete_trough_state(s);
  const double l = design_.l, l4 = design_.l4, mu = design_.mu, th = s.theta, th_d = s.theta_dot;
  const auto a = accelerations_of(design_, phase, s);
  Snapshot out;
  out.theta_ddot = a[0], out.psi_ddot = a[1], out.phi_ddot = a[2];
  out.hinge = out.counterweight = {-std::sin(th), std::cos(th)};
  out.tip = {l * std::sin(th), -l * std::cos(th)};
  // The counterweight's acceleration; the arm gives it all but its weight.
  const Vec2 hinge_acceleration{-std::cos(th) * a[0] + std::sin(th) * th_d * th_d, -std::sin(th) * a[0] - std::cos(th) * th_d * th_d};
  out.hinge_force = {hinge_acceleration.x, hinge_acceleration.y + 1};
  out.counterweight_height = std::cos(th) + l * std::cos(theta_i_);
  out.tip_height = -l * std::cos(th) + l * std::cos(theta_i_);
  out.energies.counterweight = th_d * th_d / 2 + std::cos(th);
  if (phase != Phase::released) {
    const double sp = std::sin(s.phi), cp = std::cos(s.phi), phi_d = s.phi_dot;
    out.projectile = {l * (std::sin(th) - l4 * cp), l * (-std::cos(th) - l4 * sp)};
    out.projectile_velocity = {l * (std::cos(th) * th_d + l4 * sp * phi_d), l * (std::sin(th) * th_d - l4 * cp * phi_d)};
    const Vec2 p_dd{l * (std::cos(th) * a[0] - std::sin(th) * th_d * th_d + l4 * sp * a[2] + l4 * cp * phi_d * phi_d),
                    l * (std::sin(th) * a[0] + std::cos(th) * th_d * th_d - l4 * cp * a[2] + l4 * sp * phi_d * phi_d)};
    // The sling pulls the projectile toward the tip along u = (cos phi, sin phi); in the trough
    // the trough's normal force holds its height.
    out.sling_tension = phase == Phase::trough ? mu * p_dd.x / cp : mu * (p_dd.x * cp + p_dd.y * sp + sp);
    out.normal_force = phase == Phase::trough ? mu - out.sling_tension * sp : 0;
    out.sling_on_tip = {-out.sling_tension * cp, -out.sling_tension * sp};
    out.sling_perpendicular = out.sling_tension * std::cos(s.phi - th);
    out.beam_moment = out.sling_tension * l * std::cos(th + s.phi);
    const Vec2& v = out.projectile_velocity;
    out.energies.projectile_kinetic = mu * (v.x * v.x + v.y * v.y) / 2;
    out.energies.projectile_potential = mu * out.projectile.y;
  }
  // The frame holds the beam against the counterweight's motion and the sling's pull.
  out.pivot_reaction = {out.hinge_force.x - out.sling_on_tip.x, out.hinge_force.y - out.sling_on_tip.y};
  out.energy = out.energies.counterweight + out.energies.projectile_kinetic + out.energies.projectile_potential;
  return out;
}

}  // namespace trebuchet::testing
