#include "trebuchet/dynamics.hpp"

#include <algorithm>
#include <cmath>

#include "trebuchet/angles.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/sling.hpp"

namespace trebuchet {

Dynamics::Dynamics(const ScaledDesign& design)
    : design_(design),
      theta_i_(radians(design.theta_i_deg)),
      cos_theta_i_(std::cos(theta_i_)),
      L_(design.L()),
      inertia_(design.beam_inertia()),
      inv_l_(1 / design.l),
      inv_l4_(1 / design.l4),
      inv_L_(1 / L_),
      beam_cm_(design.beam_cm()),
      dissipates_(design.parts.dissipates()) {
  const double L_psi = L_ + design.parts.counterweight_inertia / L_;  // eq:EOM_I_2 with the counterweight's own inertia
  psi_ratio_ = L_ / L_psi;
  inv_L_psi_ = 1 / L_psi;
}

double vacuum_range(Vec2 position, Vec2 velocity, double drop, double g) {
  const double flight = (velocity.y + std::sqrt(velocity.y * velocity.y + 2 * g * drop)) / g;
  return -(position.x + velocity.x * flight);
}

double Dynamics::trough_sin_phi(double theta) const { return (cos_theta_i_ - std::cos(theta)) / design_.l4; }

double Dynamics::trough_cos_phi(double theta) const {
  const double sin_phi = trough_sin_phi(theta), cos_squared = 1 - sin_phi * sin_phi;
  return cos_squared > 0 ? std::sqrt(cos_squared) : 0;
}

double Dynamics::complete_trough_state(State& s) const {
  const double sin_phi = trough_sin_phi(s.theta), cos_phi = trough_cos_phi(s.theta);
  if (!(cos_phi > 0)) return 0;
  s.phi = std::atan2(sin_phi, cos_phi);
  s.phi_dot = std::sin(s.theta) / (design_.l4 * cos_phi) * s.theta_dot;  // d/dt of eq:EOM_I_3
  return cos_phi;
}

// The constants of the equations of one design, scaled.
struct detail::Coefficients {
  double l, l4, L, mu, mu_b, I, cos_theta_i;
  double inv_l, inv_l4, inv_L;  // the equations divide by l, l4 and L at every evaluation
  double cm;  // the beam's centre of mass from the pivot, (l - 1)/2 for the uniform rod
  double psi_ratio, inv_L_psi;  // L/L_psi and 1/L_psi, L_psi = L + I_c/L: 1 and 1/L for a point counterweight
  const BuiltParts* parts;
  // The sling (sling.hpp): the point mass at its end before the release (mu, or more with the
  // sling's mass) and after it (0 unless it has mass: then it swings on, by phase II's
  // equations), the rope's share at the tip, and its inertia beyond its ends' shares.
  double end_mass, end_mass_released, tip_mass, rope_inertia;
  bool swings() const { return end_mass_released > 0; }
};

namespace {

using detail::Coefficients;

struct Accel {
  double theta, psi, phi;
};

// Sines and cosines of the three angles, one sincos each; differences by the angle-sum rules.
// In the trough phi follows from theta (eq:EOM_I_3), so its sine and cosine do too.
struct Trig {
  double st, ct, sp, cp, sf, cf;
  Trig(const Coefficients& e, Phase phase, const State& s) : st(std::sin(s.theta)), ct(std::cos(s.theta)), sp(std::sin(s.psi)), cp(std::cos(s.psi)) {
    if (phase == Phase::trough) {
      sf = (e.cos_theta_i - ct) * e.inv_l4;
      cf = std::sqrt(1 - sf * sf);
    } else {
      sf = std::sin(s.phi), cf = std::cos(s.phi);
    }
  }
};

// Generalized forces (Q_theta, Q_psi, Q_phi), scaled (M g L2): the virtual work of friction and
// drag per unit change of each angle.
using Generalized = std::array<double, 3>;

// Solves the linear system of the phase for the angular accelerations, with generalized forces
// Q on the right-hand sides. The rows are Lagrange's equations for theta, for psi divided by L
// and for phi divided by mu l l4 (appendix A), so Q enters them as Q_theta, Q_psi/L and
// Q_phi/(mu l l4). A counterweight with its own moment of inertia I_c about its centre adds
// I_c psi'' to Lagrange's equation for psi: its coefficient of psi'' becomes L_psi = L + I_c/L.
// Inlined into each caller: it is most of an evaluation of the equations, the hot path of a
// shot; without generalized forces (`forced` false) their terms are left out.
//
// A sling with mass (sling.hpp) puts the point mass `end` at the sling's end in place of mu, adds
// its rope's share at the tip to the beam (tip_mass l^2 to its inertia, tip_mass l to its weight's
// lever) and the rope's inertia beyond those, J = rope_inertia, to the sling's turn: J phi'' in
// Lagrange's equation for phi, and in the trough, where phi follows theta, J (phi_th^2 th'' +
// phi_th phi_thth th'^2) in theta's. After the release a sling with mass swings on: phase II's
// equations with its own end mass. Without, every added term is an exact 0.
template <bool forced = true>
[[gnu::always_inline]] inline Accel solve(const Coefficients& e, Phase phase, const State& s, const Trig& trig, const Generalized& Q) {
  const double I = e.I + e.tip_mass * e.l * e.l, lever = e.mu_b * e.cm + e.tip_mass * e.l;
  const double c_tp = trig.ct * trig.cp + trig.st * trig.sp, s_tp = trig.st * trig.cp - trig.ct * trig.sp;
  // eq:EOM_I_2: -cos(th - psi) th'' + L_psi psi'' = -sin(th - psi) th'^2 - sin psi + Q_psi/L
  double b2 = -s_tp * s.theta_dot * s.theta_dot - trig.sp;
  if (forced) b2 += Q[1] * e.inv_L;
  if (phase == Phase::trough || (phase == Phase::released && !e.swings())) {
    double a11 = I + 1, b1 = e.L * s_tp * s.psi_dot * s.psi_dot - (lever - 1) * trig.st;
    if (forced) b1 += Q[0];
    if (phase == Phase::trough) {  // eq:EOM_I_1 with f(th), df/dth of appendix A
      const double inv_cos_phi = 1 / trig.cf;
      const double f = (trig.ct * trig.cf + trig.st * trig.sf) * inv_cos_phi;  // cos(th - phi)/cos phi
      const double df = (-(trig.st * trig.cf - trig.ct * trig.sf) + trig.st * trig.st * e.inv_l4 * inv_cos_phi * inv_cos_phi) * inv_cos_phi;
      a11 += e.end_mass * e.l * e.l * f * f;
      b1 -= e.end_mass * e.l * e.l * f * df * s.theta_dot * s.theta_dot;
      if (e.rope_inertia != 0) {  // phi_th = sin th/(l4 cos phi), eq:EOM_I_3
        const double phi_th = trig.st * e.inv_l4 * inv_cos_phi,
                     phi_thth = (trig.ct + trig.sf * trig.st * phi_th * inv_cos_phi) * e.inv_l4 * inv_cos_phi;
        a11 += e.rope_inertia * phi_th * phi_th;
        b1 -= e.rope_inertia * phi_th * phi_thth * s.theta_dot * s.theta_dot;
      }
    }
    // [a11, -L c_tp; -c_tp, L_psi] (th'', psi'') = (b1, b2): the second row gives psi'' = (b2 + c_tp th'')/L_psi.
    const double theta_ddot = (b1 + e.psi_ratio * c_tp * b2) / (a11 - e.psi_ratio * c_tp * c_tp);
    return {theta_ddot, (b2 + c_tp * theta_ddot) * e.inv_L_psi, 0};
  }
  // Phase II: eq:EOM_II_1, eq:EOM_I_2, eq:EOM_II_3.
  const double c_tf = trig.ct * trig.cf + trig.st * trig.sf, s_tf = trig.st * trig.cf - trig.ct * trig.sf;
  const double end = phase == Phase::released ? e.end_mass_released : e.end_mass, ml2 = end * e.l * e.l;
  // eq:EOM_II_1: a11 th'' - L cos(th - psi) psi'' - m l^2 l4 sin(th - phi) phi'' = b1
  const double a11 = ml2 + I + 1;
  double b1 = e.L * s_tp * s.psi_dot * s.psi_dot - ml2 * e.l4 * c_tf * s.phi_dot * s.phi_dot - (end * e.l + lever - 1) * trig.st;
  if (forced) b1 += Q[0];
  // eq:EOM_II_3: -l sin(th - phi) th'' + l l4 phi'' = l cos(th - phi) th'^2 + cos phi + Q_phi/(mu l l4);
  // the rope's inertia J makes l4 there l4 + J/(m l^2 l4), and `ratio` l4 over that.
  double b3 = e.l * c_tf * s.theta_dot * s.theta_dot + trig.cf;
  if (forced) b3 += Q[2] / (end * e.l * e.l4);
  double ratio = 1, inv_l4_turn = e.inv_l4;  // a rope of no mass: l4 itself, and no division on the hot path
  if (e.rope_inertia != 0) {
    const double l4_turn = e.l4 + e.rope_inertia / (ml2 * e.l4);
    ratio = e.l4 / l4_turn, inv_l4_turn = 1 / l4_turn;
  }
  // psi'' = (b2 + c_tp th'')/L_psi and l4 phi'' = (b3/l + s_tf th''): substituted into the first row.
  const double theta_ddot = (b1 + e.psi_ratio * c_tp * b2 + ratio * end * e.l * s_tf * b3) /
      (a11 - e.psi_ratio * c_tp * c_tp - ratio * ml2 * s_tf * s_tf);
  return {theta_ddot, (b2 + c_tp * theta_ddot) * e.inv_L_psi, (b3 * e.inv_l + s_tf * theta_ddot) * inv_l4_turn};
}

Vec2 operator*(Vec2 v, double k) { return {v.x * k, v.y * k}; }
// |v| of the forces and speeds of a shot, which are of ordinary size: no need for hypot's care
// against overflow, which would cost a quarter of a shot with friction.
double norm(Vec2 v) { return std::sqrt(v.x * v.x + v.y * v.y); }
Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }

// How the beam's tip and the projectile move with the angles: d(position)/d(angle), scaled.
// In the trough the projectile's height is fixed and its x follows theta (eq:EOM_I_3):
// dx/dth = l cos(th - phi)/cos phi.
struct Jacobians {
  Vec2 tip_theta, projectile_theta, projectile_phi;
  Jacobians(const Coefficients& e, Phase phase, const Trig& t)
      : tip_theta{e.l * t.ct, e.l * t.st}, projectile_theta(tip_theta), projectile_phi{e.l * e.l4 * t.sf, -e.l * e.l4 * t.cf} {
    if (phase == Phase::trough) projectile_theta = {e.l * (t.ct * t.cf + t.st * t.sf) / t.cf, 0}, projectile_phi = {0, 0};
  }
};

// The air before the release (BuiltParts::drag): on the projectile, quadratic drag as in its
// flight (air.hpp); on the sling's rope, taken straight from the tip to the projectile, the drag
// of a cylinder across the flow, per length rope_drag |u_n| u_n against u_n, the air's velocity
// relative to the rope and normal to it. The rope's drag is summed by 5-point Gauss-Legendre
// quadrature along it; its power is summed the same way, so the balance of energy is exact
// whatever the quadrature's error in the force.
struct AirForces {
  Vec2 on_projectile, on_rope;  // the total on the rope
  // The rope, a straight massless link pinned at both ends, passes each piece's load across it to
  // its ends by the lever rule: the share a at the projectile (a = 0 at the tip, 1 there).
  Vec2 rope_at_projectile;
  Generalized Q{};
  double projectile_power = 0, rope_power = 0;  // the work the air does per time (< 0: it brakes)
};

AirForces air_forces(const Coefficients& e, Phase phase, const State& s, const Trig& t, const Jacobians& j) {
  AirForces out;
  const std::optional<Drag>& drag = e.parts->drag;
  if (!drag || phase == Phase::released) return out;
  const double phi_dot = phase == Phase::lifted ? s.phi_dot : 0;  // in the trough x follows theta alone
  const Vec2 tip_velocity = j.tip_theta * s.theta_dot;
  const Vec2 projectile_velocity = j.projectile_theta * s.theta_dot + j.projectile_phi * phi_dot;
  const Vec2 wind{drag->wind, 0};  // the air moves toward -x: u = v + wind x^ (air.hpp)
  const Vec2 u = projectile_velocity + wind;
  const double speed = norm(u);
  out.on_projectile = u * (-e.mu * drag->coefficient_at(speed) * drag->per_length * speed);
  out.Q[0] = dot(out.on_projectile, j.projectile_theta);
  out.Q[2] = dot(out.on_projectile, j.projectile_phi);
  out.projectile_power = dot(out.on_projectile, projectile_velocity);
  if (!(e.parts->rope_drag > 0)) return out;
  const Vec2 along{-t.cf, -t.sf};  // unit vector from the tip to the projectile
  const double length = e.l * e.l4;
  constexpr double node[5] = {0.046910077030668, 0.230765344947158, 0.5, 0.769234655052842, 0.953089922969332};  // on [0, 1]
  constexpr double weight[5] = {0.118463442528095, 0.239314335249683, 0.284444444444444, 0.239314335249683, 0.118463442528095};
  for (int k = 0; k < 5; ++k) {
    const double a = node[k];
    const Vec2 v = tip_velocity * (1 - a) + projectile_velocity * a;
    const Vec2 rel = v + wind;
    const Vec2 normal = rel + along * (-dot(rel, along));
    const Vec2 force = normal * (-e.parts->rope_drag * norm(normal) * weight[k] * length);
    out.on_rope = out.on_rope + force;
    out.rope_at_projectile = out.rope_at_projectile + force * a;
    out.Q[0] += dot(force, j.tip_theta * (1 - a) + j.projectile_theta * a);
    out.Q[2] += dot(force, j.projectile_phi * a);
    out.rope_power += dot(force, v);
  }
  return out;
}

// The forces between the bodies at given accelerations (Newton's laws for each body).
struct Internal {
  Vec2 hinge_force;  // F_H, on the counterweight
  Vec2 sling_on_projectile;  // the sling's pull on the projectile and its pouch
  RopeEnds rope;  // the rope's pull on the beam's tip, and its ends' tension and shear
  Vec2 pivot_reaction;  // F_R, on the beam
  double normal_force = 0;  // trough on projectile (phase I)
  double trough_friction = 0;  // along x on the projectile (phase I)
  Vec2 projectile_acceleration;
  double phi_ddot = 0;
};

double sign(double x) { return (x > 0) - (x < 0); }

[[gnu::always_inline]] inline Internal internal_forces(const Coefficients& e, Phase phase, const State& s, const Trig& trig, const Accel& a,
                                                       const AirForces& air) {
  Internal out;
  const double st = trig.st, ct = trig.ct, sp = trig.sp, cp = trig.cp, sf = trig.sf, cf = trig.cf;
  const double td = s.theta_dot, pd = s.psi_dot, fd = s.phi_dot;
  // Counterweight (mass 1): a = F_H + g, g = (0, -1).
  const Vec2 cw_acc{-ct * a.theta + st * td * td + e.L * (cp * a.psi - sp * pd * pd),
                    -st * a.theta - ct * td * td + e.L * (sp * a.psi + cp * pd * pd)};
  out.hinge_force = {cw_acc.x, cw_acc.y + 1};
  // Projectile; in phase I phi follows eq:EOM_I_3.
  out.phi_ddot = a.phi;
  if (phase == Phase::trough)  // second derivative of eq:EOM_I_3: l4 (cos phi phi'' - sin phi phi'^2) = cos th th'^2 + sin th th''
    out.phi_ddot = (ct * td * td + st * a.theta + e.l4 * sf * fd * fd) / (e.l4 * cf);
  out.projectile_acceleration = {e.l * (-st * td * td + ct * a.theta + e.l4 * (cf * fd * fd + sf * out.phi_ddot)),
                                 e.l * (ct * td * td + st * a.theta + e.l4 * (sf * fd * fd - cf * out.phi_ddot))};
  const Vec2& p_acc = out.projectile_acceleration;
  const Vec2 tip_acc{e.l * (ct * a.theta - st * td * td), e.l * (st * a.theta + ct * td * td)};
  const BuiltParts::Sling& sling = e.parts->sling;
  // What the sling's end carries: the projectile and the pouch until the release, the pouch after.
  const double carried = phase == Phase::released ? sling.pouch : e.mu + sling.pouch;
  if (phase == Phase::trough) {
    // The sling pulls with its tension T along it and, with the rope's drag, its share P across
    // it. Along x: mu a_x = T cos phi + P_x + friction + drag; along y (a_y = 0; the drag on the
    // stone is horizontal here): 0 = T sin phi + P_y + N - mu. Friction -mu_t sgn(v_x) N, so
    // T (cos phi + mu_t sgn(v_x) sin phi) = mu a_x - drag_x - P_x + mu_t sgn(v_x) (mu - P_y).
    const double slide = e.parts->trough_friction * sign(s.theta_dot * (ct * cf + st * sf));  // v_x = l cos(th - phi)/cos phi th'
    const Vec2 across = air.rope_at_projectile + rope_mass_across(sling, e.l * e.l4, {cf, sf}, out.phi_ddot, tip_acc);
    const double tension = (carried * p_acc.x - air.on_projectile.x - across.x + slide * (carried - across.y)) / (cf + slide * sf);
    out.sling_on_projectile = {tension * cf + across.x, tension * sf + across.y};
    out.normal_force = carried - tension * sf - across.y;
    out.trough_friction = -slide * out.normal_force;
  } else if (phase == Phase::lifted || e.swings()) {
    out.sling_on_projectile = {carried * p_acc.x - air.on_projectile.x, carried * (p_acc.y + 1) - air.on_projectile.y};
  }
  // The rope passes on what pulls its ends, what the air puts on it and what its own mass needs.
  out.rope = rope_ends(sling, {cf, sf}, out.sling_on_projectile, tip_acc, p_acc, air.on_rope);
  const Vec2& on_tip = out.rope.on_tip;
  // Beam (mass mu_b): mu_b a_CM = F_R - F_H (arm on beam) + sling on tip + mu_b g.
  const Vec2 cm_acc{e.cm * (ct * a.theta - st * td * td), e.cm * (st * a.theta + ct * td * td)};
  out.pivot_reaction = {e.mu_b * cm_acc.x + out.hinge_force.x - on_tip.x, e.mu_b * (cm_acc.y + 1) + out.hinge_force.y - on_tip.y};
  return out;
}

// Coulomb friction at the pins and in the trough at a state: the axle's torque mu r |F_R|
// against th', the hinge pin's mu r |F_H| against the arm's turn relative to the beam, psi' - th'
// (the same torque turned back on the beam), and the trough's force on the projectile, through
// dx/dth. Each generalized force is a factor of the state times what the pin or trough carries.
struct FrictionLaw {
  double axle, hinge, trough;  // -mu r sgn(th'), -mu r sgn(psi' - th'), dx/dth in phase I (else 0)
  FrictionLaw(const Coefficients& e, Phase phase, const State& s, const Jacobians& j)
      : axle(-e.parts->axle_friction * sign(s.theta_dot)),
        hinge(-e.parts->hinge_friction * sign(s.psi_dot - s.theta_dot)),
        trough(phase == Phase::trough ? j.projectile_theta.x : 0) {}
  // (Q_theta, Q_psi, Q_phi) of the forces the pins and the trough carry.
  Generalized forces(Vec2 pivot_reaction, Vec2 hinge_force, double trough_friction) const {
    const double a = axle * norm(pivot_reaction), h = hinge * norm(hinge_force);
    return {a - h + trough * trough_friction, h, 0};
  }
  // The power each takes out of the bodies.
  void losses(const State& s, const Internal& f, Losses& loss) const {
    loss[axle_loss] = -axle * norm(f.pivot_reaction) * s.theta_dot;
    loss[hinge_loss] = -hinge * norm(f.hinge_force) * (s.psi_dot - s.theta_dot);
    loss[trough_loss] = -trough * f.trough_friction * s.theta_dot;
  }
};

// The friction's generalized forces depend on the forces the pins and the trough carry, and those
// on the accelerations the friction changes: Q = friction(forces(solve(Q))). The accelerations
// are affine in Q (solve is linear in its right-hand side) and so are the forces (Newton's laws,
// and the trough's closed form with the state's sign of sliding): three solves give them exactly
// as F0 + G Q. The friction of that affine model, a function of (Q_theta, Q_psi) through |F_R|,
// |F_H| and N alone, is then solved by Newton's method with its exact Jacobian (d|F|/dQ =
// F . G/|F|), to a residual below 1e-14 (1 + |Q|) in M g L2: round-off. The trough's friction
// alone is affine and one step solves it; the pins' |F| is smooth, and two or three steps do. A
// fourth solve gives the accelerations. Where no Q exists or it is not unique (a large
// coefficient near a sling standing upright in the trough: Painleve's paradox), the iteration
// fails and the shot says so (unsettled_friction).
constexpr int max_newton_steps = 30;

struct Evaluation {
  Accel a;
  AirForces air;
  Internal forces;  // at a
};

bool evaluate(const Coefficients& e, Phase phase, const State& s, const Trig& trig, Evaluation& out, Losses* loss) {
  const BuiltParts& p = *e.parts;
  const bool friction = p.axle_friction > 0 || p.hinge_friction > 0 || (phase == Phase::trough && p.trough_friction > 0);
  if (loss) *loss = Losses{};
  if (!friction && !p.drag) {  // appendix A
    out.a = solve<false>(e, phase, s, trig, Generalized{});
    out.forces = internal_forces(e, phase, s, trig, out.a, out.air);
    return true;
  }
  const Jacobians j(e, phase, trig);
  out.air = air_forces(e, phase, s, trig, j);
  const auto forces_for = [&](double q_theta, double q_psi) {
    Generalized total = out.air.Q;
    total[0] += q_theta, total[1] += q_psi;
    return internal_forces(e, phase, s, trig, solve(e, phase, s, trig, total), out.air);
  };
  double q0 = 0, q1 = 0;
  if (friction) {
    // The affine model of the forces friction depends on: at Q = 0 and one unit along each.
    const Internal f0 = forces_for(0, 0), f_theta = forces_for(1, 0), f_psi = forces_for(0, 1);
    const FrictionLaw law(e, phase, s, j);
    const Vec2 pivot_theta = f_theta.pivot_reaction - f0.pivot_reaction, pivot_psi = f_psi.pivot_reaction - f0.pivot_reaction;
    const Vec2 hinge_theta = f_theta.hinge_force - f0.hinge_force, hinge_psi = f_psi.hinge_force - f0.hinge_force;
    const double trough_theta = f_theta.trough_friction - f0.trough_friction, trough_psi = f_psi.trough_friction - f0.trough_friction;
    bool settled = false;
    for (int step = 0; step < max_newton_steps && !settled; ++step) {
      const Vec2 pivot = f0.pivot_reaction + pivot_theta * q0 + pivot_psi * q1, hinge = f0.hinge_force + hinge_theta * q0 + hinge_psi * q1;
      const Generalized f = law.forces(pivot, hinge, f0.trough_friction + trough_theta * q0 + trough_psi * q1);
      const double r0 = f[0] - q0, r1 = f[1] - q1;
      if (!(std::isfinite(r0) && std::isfinite(r1))) return false;
      if (std::max(std::abs(r0), std::abs(r1)) <= 1e-14 * (1 + std::max(std::abs(q0), std::abs(q1)))) {
        settled = true;
        break;
      }
      // The Jacobian of the residual, exact: d|F|/dq = F . dF/dq / |F|.
      const double n_pivot = norm(pivot), n_hinge = norm(hinge);
      const double da0 = n_pivot > 0 ? law.axle * dot(pivot, pivot_theta) / n_pivot : 0,
                   da1 = n_pivot > 0 ? law.axle * dot(pivot, pivot_psi) / n_pivot : 0;
      const double dh0 = n_hinge > 0 ? law.hinge * dot(hinge, hinge_theta) / n_hinge : 0,
                   dh1 = n_hinge > 0 ? law.hinge * dot(hinge, hinge_psi) / n_hinge : 0;
      const double j00 = da0 - dh0 + law.trough * trough_theta - 1, j01 = da1 - dh1 + law.trough * trough_psi, j10 = dh0, j11 = dh1 - 1;
      const double det = j00 * j11 - j01 * j10;
      if (!(std::abs(det) > 1e-12)) return false;
      q0 -= (j11 * r0 - j01 * r1) / det;
      q1 -= (-j10 * r0 + j00 * r1) / det;
    }
    if (!settled) return false;
  }
  Generalized total = out.air.Q;
  total[0] += q0, total[1] += q1;
  out.a = solve(e, phase, s, trig, total);
  out.forces = internal_forces(e, phase, s, trig, out.a, out.air);
  if (loss) {
    if (friction) FrictionLaw(e, phase, s, j).losses(s, out.forces, *loss);
    (*loss)[projectile_drag_loss] = -out.air.projectile_power;
    (*loss)[rope_drag_loss] = -out.air.rope_power;
  }
  return true;
}

}  // namespace

