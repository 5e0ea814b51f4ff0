#include "trebuchet/dynamics.hpp"

#include <cmath>

#include "trebuchet/angles.hpp"

namespace trebuchet {

Dynamics::Dynamics(const ScaledDesign& design)
    : design_(design), theta_i_(radians(design.theta_i_deg)), cos_theta_i_(std::cos(theta_i_)), L_(design.L()),
      inertia_(design.beam_inertia()), inv_l_(1 / design.l), inv_l4_(1 / design.l4), inv_L_(1 / L_) {}

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

namespace {

struct Accel {
  double theta, psi, phi;
};

// The constants of the equations of one design, scaled.
struct Coefficients {
  double l, l4, L, mu, mu_b, I, cos_theta_i;
  double inv_l, inv_l4, inv_L;  // the equations divide by l, l4 and L at every evaluation
};

// Sines and cosines of the three angles, one sincos each; differences by the angle-sum rules.
// In the trough phi follows from theta (eq:EOM_I_3), so its sine and cosine do too.
struct Trig {
  double st, ct, sp, cp, sf, cf;
  Trig(const Coefficients& e, Phase phase, const State& s)
      : st(std::sin(s.theta)), ct(std::cos(s.theta)), sp(std::sin(s.psi)), cp(std::cos(s.psi)) {
    if (phase == Phase::trough) {
      sf = (e.cos_theta_i - ct) * e.inv_l4;
      cf = std::sqrt(1 - sf * sf);
    } else {
      sf = std::sin(s.phi), cf = std::cos(s.phi);
    }
  }
};

// Solves the linear system of the phase for the angular accelerations.
Accel solve(const Coefficients& e, Phase phase, const State& s, const Trig& trig) {
  const double I = e.I;
  const double c_tp = trig.ct * trig.cp + trig.st * trig.sp, s_tp = trig.st * trig.cp - trig.ct * trig.sp;
  // eq:EOM_I_2: -cos(th - psi) th'' + L psi'' = -sin(th - psi) th'^2 - sin psi
  const double b2 = -s_tp * s.theta_dot * s.theta_dot - trig.sp;
  if (phase == Phase::trough || phase == Phase::released) {
    double a11 = I + 1, b1 = e.L * s_tp * s.psi_dot * s.psi_dot - (e.mu_b / 2 * (e.l - 1) - 1) * trig.st;
    if (phase == Phase::trough) {  // eq:EOM_I_1 with f(th), df/dth of appendix A
      const double inv_cos_phi = 1 / trig.cf;
      const double f = (trig.ct * trig.cf + trig.st * trig.sf) * inv_cos_phi;  // cos(th - phi)/cos phi
      const double df = (-(trig.st * trig.cf - trig.ct * trig.sf) + trig.st * trig.st * e.inv_l4 * inv_cos_phi * inv_cos_phi) * inv_cos_phi;
      a11 += e.mu * e.l * e.l * f * f;
      b1 -= e.mu * e.l * e.l * f * df * s.theta_dot * s.theta_dot;
    }
    // [a11, -L c_tp; -c_tp, L] (th'', psi'') = (b1, b2): the second row gives psi'' = (b2 + c_tp th'')/L.
    const double theta_ddot = (b1 + c_tp * b2) / (a11 - c_tp * c_tp);
    return {theta_ddot, (b2 + c_tp * theta_ddot) * e.inv_L, 0};
  }
  // Phase II: eq:EOM_II_1, eq:EOM_I_2, eq:EOM_II_3.
  const double c_tf = trig.ct * trig.cf + trig.st * trig.sf, s_tf = trig.st * trig.cf - trig.ct * trig.sf;
  const double ml2 = e.mu * e.l * e.l;
  // eq:EOM_II_1: a11 th'' - L cos(th - psi) psi'' - m l^2 l4 sin(th - phi) phi'' = b1
  const double a11 = ml2 + I + 1;
  const double b1 = e.L * s_tp * s.psi_dot * s.psi_dot - ml2 * e.l4 * c_tf * s.phi_dot * s.phi_dot -
                    (e.mu * e.l + e.mu_b / 2 * (e.l - 1) - 1) * trig.st;
  // eq:EOM_II_3: -l sin(th - phi) th'' + l l4 phi'' = l cos(th - phi) th'^2 + cos phi
  const double b3 = e.l * c_tf * s.theta_dot * s.theta_dot + trig.cf;
  // psi'' = (b2 + c_tp th'')/L and l4 phi'' = (b3/l + s_tf th''): substituted into the first row.
  const double theta_ddot = (b1 + c_tp * b2 + e.mu * e.l * s_tf * b3) / (a11 - c_tp * c_tp - ml2 * s_tf * s_tf);
  return {theta_ddot, (b2 + c_tp * theta_ddot) * e.inv_L, (b3 * e.inv_l + s_tf * theta_ddot) * e.inv_l4};
}

}  // namespace

std::array<double, 3> Dynamics::accelerations(Phase phase, const State& state) const {
  const Coefficients e{design_.l, design_.l4, L_, design_.mu, design_.mu_b, inertia_, cos_theta_i_, inv_l_, inv_l4_, inv_L_};
  const Accel a = solve(e, phase, state, Trig(e, phase, state));
  return {a.theta, a.psi, a.phi};
}

Snapshot Dynamics::snapshot(Phase phase, const State& s) const {
  const Coefficients e{design_.l, design_.l4, L_, design_.mu, design_.mu_b, inertia_, cos_theta_i_, inv_l_, inv_l4_, inv_L_};
  const Trig trig(e, phase, s);
  const Accel a = solve(e, phase, s, trig);
  Snapshot out;
  out.theta_ddot = a.theta;
  out.psi_ddot = a.psi;
  out.phi_ddot = a.phi;
  const double st = trig.st, ct = trig.ct, sp = trig.sp, cp = trig.cp, sf = trig.sf, cf = trig.cf;
  const double td = s.theta_dot, pd = s.psi_dot, fd = s.phi_dot;

  // Counterweight (mass 1): a = F_H + g, g = (0, -1).
  const Vec2 cw_acc{-ct * a.theta + st * td * td + e.L * (cp * a.psi - sp * pd * pd),
                    -st * a.theta - ct * td * td + e.L * (sp * a.psi + cp * pd * pd)};
  out.hinge_force = {cw_acc.x, cw_acc.y + 1};

  // Projectile: position, velocity, acceleration; in phase I phi follows eq:EOM_I_3.
  out.projectile = {e.l * (st - e.l4 * cf), e.l * (-ct - e.l4 * sf)};
  out.projectile_velocity = {e.l * (ct * td + e.l4 * sf * fd), e.l * (st * td - e.l4 * cf * fd)};
  double phi_ddot = a.phi;
  if (phase == Phase::trough)  // second derivative of eq:EOM_I_3: l4 (cos phi phi'' - sin phi phi'^2) = cos th th'^2 + sin th th''
    phi_ddot = (ct * td * td + st * a.theta + e.l4 * sf * fd * fd) / (e.l4 * cf);
  const Vec2 p_acc{e.l * (-st * td * td + ct * a.theta + e.l4 * (cf * fd * fd + sf * phi_ddot)),
                   e.l * (ct * td * td + st * a.theta + e.l4 * (sf * fd * fd - cf * phi_ddot))};
  Vec2 sling_on_projectile{0, 0};
  if (phase == Phase::trough) {
    // Tension along the sling toward the tip, u = (cos phi, sin phi); the trough carries the rest.
    const double tension = e.mu * p_acc.x / cf;
    sling_on_projectile = {tension * cf, tension * sf};
    out.normal_force = e.mu - tension * sf;  // vertical balance, a_y = 0
  } else if (phase == Phase::lifted) {
    sling_on_projectile = {e.mu * p_acc.x, e.mu * (p_acc.y + 1)};
  }
  out.sling_on_tip = {-sling_on_projectile.x, -sling_on_projectile.y};
  // The sling runs from the projectile to the tip along (cos phi, sin phi): its tension is the
  // pull on the projectile along it; a sling can pull but not push.
  out.sling_tension = sling_on_projectile.x * cf + sling_on_projectile.y * sf;
  // Positions of the hinge, the counterweight and the tip (dynamics.hpp), and heights above the
  // engine's base, which lies l cos(theta_i) below the pivot (H = L1 cos theta_i).
  out.hinge = {-st, ct};
  out.counterweight = {-st + e.L * sp, ct - e.L * cp};
  out.tip = {e.l * st, -e.l * ct};
  const double base = -e.l * cos_theta_i_;
  out.counterweight_height = out.counterweight.y - base;
  out.tip_height = out.tip.y - base;
  // The tip moves along (cos th, sin th) as theta grows; the sling pulls against that.
  out.sling_perpendicular = -(out.sling_on_tip.x * ct + out.sling_on_tip.y * st);

  // Beam (mass mu_b): mu_b a_CM = F_R - F_H (arm on beam) + sling on tip + mu_b g.
  const double r = (e.l - 1) / 2;
  const Vec2 cm_acc{r * (ct * a.theta - st * td * td), r * (st * a.theta + ct * td * td)};
  out.pivot_reaction = {e.mu_b * cm_acc.x + out.hinge_force.x - out.sling_on_tip.x,
                        e.mu_b * (cm_acc.y + 1) + out.hinge_force.y - out.sling_on_tip.y};

  // The short section, a rod of mass mu_b/(l + 1) per L2 from the pivot to the hinge, turns
  // about the pivot: I_short th'' = moment of the arm's pull at the hinge (-F_H) + its weight
  // at its middle - the moment the long section takes. tests/test_shot.cpp checks the long
  // section's own balance against it.
  const double per_length = e.mu_b / (e.l + 1);
  out.beam_moment = st * out.hinge_force.y + ct * out.hinge_force.x + per_length * st / 2 - per_length / 3 * a.theta;

  // Energy of each body, potential from the pivot's level: beam rotation, counterweight,
  // projectile (on the trough in phase I, absent in III).
  const double I = e.I;
  out.energies.beam = 0.5 * I * td * td - e.mu_b * r * ct;
  out.energies.counterweight = 0.5 * (td * td + e.L * e.L * pd * pd - 2 * e.L * (ct * cp + st * sp) * td * pd) + out.counterweight.y;  // cos(th - psi)
  if (phase != Phase::released) {
    const Vec2& v = out.projectile_velocity;
    out.energies.projectile_kinetic = 0.5 * e.mu * (v.x * v.x + v.y * v.y);
    out.energies.projectile_potential = e.mu * out.projectile.y;
  }
  out.energy = out.energies.beam + out.energies.counterweight + out.energies.projectile_kinetic + out.energies.projectile_potential;
  return out;
}

}  // namespace trebuchet
