// The sling as built (BuiltParts::Sling; docs/machines.md, "The sling's mass"): its rope a
// uniform rod of mass m_r from the beam's tip to its end while taut, its pouch a point of mass
// m_p at that end, which carries the projectile until the release. Every machine's equations of
// motion take the sling through Sling's point masses and the rope's inertia beyond them; its
// forces and energy follow here, from the accelerations, the same for every machine. Scaled as
// dynamics.hpp says (lengths in L2, masses in M, forces in M g). The sling runs from its end
// to the tip along u = (cos phi, sin phi); n = (sin phi, -cos phi) is across it.
#pragma once

#include "trebuchet/design.hpp"
#include "trebuchet/dynamics_types.hpp"

namespace trebuchet {

/// The part of the rope's pull on what its end carries that runs across the rope because the
/// rope has mass: from the rope's turn about the tip, m_r/2 (e x a_tip) + m_r s phi''/3 - m_r cos
/// phi/2 = s e x F (e = -u, F the end's load on the rope), for a rope of length s (L2) whose tip
/// accelerates by a_tip, with u = (cos phi, sin phi) as the callers have it. 0 for a rope of no mass.
Vec2 rope_mass_across(const BuiltParts::Sling& sling, double s, Vec2 u, double phi_ddot, Vec2 tip_acceleration);

/// The forces at the rope's two ends.
struct RopeEnds {
  Vec2 on_tip;  ///< the rope's pull on the beam's tip
  double tension_at_end = 0, tension_at_tip = 0;  ///< along the rope, > 0 pulling (< 0: a rope would go slack)
  double shear_at_end = 0, shear_at_tip = 0;  ///< across it, along n: a rope carries none (the rod's model does)
};

/// The ends' forces, for a rope along u, from the rope's pull on what its end carries (`on_end`), the accelerations
/// of the tip and of the end, and the air's total force on the rope: its tip gives what the rope's
/// own mass needs besides (m_r times its centre's acceleration, against its weight).
RopeEnds rope_ends(const BuiltParts::Sling& sling, Vec2 u, Vec2 on_end, Vec2 tip_acceleration, Vec2 end_acceleration, Vec2 air_on_rope);

/// The sling at the beam's tip in a snapshot whose sling_tension is set: its pull on the tip
/// (rope.on_tip), the rope's tension and shear at both ends where the rope has mass, else one
/// tension along it, the sling's; and the pull across the beam F_S_perp (eq:F), the tip moving
/// along (cos theta, sin theta) as theta grows.
void sling_at_tip(Snapshot& out, const RopeEnds& rope, bool rope_has_mass, double cos_theta, double sin_theta);

/// The sling's kinetic and potential energy (M g L2, potential from the pivot's level): the pouch
/// at its end, the rope's centre halfway and its turn about it, m_r s^2/12 phi'^2/2.
double sling_energy(const BuiltParts::Sling& sling, double s, Vec2 tip, Vec2 tip_velocity, Vec2 end, Vec2 end_velocity, double phi_dot);

}  // namespace trebuchet
