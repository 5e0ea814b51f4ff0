// The fixed-counterweight trebuchet (issue 36; Trebuchator's "fixed", VirtualTrebuchet's L3 = 0):
// the counterweight bolted to the short arm, its centre L3 beyond the arm's end (at 1 + L from
// the pivot, L = L3/L2 >= 0), turning with the beam with its own moment of inertia about its
// centre. The beam and the counterweight are one rigid body about the fixed pivot, the sling and
// its trough are the paper's (rigid_beam_machine.hpp). Delta U is (1 + L - mu_b c)(1 + cos theta_i)
// (ScaledDesign::energy_drop).
#pragma once

#include "trebuchet/rigid_beam_machine.hpp"

namespace trebuchet {

class FixedCounterweight final : public RigidBeamMachine {
 public:
  /// `design`'s l, l4, L, mu, mu_b, theta_i and its beam (the uniform rod, or as built), and the
  /// counterweight's own inertia (parts.counterweight_inertia), and the losses as built but a
  /// hinge pin's (it has none) and the rope's drag: Error(usage) for those, Error(numerical) for
  /// L < 0 (as machine_of).
  explicit FixedCounterweight(const ScaledDesign& design);

 private:
  double distance_;  // of the counterweight's centre from the pivot, 1 + L (L2)
  Path pivot_path(double) const override { return {}; }
  bool counterweight_turns() const override { return true; }
  Share counterweight_share(double theta, const Path& pivot) const override;
  double counterweight_forces(Snapshot& out, const State& state, double theta_ddot, Vec2 pivot, Vec2 need, double base) const override;
};

}  // namespace trebuchet
