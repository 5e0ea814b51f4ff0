#include "trebuchet/floating_arm.hpp"

#include <cmath>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {

namespace {
double checked_hanger(const ScaledDesign& design, FloatingArm::Rail rail) {
  const double L = design.L();
  if (!(L >= 0))
    throw Error(ErrorKind::numerical,
                "the floating arm's counterweight hangs above its pin: L3/L2 = F l cos(theta_i) - 1 = " + format_significant(L, 4) +
                    " < 0; give {{L3}} >= 0, or a larger {{F}}");
  if (rail == FloatingArm::Rail::locked && L != 0)
    throw Error(ErrorKind::numerical,
                "a floating arm with its rail locked and no guide swings its counterweight on its pin (L3/L2 = " + format_significant(L, 4) +
                    "): that is the hinged engine; give L3 = 0");
  return L;
}
}  // namespace

FloatingArm::FloatingArm(const ScaledDesign& design, Rail rail)
    : RigidBeamMachine(design, MachineKind::floating_arm, "floating arm"), rail_(rail), hanger_(checked_hanger(design, rail)) {
  if (design.parts.counterweight_inertia > 0)
    throw Error(ErrorKind::usage,
                "the floating arm's counterweight does not turn in its guide: its own inertia does not enter; leave out {{counterweight_inertia}}");
}

// Rolling, the pin stays on the guide's line: pivot - (sin th, -cos th) has x = 0. Locked, with
// no guide, lengths are measured from the pivot, as the fixed machine's.
RigidBeamMachine::Path FloatingArm::pivot_path(double th) const {
  if (rail_ == Rail::locked) return {};
  return {std::sin(th), std::cos(th), -std::sin(th)};
}

// The pin, at the pivot less (sin th, -cos th), moves at (a' - cos th, -sin th) th': the
// counterweight's kinetic energy is ((a' - cos th)^2 + sin^2 th) th'^2/2 (sin^2 th rolling, 1 locked).
RigidBeamMachine::Share FloatingArm::counterweight_share(double th, const Path& a) const {
  const double st = std::sin(th), ct = std::cos(th), u = a.slope - ct;
  return {u * u + st * st, 2 * u * (a.curve + st) + 2 * st * ct};
}

double FloatingArm::counterweight_forces(Snapshot& out, const State& s, double th_dd, Vec2 pivot, Vec2 need, double base) const {
  const Path a = pivot_path(s.theta);
  const double st = std::sin(s.theta), ct = std::cos(s.theta), w2 = s.theta_dot * s.theta_dot, u = a.slope - ct;
  out.hinge = {pivot.x - st, ct};
  out.counterweight = {out.hinge.x, ct - hanger_};
  out.counterweight_height = out.counterweight.y - base;
  const Share share = counterweight_share(s.theta, a);
  out.energies.counterweight = share.inertia * w2 / 2 + out.counterweight.y;
  const Vec2 acceleration{u * th_dd + (a.curve + st) * w2, -st * th_dd - ct * w2};
  // Rolling, the rail takes no horizontal force: the pin gives the beam what it needs along x,
  // and the guide holds the counterweight on its line. Locked, the frame holds the axle and the
  // pin carries all the counterweight needs.
  out.hinge_force = {rail_ == Rail::locked ? acceleration.x : -need.x, acceleration.y + 1};
  out.guide_force = {acceleration.x - out.hinge_force.x, 0};
  return st * out.hinge_force.y + ct * out.hinge_force.x;  // its pull at the pin, (-sin th, cos th) from the pivot
}

}  // namespace trebuchet
