// The sling as built (issue 48): a rope of mass, a uniform rod about the tip while taut, and a
// pouch at its end (sling.hpp). tests/machines/independent.py derives the same shots from a
// Lagrangian of its own; these check what holds for any engine: no mass is today's shot, mass
// costs range and keeps the energy, through phase III too, and the rope's turn about the tip is
// what Newton's law on the pouch says it carries.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engines.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/sling.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;
using namespace trebuchet::testing;

namespace {

Engine with_sling(Engine e, MachineKind machine, double rope, double pouch) {
  e.machine = machine, e.parts.rope_mass = rope, e.parts.pouch_mass = pouch;
  if (machine != MachineKind::hinged) e.L3 = 0.2;  // the counterweight 0.2 m beyond the arm's end, or below its pin
  return e;
}

ShotSettings range_optimum() {
  ShotSettings s;
  s.criterion.release = Release::range;
  return s;
}

}  // namespace

TEST_CASE("a sling of no mass is today's shot, bit for bit, and a grain of mass barely moves it", "[sling]") {
  for (const MachineKind machine : {MachineKind::hinged, MachineKind::fixed, MachineKind::floating_arm}) {
    const Verification none = verify_engine(with_sling(laboratory_engine(), machine, 0, 0), range_optimum());
    Engine plain = laboratory_engine();
    plain.machine = machine;
    if (machine != MachineKind::hinged) plain.L3 = 0.2;
    const Verification today = verify_engine(plain, range_optimum());
    CHECK(none.R_vacuum == today.R_vacuum);
    CHECK(none.t_release == today.t_release);
    CHECK(none.FR_Mg == today.FR_Mg);
    // A milligram of rope swings on after the release (phase III of three angles): the range
    // moves by about its share of the moving mass, 1e-6/0.717, far below 1e-5.
    const Verification grain = verify_engine(with_sling(laboratory_engine(), machine, 1e-6, 0), range_optimum());
    std::printf("machine %d: a milligram of rope moves the range by %.2g\n", static_cast<int>(machine), std::abs(grain.R_vacuum / today.R_vacuum - 1));
    CHECK(std::abs(grain.R_vacuum / today.R_vacuum - 1) < 1e-5);
    CHECK(grain.R_vacuum != today.R_vacuum);
  }
}

TEST_CASE("a sling of 0.1 kg on the laboratory engine throws shorter with its energy kept", "[sling]") {
  const Verification bare = verify_engine(laboratory_engine(), range_optimum());
  for (const auto& [rope, pouch] : {std::pair{0.1, 0.0}, {0.0, 0.1}, {0.05, 0.05}}) {
    std::vector<TracePoint> trace;
    const Engine e = with_sling(laboratory_engine(), MachineKind::hinged, rope, pouch);
    const Verification v = verify_engine(e, range_optimum(), &trace, 1e-3);
    std::printf("laboratory engine, rope %g kg, pouch %g kg: R = %.4f m (bare %.4f m), drift %.1e of Delta U\n", rope, pouch, v.R_vacuum, bare.R_vacuum,
                v.energy_drift);
    // The sling's mass takes energy the projectile would have had: at least a few per cent of
    // the 0.717 kg stone's range for a tenth of its mass (a pouch at its end costs most).
    CHECK(v.R_vacuum < 0.97 * bare.R_vacuum);
    CHECK(v.energy_drift < 1e-9);
    // After the release the sling swings on: the bodies' energy stays what it was (no losses).
    const double delta_U = scaled_design(e).energy_drop();
    double first = 0, worst = 0;
    bool seen = false;
    for (const TracePoint& p : trace) {
      if (p.phase != Phase::released) continue;
      if (!seen) first = p.snapshot.energy, seen = true;
      worst = std::max(worst, std::abs(p.snapshot.energy - first) / delta_U);
    }
    REQUIRE(seen);
    std::printf("  phase III: energy within %.1e of Delta U\n", worst);
    CHECK(worst < 1e-9);
  }
}

TEST_CASE("the rope's shear at the pouch is what its turn about the tip needs", "[sling]") {
  // Lagrange's equation for phi and Newton's law on the pouch are two ways to the shear the rod
  // carries at its end: they agree to round-off where the equations of motion are right, and a
  // term of the rope's inertia left out would part them by a share of the rope's weight.
  for (const MachineKind machine : {MachineKind::hinged, MachineKind::fixed, MachineKind::floating_arm}) {
    const Engine e = with_sling(laboratory_engine(), machine, 0.3, 0.1);
    const ScaledDesign d = scaled_design(e);
    std::vector<TracePoint> trace;
    simulate_shot(d, ReleaseCriterion{}, IntegratorSettings{}, &trace, 0.05);
    int checked = 0;
    for (const TracePoint& p : trace) {
      if (p.phase != Phase::lifted && p.phase != Phase::released) continue;
      const Snapshot& s = p.snapshot;
      // The tip's acceleration from the beam's turn and the pivot's (the floating arm's moves).
      const double th = p.state.theta, w = p.state.theta_dot, l = d.l;
      Vec2 tip{l * (std::cos(th) * s.theta_ddot - std::sin(th) * w * w), l * (std::sin(th) * s.theta_ddot + std::cos(th) * w * w)};
      if (machine == MachineKind::floating_arm)  // its pivot rolls at x = sin(theta) (L2 = 1), the pin on the guide's line
        tip.x += std::cos(th) * s.theta_ddot - std::sin(th) * w * w;
      const Vec2 across = rope_mass_across(d.parts.sling, d.l * d.l4, p.state.phi, s.phi_ddot, tip);
      const double from_turn = across.x * std::sin(p.state.phi) - across.y * std::cos(p.state.phi);
      INFO("machine " << static_cast<int>(machine) << " t " << p.t << " shear " << s.rope_shear_at_end << " from the turn " << from_turn);
      CHECK(std::abs(s.rope_shear_at_end - from_turn) < 1e-10 * (1 + std::abs(s.sling_tension)));
      ++checked;
    }
    CHECK(checked > 10);
  }
}

TEST_CASE("the whipper refuses a sling of mass by name", "[sling]") {
  Engine e;
  e.machine = MachineKind::whipper, e.L1 = 4, e.L2 = 2, e.L3 = 4, e.L4 = 4, e.M = 100, e.m = 3, e.mb = 10, e.theta_i_deg = -150;
  e.whipper.H = 5;
  e.parts.pouch_mass = 0.2;
  try {
    verify_engine(e, ShotSettings{});
    FAIL("accepted");
  } catch (const Error& error) {
    INFO(error.what());
    CHECK(error.kind() == ErrorKind::usage);
    CHECK(std::string(error.what()).find("pouch_mass") != std::string::npos);
  }
}
