// The floating-arm trebuchet (issue 36; Trebuchator's "floating"): the axle, of no mass, rolls
// on a level rail at the pivot's height, while the counterweight, pinned to the short arm's end
// with its centre L3 below the pin, falls in a vertical guide without turning. The guide holds
// the pin on its line, x = 0, so that the pivot sits at x = sin(theta) and the counterweight
// falls straight through 1 + cos(theta_i) (in L2), pulling the beam round as the axle rolls
// along the rail, L2 sin(theta) behind the guide. Lengths are measured from the guide's line at the pivot's height:
// the range too, as Trebuchator measures it (its origin is the guide). The sling and its trough
// are the paper's (rigid_beam_machine.hpp); the counterweight's own inertia does not enter, as
// it does not turn. Delta U is (1 - mu_b c)(1 + cos theta_i) (ScaledDesign::energy_drop).
#pragma once

#include "trebuchet/rigid_beam_machine.hpp"

namespace trebuchet {

class FloatingArm final : public RigidBeamMachine {
 public:
  /// How the axle and the counterweight are held: as built, the axle rolls and the guide holds
  /// the counterweight; `locked` holds the axle where it stands at rest and takes the guide away,
  /// so that the counterweight hangs free on its pin (a limit case: with its centre on the pin,
  /// L3 = 0, it is the fixed counterweight's point at the short arm's end); lengths are then
  /// measured from the pivot.
  enum class Rail { rolling, locked };

  /// `design`'s l, l4, L (the counterweight's centre below its pin), mu, mu_b, theta_i and its
  /// beam, and the losses as built but the rope's drag. Error(usage) for that and for the
  /// counterweight's own inertia (it does not turn), Error(numerical) for L < 0 or,
  /// with the rail locked, L > 0 (the counterweight would swing on its pin: the hinged engine).
  explicit FloatingArm(const ScaledDesign& design, Rail rail = Rail::rolling);

 private:
  Rail rail_;
  double hanger_;  // L: the counterweight's centre below its pin (L2)
  Path pivot_path(double theta) const override;
  bool counterweight_turns() const override { return false; }
  Share counterweight_share(double theta, const Path& pivot) const override;
  double counterweight_forces(Snapshot& out, const State& state, double theta_ddot, Vec2 pivot, Vec2 need, double base) const override;
};

}  // namespace trebuchet
