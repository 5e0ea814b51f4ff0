// The fixed-counterweight trebuchet (issue 36, Trebuchator's "fixed", VirtualTrebuchet's L3 = 0):
// the counterweight bolted to the short arm's end, turning with the beam, with its own moment of
// inertia about its centre. The beam and the counterweight are one rigid body about the pivot;
// the sling and its trough are the paper's (appendix A). Scaled as dynamics.hpp says: lengths in
// L2, masses in M, time in (L2/g)^(1/2), forces in M g. psi follows the beam (psi'' = theta''),
// phi is the sling's angle. With the counterweight's centre at the hinge, Delta U is eq:DU's:
// (1 - mu_b c)(1 + cos theta_i), c the beam's centre of mass (ScaledDesign::energy_drop).
#pragma once

#include <array>

#include "trebuchet/design.hpp"
#include "trebuchet/machine.hpp"

namespace trebuchet {

class FixedCounterweight final : public Machine {
 public:
  /// `design`'s l, l4, mu, mu_b, theta_i and its beam (the uniform rod, or as built), and the
  /// counterweight's own inertia (parts.counterweight_inertia); its counterweight arm, a propped
  /// counterweight and the losses are not this machine's: Error(usage) for friction or drag.
  explicit FixedCounterweight(const ScaledDesign& design);

  const ScaledDesign& design() const override { return design_; }
  double theta_i() const override { return theta_i_; }
  double trough_cos_phi(double theta) const override;
  double complete_trough_state(State& state) const override;
  Snapshot snapshot(Phase phase, const State& state) const override;
  bool accelerations(Phase phase, const State& state, std::array<double, 3>& out, Losses* loss_power = nullptr) const override;
  bool dissipates() const override { return false; }

 private:
  ScaledDesign design_;
  double theta_i_;  // [rad]
  double inertia_;  // J: the beam's and the counterweight's moment of inertia about the pivot, scaled (M L2^2)
  double weight_;  // G = 1 - mu_b c: the rigid body's potential is G cos(theta), scaled (M g L2)
  std::array<double, 3> accelerations_of(Phase phase, const State& state) const;
};

}  // namespace trebuchet
