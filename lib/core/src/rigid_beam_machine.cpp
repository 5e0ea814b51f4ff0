#include "trebuchet/rigid_beam_machine.hpp"

#include <cmath>
#include <string>

#include "trebuchet/angles.hpp"
#include "trebuchet/dynamics.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/sling.hpp"

namespace trebuchet {

RigidBeamMachine::RigidBeamMachine(const ScaledDesign& design, MachineKind kind, const char* name)
    : design_(design), theta_i_(radians(design.theta_i_deg)) {
  if (design.parts.rope_drag > 0)
    throw Error(ErrorKind::usage, std::string("the ") + name + " takes no drag on the sling's rope yet; leave out {{rope_diameter}}");
  design_.machine = kind;  // its Delta U and lever (ScaledDesign::energy_drop)
  design_.psi_i_deg = 0;  // the counterweight moves with the beam: nothing to prop
  weight_ = design_.counterweight_lever() - design_.mu_b * design_.beam_cm();
}

RigidBeamMachine::Share RigidBeamMachine::body_inertia(double th, const Path& a) const {
  // The beam's centre c along it moves with the pivot: its speed is (a' + c cos th, c sin th) th',
  // so its kinetic energy is (I + mu_b (a'^2 + 2 a' c cos th)) th'^2/2, I about the pivot.
  const double mu_b = design_.mu_b, c = design_.beam_cm();
  const Share cw = counterweight_share(th, a);
  return {design_.beam_inertia() + mu_b * (a.slope * a.slope + 2 * a.slope * c * std::cos(th)) + cw.inertia,
          mu_b * (2 * a.slope * a.curve + 2 * c * (a.curve * std::cos(th) - a.slope * std::sin(th))) + cw.slope};
}

// From the Lagrangian T = J(th) th'^2/2 + mu |p'|^2/2, V = G cos th + mu p_y (docs/machines.md),
// the projectile p = (a + l sin th - s cos phi, -l cos th - s sin phi),
// s = l l4 the sling in L2, each term of p a function of one coordinate, so that
// p'' = p_th th'' + p_phi phi'' + p_thth th'^2 + p_phiphi phi'^2, and with y the unit upward:
//   Phase I: the trough holds p_y (cos th + l4 sin phi = cos th_i), one degree of freedom; with
//     k = dp_x/dth = a' + l (cos th + sin th tan phi):
//     (J + mu k^2) th'' + (J'/2 + mu k k_th) th'^2 = G sin th.
//   Phase II:  J th'' + J' th'^2/2 - G sin th + mu p_th . (p'' + y) = 0,  p_phi . (p'' + y) = 0.
//   Phase III: the body alone, J th'' + J' th'^2/2 = G sin th.
//   Friction and the air add their generalized forces Q_theta and Q_phi to the right-hand sides.
// A sling with mass (sling.hpp) puts the point mass `end` at the sling's end in place of mu, its
// rope's share m_t at the tip into the body (J and G), and the rope's inertia beyond those, Js,
// into the sling's turn: Js phi'' in phi's equation, and in the trough, where phi follows
// theta, Js (phi_th^2 th'' + phi_th phi_thth th'^2) in theta's. After the release a sling with
// mass swings on by phase II's equations with its own end mass.
std::array<double, 3> RigidBeamMachine::accelerations_of(Phase phase, const State& s, Generalized extra) const {
  const BuiltParts::Sling& sling_parts = design_.parts.sling;
  const double l = design_.l, l4 = design_.l4, th = s.theta, w2 = s.theta_dot * s.theta_dot;
  const double mu = sling_parts.end_mass(phase == Phase::released ? 0 : design_.mu), G = weight_ - sling_parts.tip_mass() * l;
  const Path a = pivot_path(th);
  Share J = body_inertia(th, a);
  if (sling_parts.tip_mass() > 0) {  // the tip (a + l sin th, -l cos th) moves by (a' + l cos th, l sin th) th'
    const double m = sling_parts.tip_mass(), ct = std::cos(th), st = std::sin(th);
    J.inertia += m * (a.slope * a.slope + 2 * a.slope * l * ct + l * l);
    J.slope += m * (2 * a.slope * a.curve + 2 * l * (a.curve * ct - a.slope * st));
  }
  const double rope_inertia = sling_parts.inertia_beyond(l * l4);
  const double turns = counterweight_turns() ? 1 : 0;  // psi'' = theta'', or 0
  if (phase == Phase::released && !swings_after_release()) {
    const double th_dd = (G * std::sin(th) + extra.theta - J.slope * w2 / 2) / J.inertia;
    return {th_dd, turns * th_dd, 0};
  }
  if (phase == Phase::trough) {
    const double sin_phi = std::sin(s.phi), cos_phi = std::cos(s.phi), tan_phi = sin_phi / cos_phi;
    const double k = a.slope + l * (std::cos(th) + std::sin(th) * tan_phi);
    const double k_th = a.curve + l * (-std::sin(th) + std::cos(th) * tan_phi + std::sin(th) * std::sin(th) / (l4 * cos_phi * cos_phi * cos_phi));
    double inertia = J.inertia + mu * k * k, slope = J.slope / 2 + mu * k * k_th;
    if (rope_inertia != 0) {  // phi_th = sin th/(l4 cos phi), eq:EOM_I_3
      const double phi_th = std::sin(th) / (l4 * cos_phi), phi_thth = (std::cos(th) + sin_phi * std::sin(th) * phi_th / cos_phi) / (l4 * cos_phi);
      inertia += rope_inertia * phi_th * phi_th, slope += rope_inertia * phi_th * phi_thth;
    }
    const double th_dd = (G * std::sin(th) + extra.theta - slope * w2) / inertia;
    const double phi_dd = (std::cos(th) * w2 + std::sin(th) * th_dd + l4 * sin_phi * s.phi_dot * s.phi_dot) /
        (l4 * cos_phi);  // eq:EOM_I_3 twice differentiated
    return {th_dd, turns * th_dd, phi_dd};
  }
  const double sling = l * l4, sp = std::sin(s.phi), cp = std::cos(s.phi);
  const Vec2 p_th{a.slope + l * std::cos(th), l * std::sin(th)}, p_phi{sling * sp, -sling * cp};
  // p's acceleration without th'' and phi'', plus the weight's unit: p_thth th'^2 + p_phiphi phi'^2 + y
  const Vec2 rest{(a.curve - l * std::sin(th)) * w2 + sling * cp * s.phi_dot * s.phi_dot,
                  l * std::cos(th) * w2 + sling * sp * s.phi_dot * s.phi_dot + 1};
  const double a11 = J.inertia + mu * dot(p_th, p_th), a12 = mu * dot(p_th, p_phi), a22 = mu * dot(p_phi, p_phi) + rope_inertia;
  const double b1 = G * std::sin(th) + extra.theta - J.slope * w2 / 2 - mu * dot(p_th, rest), b2 = extra.phi - mu * dot(p_phi, rest);
  const double det = a11 * a22 - a12 * a12;
  const double th_dd = (b1 * a22 - a12 * b2) / det, phi_dd = (a11 * b2 - a12 * b1) / det;
  return {th_dd, turns * th_dd, phi_dd};
}

double RigidBeamMachine::trough_cos_phi(double theta) const {
  const double sin_phi = (std::cos(theta_i_) - std::cos(theta)) / design_.l4;
  return sin_phi * sin_phi < 1 ? std::sqrt(1 - sin_phi * sin_phi) : 0;
}

double RigidBeamMachine::complete_trough_state(State& s) const {
  const double cos_phi = trough_cos_phi(s.theta);
  if (!(cos_phi > 0)) return 0;
  s.phi = std::asin((std::cos(theta_i_) - std::cos(s.theta)) / design_.l4);  // eq:EOM_I_3
  s.phi_dot = std::sin(s.theta) * s.theta_dot / (design_.l4 * cos_phi);
  return cos_phi;
}

Evaluated RigidBeamMachine::accelerations(Phase phase, const State& given, std::array<double, 3>& out, Losses* loss_power) const {
  State state = given;  // in the trough phi follows from theta (the seam's contract)
  if (phase == Phase::trough && !(complete_trough_state(state) > refuse_trough_cos_phi)) return Evaluated::near_trough_singularity;
  if (!dissipates()) {
    out = accelerations_of(phase, state, {});
  } else {
    const std::optional<Snapshot> snapshot = resisted(phase, state);
    if (!snapshot) return Evaluated::failed;
    out = {snapshot->theta_ddot, snapshot->psi_ddot, snapshot->phi_ddot};
    if (loss_power) *loss_power = snapshot->loss_power;
  }
  return std::isfinite(out[0]) && std::isfinite(out[2]) ? Evaluated::found : Evaluated::failed;
}

Snapshot RigidBeamMachine::snapshot(Phase phase, const State& given) const {
  State s = given;
  if (phase == Phase::trough) complete_trough_state(s);
  if (!dissipates()) return snapshot_with(phase, s, accelerations_of(phase, s, {}), {}, 0);
  const std::optional<Snapshot> out = resisted(phase, s);
  if (!out) throw Error(ErrorKind::numerical, unsettled_friction);
  return *out;
}

// Coulomb's friction at the axle (and at the floating arm's pin) against the beam's turn, and in
// the trough against the projectile's slide, takes the forces that carry it; those depend on the
// accelerations, which depend on the friction: a fixed point, reached in a few rounds for any
// friction the model holds. The air's drag on the projectile, -mu Cd k |u| u with u its velocity
// through the air (air.hpp), depends on the state alone. Each enters as its generalized force.
std::optional<Snapshot> RigidBeamMachine::resisted(Phase phase, const State& s) const {
  const BuiltParts& parts = design_.parts;
  const double l = design_.l, sling = l * design_.l4, th = s.theta, turn = (s.theta_dot > 0) - (s.theta_dot < 0);
  const Path path = pivot_path(th);
  const Vec2 p_th{path.slope + l * std::cos(th), l * std::sin(th)}, p_phi{sling * std::sin(s.phi), -sling * std::cos(s.phi)};
  const double k = phase == Phase::trough ? path.slope + l * (std::cos(th) + std::sin(th) * std::tan(s.phi)) : 0;  // dp_x/dtheta in the trough
  const Vec2 v = phase == Phase::released ? Vec2{} : Vec2{p_th.x * s.theta_dot + p_phi.x * s.phi_dot, p_th.y * s.theta_dot + p_phi.y * s.phi_dot};
  Vec2 drag{};
  if (parts.drag && phase != Phase::released) {
    drag = air_force(*parts.drag, design_.mu, v);
  }
  const Generalized air = phase == Phase::trough ? Generalized{drag.x * k, 0}
                                                 : Generalized{drag.x * p_th.x + drag.y * p_th.y, drag.x * p_phi.x + drag.y * p_phi.y};
  const double slide = (v.x > 0) - (v.x < 0);
  std::array<double, 3> a = accelerations_of(phase, s, air);
  double friction = 0;  // the trough's on the projectile, along x
  for (int round = 0; round < 60; ++round) {
    Snapshot snap = snapshot_with(phase, s, a, drag, friction);
    const double axle = parts.axle_friction * std::hypot(snap.pivot_reaction.x, snap.pivot_reaction.y);
    const double pin = counterweight_turns() ? 0 : parts.hinge_friction * std::hypot(snap.hinge_force.x, snap.hinge_force.y);
    const double trough = phase == Phase::trough ? -parts.trough_friction * std::max(snap.normal_force, 0.0) * slide : 0;
    Generalized q = air;
    q.theta += trough * k - (axle + pin) * turn;
    const std::array<double, 3> next = accelerations_of(phase, s, q);
    const bool settled = std::abs(next[0] - a[0]) <= 1e-14 * (1 + std::abs(a[0])) && std::abs(next[2] - a[2]) <= 1e-14 * (1 + std::abs(a[2])) &&
        std::abs(trough - friction) <= 1e-14 * (1 + std::abs(friction));
    a = next, friction = trough;
    if (settled) {
      snap = snapshot_with(phase, s, a, drag, friction);
      snap.loss_power[axle_loss] = axle * std::abs(s.theta_dot);
      snap.loss_power[hinge_loss] = pin * std::abs(s.theta_dot);
      snap.loss_power[trough_loss] = std::abs(friction * v.x);
      snap.loss_power[projectile_drag_loss] = -(drag.x * v.x + drag.y * v.y);
      if (design_.short_section()) snap.beam_moment -= pin * turn;  // the pin's friction holds the short section back
      return snap;
    }
  }
  return std::nullopt;
}

Snapshot RigidBeamMachine::snapshot_with(Phase phase, const State& s, const std::array<double, 3>& a, Vec2 drag, double friction) const {
  const ScaledDesign& e = design_;
  const double l = e.l, l4 = e.l4, mu = e.mu, th = s.theta, th_d = s.theta_dot, st = std::sin(th), ct = std::cos(th);
  const Path path = pivot_path(th);
  const Vec2 pivot{path.x, 0}, pivot_acceleration{path.slope * a[0] + path.curve * th_d * th_d, 0};
  Snapshot out;
  out.theta_ddot = a[0], out.psi_ddot = a[1], out.phi_ddot = a[2];
  out.pivot = pivot;
  out.tip = {pivot.x + l * st, -l * ct};
  // A point at r (sin th, -cos th) of the beam accelerates by the pivot's plus r times this.
  const Vec2 along{ct * a[0] - st * th_d * th_d, st * a[0] + ct * th_d * th_d};
  const double base = -e.pivot_height();  // the engine's base, below the pivot's level
  out.tip_height = out.tip.y - base;
  const double c = e.beam_cm();
  out.energies.beam = (e.beam_inertia() + e.mu_b * (path.slope * path.slope + 2 * path.slope * c * ct)) * th_d * th_d / 2 - e.mu_b * c * ct;
  const BuiltParts::Sling& sling_parts = e.parts.sling;
  if (phase != Phase::released || swings_after_release()) {
    const double sp = std::sin(s.phi), cp = std::cos(s.phi), phi_d = s.phi_dot, sling = l * l4;
    out.projectile = {out.tip.x - sling * cp, out.tip.y - sling * sp};
    out.projectile_velocity = {(path.slope + l * ct) * th_d + sling * sp * phi_d, l * st * th_d - sling * cp * phi_d};
    const Vec2 tip_acceleration{pivot_acceleration.x + l * along.x, l * along.y};
    const Vec2 p_dd{tip_acceleration.x + sling * (sp * a[2] + cp * phi_d * phi_d), tip_acceleration.y + sling * (-cp * a[2] + sp * phi_d * phi_d)};
    // The sling pulls the projectile (and its pouch, `carried`) toward the tip along u = (cos
    // phi, sin phi), with a rope of mass also across it (sling.hpp), beside its weight, the air
    // and, in the trough, the trough's friction and its normal force, which holds its height.
    const double carried = phase == Phase::released ? sling_parts.pouch : mu + sling_parts.pouch;
    Vec2 on_end;
    if (phase == Phase::trough) {
      const Vec2 across = rope_mass_across(sling_parts, sling, {cp, sp}, a[2], tip_acceleration);
      out.sling_tension = (carried * p_dd.x - friction - drag.x - across.x) / cp;
      out.normal_force = carried - out.sling_tension * sp - drag.y - across.y;
      on_end = {out.sling_tension * cp + across.x, out.sling_tension * sp + across.y};
    } else {
      out.sling_tension = carried * (p_dd.x * cp + p_dd.y * sp + sp) - drag.x * cp - drag.y * sp;
      const double shear = sling_parts.any() ? (carried * p_dd.x - drag.x) * sp - (carried * (p_dd.y + 1) - drag.y) * cp : 0;
      on_end = {out.sling_tension * cp + shear * sp, out.sling_tension * sp - shear * cp};
    }
    const RopeEnds rope = rope_ends(sling_parts, {cp, sp}, on_end, tip_acceleration, p_dd, {});
    sling_at_tip(out, rope, sling_parts.any(), ct, st);
    if (phase != Phase::released) {
      const Vec2& v = out.projectile_velocity;
      out.energies.projectile_kinetic = mu * (v.x * v.x + v.y * v.y) / 2;
      out.energies.projectile_potential = mu * out.projectile.y;
    }
    if (sling_parts.any())
      out.energies.sling = sling_energy(sling_parts, sling, out.tip, {(path.slope + l * ct) * th_d, l * st * th_d}, out.projectile,
                                        out.projectile_velocity, phi_d);
  }
  // The beam of mass mu_b, its centre c along it, moves under its weight, the sling's pull, the
  // counterweight's force and the frame's.
  const Vec2 need{e.mu_b * (pivot_acceleration.x + c * along.x) - out.sling_on_tip.x, e.mu_b * (c * along.y + 1) - out.sling_on_tip.y};
  const double counterweight_moment = counterweight_forces(out, s, a[0], pivot, need, base);
  out.pivot_reaction = {out.hinge_force.x + need.x, out.hinge_force.y + need.y};
  // The short section passes the long one what turns it and the counterweight about the pivot:
  // its weight, its share of the pivot's acceleration and the counterweight's pull, less its own turn.
  if (const auto section = e.short_section())
    out.beam_moment = counterweight_moment - section->mass * section->cm * (st + ct * pivot_acceleration.x) - section->inertia * a[0];
  out.energy = out.energies.beam + out.energies.counterweight + out.energies.projectile_kinetic + out.energies.projectile_potential;
  if (sling_parts.any()) out.energy += out.energies.sling;
  return out;
}

}  // namespace trebuchet
