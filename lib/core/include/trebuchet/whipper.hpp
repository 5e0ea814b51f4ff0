// The whipper (issue 36; pytrebuchet's WhipperTrebuchet): the paper's bodies, the beam, the
// counterweight hanging from the short arm's end on its arm L3 and the projectile in its sling
// (appendix A), started another way. The beam stands on a frame of its own height H, its long
// arm forward (toward the target, -x) and up; the counterweight's rope runs from the short arm's
// end up along the beam past the pivot, turned off it by the rope's angle, the counterweight
// resting on the arm; the sling lies folded back along the long arm, the projectile resting on
// the arm beside it. The beam falls forward with both on it, and each leaves the arm in turn:
//   phase held: counterweight and projectile move with the beam (psi - theta, phi - theta fixed);
//   phase I: the counterweight swings free, the projectile still on the arm (phi - theta fixed);
//   phase II: the projectile swings free in its sling, until the release, a whole turn or so
//     later (the "whip"); phase III: the engine without it.
// Each leaves where pytrebuchet lets it: where its angular acceleration relative to the beam,
// were both let go (the unconstrained equations of phase II), changes sign. For the projectile,
// held alone, that is where the arm's push on it vanishes (normal_force); for the counterweight,
// held with the projectile, it is a part in 10^5 of the shot earlier than where the arm's push on
// it would vanish (docs/machines.md, "The whipper").
//
// Scaled as dynamics.hpp says, with its angles and positions: lengths in L2, masses in M, time in
// (L2/g)^(1/2), forces in M g. The equations are Lagrange's for q = (theta, psi, phi) in mass-matrix
// form, M(q) q'' = r(q, q'), which the contacts constrain (docs/machines.md):
//   M = [[I_b + 1 + mu l^2,    -L cos(th - psi),    mu l^2 l4 sin(phi - th)],
//        [-L cos(th - psi),    L^2 + I_c,           0                      ],
//        [mu l^2 l4 sin(phi - th), 0,               mu l^2 l4^2            ]]
//   r = [L sin(th - psi) psi'^2 - mu l^2 l4 cos(phi - th) phi'^2 + (1 - mu_b c - mu l) sin th,
//        -L sin(th - psi) th'^2 - L sin psi,
//        mu l^2 l4 cos(phi - th) th'^2 + mu l l4 cos phi]  + the generalized forces of the losses.
// In phase II they are eq:EOM_II_1, eq:EOM_I_2 and eq:EOM_II_3 (tests/test_machine.cpp checks
// them against Dynamics). As built: the beam as built, the counterweight's own inertia, the
// axle's and the hinge pin's friction and the air on the projectile before the release; the
// rope's drag and the trough's friction (it has no trough) are refused.
#pragma once

#include <array>
#include <optional>

#include "trebuchet/design.hpp"
#include "trebuchet/machine.hpp"

namespace trebuchet {

class Whipper final : public Machine {
 public:
  /// `design` with its frame (ScaledDesign::H, projectile_radius), its beam's start theta_i and
  /// its rope's psi_i. Error(usage) for the trough's friction and the rope's drag.
  explicit Whipper(const ScaledDesign& design);

  const ScaledDesign& design() const override { return design_; }
  double theta_i() const override { return theta_i_; }
  /// The sling lies on the arm in phases held and I: never vertical in a trough (1).
  double trough_cos_phi(double) const override { return 1; }
  /// phi = theta + (phi_i - theta_i), phi_dot = theta_dot: the projectile moves with the arm.
  double complete_trough_state(State& state) const override;
  Snapshot snapshot(Phase phase, const State& state) const override;
  Evaluated accelerations(Phase phase, const State& state, std::array<double, 3>& out, Losses* loss_power = nullptr) const override;
  bool dissipates() const override { return design_.parts.dissipates(); }
  Phase first_phase() const override { return Phase::held; }
  /// Two whole turns from the start in every phase: the whip takes about one.
  double turn_limit(Phase) const override;

  /// The sling's angle at rest [rad]: folded back along the long arm and turned off it by
  /// asin(r/(r + L4)), so that the ball of radius r lies on the arm (pytrebuchet's).
  double phi_i() const { return phi_i_; }

 private:
  ScaledDesign design_;
  double theta_i_, phi_i_;  // [rad]
  double L_, c_, I_b_, weight_;  // L3/L2, the beam's centre and inertia, 1 - mu_b c (scaled)

  /// Generalized forces on (theta, psi, phi) besides gravity's (M g L2).
  using Generalized = std::array<double, 3>;
  /// The accelerations in a phase, and those of phase II's equations at the same state (`free`).
  struct Motion {
    std::array<double, 3> a, free;
  };
  Motion motion(Phase phase, const State& state, const Generalized& extra) const;
  /// The snapshot of a state whose motion is `m`, with the air's force on the projectile `drag`.
  Snapshot snapshot_with(Phase phase, const State& state, const Motion& m, Vec2 drag) const;
  /// The motion with the losses, the pins' friction settled by fixed-point iteration on the
  /// forces it depends on, and the snapshot there with each loss's power; none where they do
  /// not settle.
  std::optional<Snapshot> resisted(Phase phase, const State& state) const;
};

}  // namespace trebuchet
