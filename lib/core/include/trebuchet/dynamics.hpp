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
#include "trebuchet/dynamics_types.hpp"
#include "trebuchet/machine.hpp"

namespace trebuchet {

/// Phase III in vacuum: the horizontal distance from the pivot, toward the target (-x), to
/// where a projectile released at `position` with `velocity` lands `drop` below its release
/// height. Units consistent with g (scaled: g = 1).
double vacuum_range(Vec2 position, Vec2 velocity, double drop, double g);

/// The bending moment in the beam at a fixed pivot (Snapshot::beam_moment, M g L2) from its short
/// section's turn: the hinge's pull on it (-hinge_force, the force of the arm on the counterweight
/// reversed) at (-sin th, cos th), its weight at its centre, less its own I theta''.
double short_section_moment(const BuiltParts::Section& section, double theta, Vec2 hinge_force, double theta_ddot);

/// The air's force on a body of scaled `mass` moving at `velocity` (the projectile of the
/// machines whose equations are written from their bodies): -mass Cd per_length |u| u, u its
/// velocity through the air, which moves toward -x at drag.wind (air.hpp).
Vec2 air_force(const Drag& drag, double mass, Vec2 velocity);

namespace detail {
struct Coefficients;  // the constants of the equations, as dynamics.cpp evaluates them
}

/// The paper's engine (appendix A) as a Machine: the equations of motion of one scaled design,
/// with its constants computed once.
class Dynamics final : public Machine {
 public:
  explicit Dynamics(const ScaledDesign& design);

  const ScaledDesign& design() const override { return design_; }
  double theta_i() const override { return theta_i_; }  ///< [rad]

  /// sin phi in the trough from eq:EOM_I_3: cos th + l4 sin phi = cos th_i.
  double trough_sin_phi(double theta) const;

  /// cos phi in the trough from eq:EOM_I_3 (0 where the sling would stand vertical or beyond).
  double trough_cos_phi(double theta) const override;

  /// Fills phi and phi_dot of a phase-I state from eq:EOM_I_3; returns cos phi (<= 0: the sling stands vertical).
  double complete_trough_state(State& state) const override;

  /// Accelerations and forces at a state of the given phase.
  Snapshot snapshot(Phase phase, const State& state) const override;

  /// Accelerations only (the right-hand side of the ODE), cheaper than snapshot. In the trough
  /// phi and phi_dot of `state` are not read: they follow from theta. With friction, the
  /// accelerations are found by Newton's method on the forces' affine model (dynamics.cpp);
  /// Evaluated::failed where they do not settle (a friction too strong for the model), and
  /// near_trough_singularity for a trough state as Machine::accelerations says; `out` is then not set.
  Evaluated accelerations(Phase phase, const State& state, std::array<double, 3>& out, Losses* loss_power = nullptr) const override;

  /// Whether the shot loses energy other than to the bodies (BuiltParts::dissipates).
  bool dissipates() const override { return dissipates_; }

 private:
  ScaledDesign design_;
  double theta_i_, cos_theta_i_;  // [rad], scaled
  double L_, inertia_;  // eq:Design, section 2; scaled
  double inv_l_, inv_l4_, inv_L_;  // their reciprocals, so that evaluations multiply
  double beam_cm_;  // ScaledDesign::beam_cm
  double psi_ratio_, inv_L_psi_;  // L/L_psi and 1/L_psi, L_psi = L + I_c/L (dynamics.cpp)
  bool dissipates_;  // BuiltParts::dissipates
  detail::Coefficients coefficients() const;
};

/// Thrown by Dynamics::snapshot where friction leaves the accelerations unsettled.
inline constexpr const char* unsettled_friction =
    "the friction at the pins is too strong for the model: the accelerations do not settle (docs/verifier.md, \"Real engines\"); "
    "give smaller coefficients or pin radii ({{axle_friction}}, {{hinge_friction}}, {{trough_friction}})";

}  // namespace trebuchet