detail::Coefficients Dynamics::coefficients() const {
  const BuiltParts::Sling& sling = design_.parts.sling;
  return {design_.l,
          design_.l4,
          L_,
          design_.mu,
          design_.mu_b,
          inertia_,
          cos_theta_i_,
          inv_l_,
          inv_l4_,
          inv_L_,
          beam_cm_,
          psi_ratio_,
          inv_L_psi_,
          &design_.parts,
          sling.end_mass(design_.mu),
          sling.end_mass(0),
          sling.tip_mass(),
          sling.inertia_beyond(design_.l * design_.l4)};
}

Evaluated Dynamics::accelerations(Phase phase, const State& state, std::array<double, 3>& out, Losses* loss_power) const {
  const Coefficients e = coefficients();
  const Trig trig(e, phase, state);  // in the trough, cos phi from theta's own cosine (eq:EOM_I_3)
  if (phase == Phase::trough && !(trig.cf > refuse_trough_cos_phi)) return Evaluated::near_trough_singularity;
  if (!dissipates_ && !loss_power) {  // appendix A: one solve
    const Accel a = solve<false>(e, phase, state, trig, Generalized{});
    out = {a.theta, a.psi, a.phi};
    return Evaluated::found;
  }
  // The forces that friction depends on need phi' in the trough (eq:EOM_I_3).
  State full = state;
  if (phase == Phase::trough) complete_trough_state(full);
  Evaluation ev;
  if (!evaluate(e, phase, full, trig, ev, loss_power)) return Evaluated::failed;
  out = {ev.a.theta, ev.a.psi, ev.a.phi};
  return Evaluated::found;
}

