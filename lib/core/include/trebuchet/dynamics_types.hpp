// The states, forces and energies that a machine's equations of motion give the shot, scaled
// as dynamics.hpp says (lengths in L2, masses in M, time in (L2/g)^(1/2), forces in M g,
// energies in M g L2). Pivot at the origin, y up; the target lies toward -x.
#pragma once

#include <array>

namespace trebuchet {

/// Phase I: projectile slides in the trough (eq:EOM_I_1 to eq:EOM_I_3). Phase II: lifted (eq:EOM_II_1,
/// eq:EOM_I_2, eq:EOM_II_3). Phase III: released, mu = 0. The whipper (whipper.hpp) has no trough:
/// its phase I holds the projectile on the arm, after a phase `held` that holds the
/// counterweight there too.
enum class Phase { held, trough, lifted, released };

/// The phase's numeral in the series and the pictures: I (the whipper's `held` too), II or III.
inline const char* phase_numeral(Phase phase) { return phase == Phase::lifted ? "II" : phase == Phase::released ? "III" : "I"; }

/// A state of the engine, scaled. In phase I, phi and phi_dot follow from eq:EOM_I_3.
struct State {
  double theta = 0, psi = 0, phi = 0;  ///< [rad]
  double theta_dot = 0, psi_dot = 0, phi_dot = 0;  ///< scaled angular speeds
};

struct Vec2 {
  double x = 0, y = 0;
};
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }

/// Kinetic plus potential energy of each body, scaled (M g L2), potential from the pivot's level;
/// the sling's, its rope's and pouch's (sling.hpp), 0 for a sling of no mass.
struct BodyEnergies {
  double beam = 0, counterweight = 0, projectile_kinetic = 0, projectile_potential = 0, sling = 0;
};

/// Where the energy of an engine as built goes besides the bodies: the friction at the axle, at
/// the counterweight's hinge and in the trough, and the drag on the projectile and on the sling's
/// rope before the release. As powers (scaled, M g L2 per scaled time) or as work done.
enum LossIndex { axle_loss, hinge_loss, trough_loss, projectile_drag_loss, rope_drag_loss };
inline constexpr int loss_count = 5;
using Losses = std::array<double, loss_count>;

/// Angular accelerations and the internal forces at one state, scaled (forces in Mg).
struct Snapshot {
  double theta_ddot = 0, psi_ddot = 0, phi_ddot = 0;
  /// Positions relative to the frame's origin at the pivot's height, scaled: the pivot, which
  /// stays there but for the floating arm's (its origin is the guide's line).
  Vec2 pivot, hinge, counterweight, tip;
  Vec2 projectile, projectile_velocity;  ///< relative to the frame's origin, scaled
  Vec2 pivot_reaction;  ///< F_R: force of the frame on the beam at the pivot
  Vec2 hinge_force;  ///< F_H: force of the arm on the counterweight
  Vec2 guide_force;  ///< of the frame's guide on the counterweight (the floating arm's; 0 for the others)
  Vec2 sling_on_tip;  ///< force of the sling on the beam tip
  double sling_perpendicular = 0;  ///< F_S_perp: component of the sling's pull on the tip against the beam's turn
  double normal_force = 0;  ///< trough on projectile (phase I; 0 after); the whipper's arm on it, phases held and I
  /// The whipper's, in phase held: the counterweight's angular acceleration relative to the beam,
  /// psi'' - theta'' (scaled), were the arm to let it go; > 0 while it presses on the arm.
  double counterweight_on_arm = 0;
  /// The whipper's, in phase held: the arm's push on the counterweight along its upper normal
  /// (M g; < 0: the arm would have to pull it, and the model, holding it there, no longer holds).
  double counterweight_push = 0;
  double sling_tension = 0;  ///< pull of the sling on the projectile (and its pouch) along it (< 0: it would push, the sling is slack)
  /// A sling with mass (sling.hpp): its rope's tension at the tip, and the shear the rod's model
  /// puts across the rope at each end, which a rope cannot carry (0 for a rope of no mass but in air).
  double rope_tension_at_tip = 0, rope_shear_at_tip = 0, rope_shear_at_end = 0;
  double counterweight_height = 0;  ///< of the counterweight above the engine's base (< 0: below it)
  double tip_height = 0;  ///< of the beam's tip above the engine's base (< 0: below it)
  /// Bending moment in the beam at the pivot, in M g L2: what the short section passes to the
  /// long one, > 0 turning the long arm up. Held at rest with the beam level it is the M g L2 of
  /// eq:Strain plus the short section's own weight, mu_b/(2(l + 1)); in the shot the beam's
  /// rigid turn adds its inertia.
  double beam_moment = 0;
  BodyEnergies energies;  ///< phase III: the projectile's are 0
  double energy = 0;  ///< kinetic + potential of all bodies, scaled; conserved without losses
  Losses loss_power{};  ///< the power each loss takes out of the bodies (< 0: the wind gives)
};

}  // namespace trebuchet
