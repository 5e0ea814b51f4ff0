// A second machine for the seam (machine.hpp), small enough to derive by hand: a pendulum that
// slings. The counterweight, of mass M, is fixed at the hinge end of a massless beam (a
// pendulum of length L2 about the pivot); the projectile of mass m lies in the trough and hangs
// from the tip, l L2 from the pivot, on a sling of length l4 L1. Scaled as dynamics.hpp says;
// psi follows the beam (psi'' = theta''), phi is the sling's angle. Its design is the
// ScaledDesign with mu_b = 0: Delta U = (1 + cos theta_i) M g L2, as eq:DU gives without a beam.
#pragma once

#include "trebuchet/machine.hpp"

namespace trebuchet::testing {

class PendulumSling final : public Machine {
 public:
  /// `design`'s l, l4, mu and theta_i_deg; its beam, counterweight arm and parts are not used.
  explicit PendulumSling(const ScaledDesign& design);

  const ScaledDesign& design() const override { return design_; }
  double theta_i() const override { return theta_i_; }
  double trough_cos_phi(double theta) const override;
  double complete_trough_state(State& state) const override;
  Snapshot snapshot(Phase phase, const State& state) const override;
  bool accelerations(Phase phase, const State& state, std::array<double, 3>& out, Losses* loss_power = nullptr) const override;
  bool dissipates() const override { return false; }

 private:
  ScaledDesign design_;
  double theta_i_;
};

}  // namespace trebuchet::testing