Vec2 air_force(const Drag& drag, double mass, Vec2 velocity) {
  const Vec2 u{velocity.x + drag.wind, velocity.y};  // the air moves toward -x (air.hpp)
  const double speed = std::hypot(u.x, u.y), factor = -mass * drag.coefficient_at(speed) * drag.per_length * speed;
  return {factor * u.x, factor * u.y};
}

double short_section_moment(const BuiltParts::Section& section, double theta, Vec2 hinge_force, double theta_ddot) {
  const double st = std::sin(theta), ct = std::cos(theta);
  return st * hinge_force.y + ct * hinge_force.x - section.mass * section.cm * st - section.inertia * theta_ddot;
}

Snapshot Dynamics::snapshot(Phase phase, const State& s) const {
  const Coefficients e = coefficients();
  const Trig trig(e, phase, s);
  Evaluation ev;
  Snapshot out;
  if (!dissipates_) {  // appendix A
    ev.a = solve<false>(e, phase, s, trig, Generalized{});
    ev.forces = internal_forces(e, phase, s, trig, ev.a, ev.air);
  } else if (!evaluate(e, phase, s, trig, ev, &out.loss_power)) {
    throw Error(ErrorKind::numerical, unsettled_friction);
  }
  const Accel& a = ev.a;
  const Internal& f = ev.forces;
  out.theta_ddot = a.theta;
  out.psi_ddot = a.psi;
  out.phi_ddot = a.phi;
  const double st = trig.st, ct = trig.ct, sp = trig.sp, cp = trig.cp, sf = trig.sf, cf = trig.cf;
  const double td = s.theta_dot, pd = s.psi_dot, fd = s.phi_dot;
  out.hinge_force = f.hinge_force;
  out.projectile = {e.l * (st - e.l4 * cf), e.l * (-ct - e.l4 * sf)};
  out.projectile_velocity = {e.l * (ct * td + e.l4 * sf * fd), e.l * (st * td - e.l4 * cf * fd)};
  out.normal_force = f.normal_force;
  // The sling runs from the projectile to the tip along (cos phi, sin phi): its tension is the
  // pull on the projectile along it (the rope's drag adds a share across it); a sling can pull
  // but not push.
  out.sling_tension = f.sling_on_projectile.x * cf + f.sling_on_projectile.y * sf;
  sling_at_tip(out, f.rope, design_.parts.sling.any(), ct, st);
  // Positions of the hinge, the counterweight and the tip (dynamics.hpp), and heights above the
  // engine's base, which lies l cos(theta_i) below the pivot (H = L1 cos theta_i).
  out.hinge = {-st, ct};
  out.counterweight = {-st + e.L * sp, ct - e.L * cp};
  out.tip = {e.l * st, -e.l * ct};
  const double base = -design_.pivot_height();
  out.counterweight_height = out.counterweight.y - base;
  out.tip_height = out.tip.y - base;
  out.pivot_reaction = f.pivot_reaction;

  // The short section (pivot to hinge) turns about the pivot: I_s th'' = moment of the arm's pull
  // at the hinge (-F_H) + its weight at its centre + the hinge pin's friction on the beam - the
  // moment the long section takes. For the uniform rod, mass mu_b/(l + 1) per L2, centre 1/2
  // toward the hinge, I_s a third of its mass. The axle's friction acts at the pivot itself: the
  // moment is the one on the short section's side. tests/test_shot.cpp checks the long section's
  // own balance against it. A beam given only as a whole has no known short section: 0.
  if (const auto section = design_.short_section()) {
    out.beam_moment = short_section_moment(*section, s.theta, out.hinge_force, a.theta);
    if (design_.parts.hinge_friction > 0) out.beam_moment += design_.parts.hinge_friction * norm(f.hinge_force) * sign(pd - td);
  }

  // Energy of each body, potential from the pivot's level: beam rotation, counterweight (its
  // centre's motion and its own turn), projectile (on the trough in phase I, absent in III).
  const double I = e.I;
  out.energies.beam = 0.5 * I * td * td - e.mu_b * e.cm * ct;
  out.energies.counterweight = 0.5 * (td * td + e.L * e.L * pd * pd - 2 * e.L * (ct * cp + st * sp) * td * pd) +
      out.counterweight.y;  // cos(th - psi)
  if (design_.parts.counterweight_inertia > 0) out.energies.counterweight += 0.5 * design_.parts.counterweight_inertia * pd * pd;
  if (phase != Phase::released) {
    const Vec2& v = out.projectile_velocity;
    out.energies.projectile_kinetic = 0.5 * e.mu * (v.x * v.x + v.y * v.y);
    out.energies.projectile_potential = e.mu * out.projectile.y;
  }
  out.energy = out.energies.beam + out.energies.counterweight + out.energies.projectile_kinetic + out.energies.projectile_potential;
  if (design_.parts.sling.any()) {
    out.energies.sling = sling_energy(design_.parts.sling, e.l * e.l4, out.tip, {e.l * ct * td, e.l * st * td}, out.projectile,
                                      out.projectile_velocity, fd);
    out.energy += out.energies.sling;
  }
  return out;
}

}  // namespace trebuchet
