#include "trebuchet/whipper.hpp"

#include <cmath>

#include "trebuchet/angles.hpp"
#include "trebuchet/dynamics.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/sling.hpp"

namespace trebuchet {
namespace {

// The force f split along two directions: f = p u + q n.
std::array<double, 2> split(Vec2 f, Vec2 u, Vec2 n) {
  const double det = u.x * n.y - u.y * n.x;
  return {(f.x * n.y - f.y * n.x) / det, (u.x * f.y - u.y * f.x) / det};
}

}  // namespace

Whipper::Whipper(const ScaledDesign& design) : design_(design), theta_i_(radians(design.theta_i_deg)) {
  if (design.parts.trough_friction > 0)
    throw Error(ErrorKind::usage, "the whipper has no trough: its projectile rests on the arm; leave out {{trough_friction}}");
  if (design.parts.sling.any())
    throw Error(ErrorKind::usage,
                "the whipper's sling has no mass yet: its folded start is not built for a rope of mass; leave out {{rope_mass}} and {{pouch_mass}}");
  if (design.parts.rope_drag > 0) throw Error(ErrorKind::usage, "the whipper takes no drag on the sling's rope yet; leave out {{rope_diameter}}");
  design_.machine = MachineKind::whipper;
  L_ = design_.L();
  c_ = design_.beam_cm();
  I_b_ = design_.beam_inertia();
  weight_ = 1 - design_.mu_b * c_;
  // Folded back from the tip toward the pivot, the sling lies along the long arm, phi = theta -
  // pi/2 by the positions of dynamics.hpp; the ball of radius r touching the arm turns it by
  // asin(r/(r + L4)) to the arm's upper side.
  const double sling = design_.l * design_.l4;
  phi_i_ = theta_i_ - M_PI / 2 + std::asin(design_.projectile_radius / (design_.projectile_radius + sling));
}

double Whipper::turn_limit(Phase) const { return theta_i_ + 4 * M_PI; }

double Whipper::complete_trough_state(State& s) const {
  s.phi = s.theta + (phi_i_ - theta_i_);
  s.phi_dot = s.theta_dot;
  return 1;
}

// The mass matrix M = [[A, b, k], [b, d, 0], [k, 0, e]] and r of whipper.hpp; phase III drops the
// projectile (mu = 0). Each phase solves it on its own coordinates: held, q = theta (1, 1, 1);
// phase I, q = (theta, psi, theta); phase II, all three; phase III, (theta, psi).
Whipper::Motion Whipper::motion(Phase phase, const State& s, const Generalized& extra) const {
  const ScaledDesign& e = design_;
  const double mu = phase == Phase::released ? 0 : e.mu, l = e.l, l4 = e.l4, L = L_;
  const double th = s.theta, ps = s.psi, ph = s.phi, td = s.theta_dot, pd = s.psi_dot, fd = s.phi_dot;
  const double s_tp = std::sin(th - ps), c_tp = std::cos(th - ps), s_ft = std::sin(ph - th), c_ft = std::cos(ph - th);
  const double A = I_b_ + 1 + mu * l * l, b = -L * c_tp, d = L * L + e.parts.counterweight_inertia, k = mu * l * l * l4 * s_ft,
               E = mu * l * l * l4 * l4;
  const double r1 = L * s_tp * pd * pd - mu * l * l * l4 * c_ft * fd * fd + (weight_ - mu * l) * std::sin(th) + extra[0];
  const double r2 = -L * s_tp * td * td - L * std::sin(ps) + extra[1];
  const double r3 = mu * l * l * l4 * c_ft * td * td + mu * l * l4 * std::cos(ph) + extra[2];
  Motion m;
  if (phase == Phase::released) {
    const double th_dd = (r1 - b * r2 / d) / (A - b * b / d);
    m.a = m.free = {th_dd, (r2 - b * th_dd) / d, 0};
    return m;
  }
  // Rows psi and phi give psi'' and phi'' from theta''; row theta then gives theta''.
  const double th_free = (r1 - b * r2 / d - k * r3 / E) / (A - b * b / d - k * k / E);
  m.free = {th_free, (r2 - b * th_free) / d, (r3 - k * th_free) / E};
  if (phase == Phase::lifted) {
    m.a = m.free;
  } else if (phase == Phase::trough) {  // phi'' = theta'': rows theta and phi add
    const double th_dd = (r1 + r3 - b * r2 / d) / (A + 2 * k + E - b * b / d);
    m.a = {th_dd, (r2 - b * th_dd) / d, th_dd};
  } else {  // held: psi'' = phi'' = theta'', all rows add
    const double th_dd = (r1 + r2 + r3) / (A + d + E + 2 * (b + k));
    m.a = {th_dd, th_dd, th_dd};
  }
  return m;
}

Snapshot Whipper::snapshot_with(Phase phase, const State& s, const Motion& m, Vec2 drag) const {
  const ScaledDesign& e = design_;
  const double l = e.l, sling = l * e.l4, L = L_, mu = e.mu;
  const double th = s.theta, ps = s.psi, ph = s.phi, td = s.theta_dot, pd = s.psi_dot, fd = s.phi_dot;
  const double st = std::sin(th), ct = std::cos(th), sp = std::sin(ps), cp = std::cos(ps), sf = std::sin(ph), cf = std::cos(ph);
  const auto& a = m.a;
  Snapshot out;
  out.theta_ddot = a[0], out.psi_ddot = a[1], out.phi_ddot = a[2];
  // Positions (dynamics.hpp) and heights above the base, H below the pivot.
  out.hinge = {-st, ct};
  out.counterweight = {-st + L * sp, ct - L * cp};
  out.tip = {l * st, -l * ct};
  const double base = -e.pivot_height();
  out.counterweight_height = out.counterweight.y - base;
  out.tip_height = out.tip.y - base;
  // Accelerations of the beam's points along it (per unit of length), the counterweight and the
  // projectile, and the arm's upper normal, which the resting bodies press on.
  const Vec2 along{ct * a[0] - st * td * td, st * a[0] + ct * td * td};
  const Vec2 cw_acceleration{-along.x + L * (cp * a[1] - sp * pd * pd), -along.y + L * (sp * a[1] + cp * pd * pd)};
  const Vec2 upper{-ct, -st};
  // The counterweight: its rope pulls it toward the hinge along (-sin psi, cos psi); in phase held
  // the arm pushes it along its upper normal too.
  const Vec2 cw_force{cw_acceleration.x, cw_acceleration.y + 1};  // all but its weight
  const Vec2 rope{-sp, cp};
  if (phase == Phase::held) {
    const auto [pull, push] = split(cw_force, rope, upper);
    out.hinge_force = {pull * rope.x, pull * rope.y};
    out.counterweight_on_arm = m.free[1] - m.free[0];
    out.counterweight_push = push;
  } else {
    out.hinge_force = cw_force;
  }
  Vec2 projectile_force{};  // all the projectile takes but its weight (0 once released)
  if (phase != Phase::released) {
    out.projectile = {out.tip.x - sling * cf, out.tip.y - sling * sf};
    out.projectile_velocity = {l * ct * td + sling * sf * fd, l * st * td - sling * cf * fd};
    const Vec2 p_dd{l * along.x + sling * (sf * a[2] + cf * fd * fd), l * along.y + sling * (-cf * a[2] + sf * fd * fd)};
    projectile_force = {mu * p_dd.x, mu * (p_dd.y + 1)};
    // The sling pulls it toward the tip along u = (cos phi, sin phi), the air pushes; on the arm,
    // the arm pushes it along its upper normal.
    const Vec2 u{cf, sf}, rest{projectile_force.x - drag.x, projectile_force.y - drag.y};
    if (phase == Phase::lifted) {
      out.sling_tension = dot(rest, u);
    } else {
      const auto [pull, push] = split(rest, u, upper);
      out.sling_tension = pull, out.normal_force = push;
    }
    sling_at_tip(out, RopeEnds{{-out.sling_tension * cf, -out.sling_tension * sf}}, false, ct, st);  // its sling has no mass
    const Vec2& v = out.projectile_velocity;
    out.energies.projectile_kinetic = mu * dot(v, v) / 2;
    out.energies.projectile_potential = mu * out.projectile.y;
  }
  // The frame holds the whole at the pivot: it gives each body all it takes but its weight and
  // the air's push (the counterweight's, in phase held, through the rope and the arm alike).
  out.pivot_reaction = {cw_force.x + projectile_force.x - drag.x + e.mu_b * c_ * along.x,
                        cw_force.y + projectile_force.y - drag.y + e.mu_b * (c_ * along.y + 1)};
  if (const auto section = e.short_section()) out.beam_moment = short_section_moment(*section, th, out.hinge_force, a[0]);
  const double I_c = e.parts.counterweight_inertia;
  out.energies.beam = I_b_ * td * td / 2 - e.mu_b * c_ * ct;
  out.energies.counterweight = (td * td + L * L * pd * pd - 2 * L * std::cos(th - ps) * td * pd + I_c * pd * pd) / 2 + out.counterweight.y;
  out.energy = out.energies.beam + out.energies.counterweight + out.energies.projectile_kinetic + out.energies.projectile_potential;
  return out;
}

Evaluated Whipper::accelerations(Phase phase, const State& given, std::array<double, 3>& out, Losses* loss_power) const {
  State s = given;
  if (phase == Phase::held || phase == Phase::trough) complete_trough_state(s);
  if (!dissipates()) {
    out = motion(phase, s, {}).a;
  } else {
    const std::optional<Snapshot> snap = resisted(phase, s);
    if (!snap) return Evaluated::failed;
    out = {snap->theta_ddot, snap->psi_ddot, snap->phi_ddot};
    if (loss_power) *loss_power = snap->loss_power;
  }
  return std::isfinite(out[0]) && std::isfinite(out[1]) && std::isfinite(out[2]) ? Evaluated::found : Evaluated::failed;
}

Snapshot Whipper::snapshot(Phase phase, const State& given) const {
  State s = given;
  if (phase == Phase::held || phase == Phase::trough) complete_trough_state(s);
  if (!dissipates()) return snapshot_with(phase, s, motion(phase, s, {}), {});
  const std::optional<Snapshot> out = resisted(phase, s);
  if (!out) throw Error(ErrorKind::numerical, unsettled_friction);
  return *out;
}

// The air's drag on the projectile, -mu Cd k |u| u with u its velocity through the air (air.hpp),
// acts on theta and phi through the projectile's position; Coulomb's friction at the axle against
// the beam's turn, and at the hinge pin against the counterweight's turn relative to the beam,
// each takes the force its pin carries, which depends on the accelerations: a fixed point.
std::optional<Snapshot> Whipper::resisted(Phase phase, const State& s) const {
  const BuiltParts& parts = design_.parts;
  const double l = design_.l, sling = l * design_.l4, th = s.theta;
  const Vec2 p_th{l * std::cos(th), l * std::sin(th)}, p_phi{sling * std::sin(s.phi), -sling * std::cos(s.phi)};
  Vec2 drag{}, v{};
  if (parts.drag && phase != Phase::released) {
    v = {p_th.x * s.theta_dot + p_phi.x * s.phi_dot, p_th.y * s.theta_dot + p_phi.y * s.phi_dot};
    drag = air_force(*parts.drag, design_.mu, v);
  }
  const Generalized air{dot(drag, p_th), 0, dot(drag, p_phi)};
  const double axle_turn = (s.theta_dot > 0) - (s.theta_dot < 0);
  Motion m = motion(phase, s, air);
  // The pin's friction opposes its turn, or the turn it starts: riding on the arm the weight
  // presses toward it (psi'' - theta'' > 0 were it free), so that leaving it turns the pin back,
  // and the friction holds it on until the drive beats it (the free motion of phase held, which
  // its rigid turn does not feel: the torque acts within it); at rest on its pin, the way the
  // frictionless motion would turn it.
  const double swing = s.psi_dot - s.theta_dot, drive = m.a[1] - m.a[0];
  const double hinge_turn = phase == Phase::held ? -1 : swing != 0 ? (swing > 0) - (swing < 0) : (drive > 0) - (drive < 0);
  for (int round = 0; round < 60; ++round) {
    Snapshot snap = snapshot_with(phase, s, m, drag);
    const double axle = parts.axle_friction * std::hypot(snap.pivot_reaction.x, snap.pivot_reaction.y);
    const double pin = parts.hinge_friction * std::hypot(snap.hinge_force.x, snap.hinge_force.y);
    Generalized q = air;
    q[0] += -axle * axle_turn + pin * hinge_turn;
    q[1] += -pin * hinge_turn;
    const Motion next = motion(phase, s, q);
    bool settled = true;
    for (int i = 0; i < 3; ++i) settled = settled && std::abs(next.a[i] - m.a[i]) <= 1e-14 * (1 + std::abs(m.a[i]));
    m = next;
    if (settled) {
      snap = snapshot_with(phase, s, m, drag);
      snap.loss_power[axle_loss] = axle * std::abs(s.theta_dot);
      snap.loss_power[hinge_loss] = pin * std::abs(hinge_turn * swing);
      snap.loss_power[projectile_drag_loss] = -dot(drag, v);
      if (design_.short_section() && phase != Phase::held)
        snap.beam_moment += pin * hinge_turn;  // the pin's friction turns the short section with the swing
      return snap;
    }
  }
  return std::nullopt;
}

}  // namespace trebuchet
