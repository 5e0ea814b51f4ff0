#include "trebuchet/sling.hpp"

namespace trebuchet {

Vec2 rope_mass_across(const BuiltParts::Sling& sling, double s, Vec2 u, double phi_ddot, Vec2 tip_acceleration) {
  if (!(sling.rope > 0)) return {};
  const double c = u.x, sn = u.y;
  // e = (-cos phi, -sin phi) from the tip to the end; e x a = e_x a_y - e_y a_x.
  const double e_cross_a = -c * tip_acceleration.y + sn * tip_acceleration.x;
  const double b = sling.rope / 2 * e_cross_a + sling.rope * s * phi_ddot / 3 - sling.rope / 2 * c;  // the end's load on the rope, along n
  return {-b * sn, b * c};  // the rope's on the end: -b n
}

RopeEnds rope_ends(const BuiltParts::Sling& sling, Vec2 u, Vec2 on_end, Vec2 tip_acceleration, Vec2 end_acceleration, Vec2 air_on_rope) {
  const double m = sling.rope, c = u.x, sn = u.y;
  RopeEnds out;
  // The rope: m_r a_centre = (tip's force on it) - on_end + air - m_r y.
  out.on_tip = {-on_end.x - m * (tip_acceleration.x + end_acceleration.x) / 2 + air_on_rope.x,
                -on_end.y - m * ((tip_acceleration.y + end_acceleration.y) / 2 + 1) + air_on_rope.y};
  out.tension_at_end = on_end.x * c + on_end.y * sn;
  out.shear_at_end = on_end.x * sn - on_end.y * c;
  out.tension_at_tip = -(out.on_tip.x * c + out.on_tip.y * sn);
  out.shear_at_tip = out.on_tip.x * sn - out.on_tip.y * c;
  return out;
}

double sling_energy(const BuiltParts::Sling& sling, double s, Vec2 tip, Vec2 tip_velocity, Vec2 end, Vec2 end_velocity, double phi_dot) {
  const auto square = [](Vec2 v) { return v.x * v.x + v.y * v.y; };
  const Vec2 centre_velocity{(tip_velocity.x + end_velocity.x) / 2, (tip_velocity.y + end_velocity.y) / 2};
  return sling.pouch * (square(end_velocity) / 2 + end.y) +
      sling.rope * (square(centre_velocity) / 2 + s * s * phi_dot * phi_dot / 24 + (tip.y + end.y) / 2);
}

void sling_at_tip(Snapshot& out, const RopeEnds& rope, bool rope_has_mass, double cos_theta, double sin_theta) {
  out.sling_on_tip = rope.on_tip;
  if (rope_has_mass)
    out.rope_tension_at_tip = rope.tension_at_tip, out.rope_shear_at_tip = rope.shear_at_tip, out.rope_shear_at_end = rope.shear_at_end;
  else
    out.rope_tension_at_tip = out.sling_tension;  // one tension along a rope of no mass
  out.sling_perpendicular = -(out.sling_on_tip.x * cos_theta + out.sling_on_tip.y * sin_theta);
}

}  // namespace trebuchet
