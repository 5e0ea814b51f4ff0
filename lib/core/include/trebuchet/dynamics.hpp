// The scaled equations of motion of appendix A and the internal forces that follow from
// them by Newton's laws. Scaled units: lengths in L2, masses in M, time in (L2/g)^(1/2),
// forces in Mg, energies in M g L2. Pivot at the origin, y up; the long arm starts at
// theta_i from the downward vertical on the +x side and the target lies toward -x.
//   hinge          (-sin th, cos th)
//   counterweight  (-sin th + L sin psi, cos th - L cos psi)
//   beam CM        (l - 1)/2 (sin th, -cos th)
//   projectile     l (sin th - l4 cos phi, -cos th - l4 sin phi)
// These positions give eq:EOM_I_1, eq:EOM_I_2, eq:EOM_II_1 and eq:EOM_II_3 from the Lagrangian.
// An engine as built (design.hpp, BuiltParts) changes the beam's and the counterweight's terms
// and adds generalized forces of friction and drag to the right-hand sides (docs/verifier.md,
// "Real engines").
#pragma once

#include <array>

#include "trebuchet/design.hpp"

namespace trebuchet {

/// Phase I: projectile slides in the trough (eq:EOM_I_1 to eq:EOM_I_3). Phase II: lifted (eq:EOM_II_1,
/// eq:EOM_I_2, eq:EOM_II_3). Phase III: released, mu = 0.
enum class Phase { trough, lifted, released };

/// A state of the engine, scaled. In phase I, phi and phi_dot follow from eq:EOM_I_3.
struct State {
  double theta = 0, psi = 0, phi = 0;              ///< [rad]
  double theta_dot = 0, psi_dot = 0, phi_dot = 0;  ///< scaled angular speeds
};

struct Vec2 {
  double x = 0, y = 0;
};

/// Kinetic plus potential energy of each body, scaled (M g L2), potential from the pivot's level.
struct BodyEnergies {
  double beam = 0, counterweight = 0, projectile_kinetic = 0, projectile_potential = 0;
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
  Vec2 hinge, counterweight, tip;        ///< relative to the pivot, scaled
  Vec2 projectile, projectile_velocity;  ///< relative to the pivot, scaled
  Vec2 pivot_reaction;   ///< F_R: force of the frame on the beam at the pivot
  Vec2 hinge_force;      ///< F_H: force of the arm on the counterweight
  Vec2 sling_on_tip;     ///< force of the sling on the beam tip
  double sling_perpendicular = 0;  ///< F_S_perp: component of the sling's pull on the tip against the beam's turn
  double normal_force = 0;         ///< trough on projectile (phase I; 0 after)
  double sling_tension = 0;        ///< pull of the sling on the projectile along it (< 0: it would push, the sling is slack)
  double counterweight_height = 0; ///< of the counterweight above the engine's base (< 0: below it)
  double tip_height = 0;           ///< of the beam's tip above the engine's base (< 0: below it)
  /// Bending moment in the beam at the pivot, in M g L2: what the short section passes to the
  /// long one, > 0 turning the long arm up. Held at rest with the beam level it is the M g L2 of
  /// eq:Strain plus the short section's own weight, mu_b/(2(l + 1)); in the shot the beam's
  /// rigid turn adds its inertia.
  double beam_moment = 0;
  BodyEnergies energies;           ///< phase III: the projectile's are 0
  double energy = 0;               ///< kinetic + potential of all bodies, scaled; conserved without losses
  Losses loss_power{};             ///< the power each loss takes out of the bodies (< 0: the wind gives)
};

/// Phase III in vacuum: the horizontal distance from the pivot, toward the target (-x), to
/// where a projectile released at `position` with `velocity` lands `drop` below its release
/// height. Units consistent with g (scaled: g = 1).
double vacuum_range(Vec2 position, Vec2 velocity, double drop, double g);

namespace detail {
struct Coefficients;  // the constants of the equations, as dynamics.cpp evaluates them
}

/// The equations of motion of one scaled design, with its constants computed once.
class Dynamics {
 public:
  explicit Dynamics(const ScaledDesign& design);

  const ScaledDesign& design() const { return design_; }
  double theta_i() const { return theta_i_; }  ///< [rad]

  /// sin phi in the trough from eq:EOM_I_3: cos th + l4 sin phi = cos th_i.
  double trough_sin_phi(double theta) const;

  /// cos phi in the trough from eq:EOM_I_3 (0 where the sling would stand vertical or beyond).
  double trough_cos_phi(double theta) const;

  /// Fills phi and phi_dot of a phase-I state from eq:EOM_I_3; returns cos phi (<= 0: the sling stands vertical).
  double complete_trough_state(State& state) const;

  /// Accelerations and forces at a state of the given phase.
  Snapshot snapshot(Phase phase, const State& state) const;

  /// Accelerations only (the right-hand side of the ODE), cheaper than snapshot. In the trough
  /// phi and phi_dot of `state` are not read: they follow from theta. With friction, the
  /// accelerations are found by Newton's method on the forces' affine model (dynamics.cpp); false where they do not
  /// settle (a friction too strong for the model), and then `out` is not set.
  bool accelerations(Phase phase, const State& state, std::array<double, 3>& out, Losses* loss_power = nullptr) const;

  /// Whether the shot loses energy other than to the bodies (BuiltParts::dissipates).
  bool dissipates() const { return dissipates_; }

 private:
  ScaledDesign design_;
  double theta_i_, cos_theta_i_;  // [rad], scaled
  double L_, inertia_;            // eq:Design, section 2; scaled
  double inv_l_, inv_l4_, inv_L_; // their reciprocals, so that evaluations multiply
  double beam_cm_;                 // ScaledDesign::beam_cm
  double psi_ratio_, inv_L_psi_;   // L/L_psi and 1/L_psi, L_psi = L + I_c/L (dynamics.cpp)
  bool dissipates_;                // BuiltParts::dissipates
  detail::Coefficients coefficients() const;
};

/// Thrown by Dynamics::snapshot where friction leaves the accelerations unsettled.
inline constexpr const char* unsettled_friction =
    "the friction at the pins is too strong for the model: the accelerations do not settle (docs/verifier.md, \"Real engines\"); "
    "give smaller coefficients or pin radii ({{axle_friction}}, {{hinge_friction}}, {{trough_friction}})";

}  // namespace trebuchet
