// Engines as built (issue 24): a beam as built, a counterweight with its own inertia, friction
// at the pins and in the trough, and the air before the release. Each reduces to the paper's
// ideal engine when it vanishes, conserves energy with the work of its losses, and a small
// friction costs what the first-order estimate along the frictionless motion says.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engines.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/calibration.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;
using namespace trebuchet::testing;

namespace {

ShotResult shot_of(const ScaledDesign& d, std::vector<TracePoint>* trace = nullptr, double dt = 0) {
  return simulate_shot(d, ReleaseCriterion{}, IntegratorSettings{}, trace, dt);
}

// The integral of f over the trace's points in [0, t_end] (trapezoids), for the first-order
// estimates below: at a sampling of 2e-4 (scaled time) its error is ~1e-9 of the integral, far
// below the second-order differences (1e-4 and more) that the tests measure.
template <class F>
double integral(const std::vector<TracePoint>& trace, double t_end, F f) {
  double sum = 0;
  for (std::size_t k = 1; k < trace.size() && trace[k].t <= t_end; ++k) sum += (trace[k].t - trace[k - 1].t) * (f(trace[k]) + f(trace[k - 1])) / 2;
  return sum;
}

}  // namespace

TEST_CASE("a uniform beam given as built is the paper's beam", "[real]") {
  const Engine ca = alcala_ca();
  const ScaledDesign ideal = scaled_design(ca);
  const ShotResult reference = shot_of(ideal);
  // The same beam handed to the equations as a body: its centre of mass and inertia, the
  // very doubles of section 2's rod, give the very same shot.
  ScaledDesign as_body = ideal;
  as_body.parts.beam = BuiltParts::Beam{ideal.beam_cm(), ideal.beam_inertia()};
  CHECK(shot_of(as_body).release.range == reference.release.range);
  CHECK(shot_of(as_body).release.quality == reference.release.quality);
  // Given in SI, as a user would (c = (L1 - L2)/2, I = mb (L1^2 - L1 L2 + L2^2)/3), the scaling
  // rounds each value once; a one-ulp change of a length moves the range by up to 3e-10
  // (docs/web.md), so 1e-9 is the round-off of a shot.
  Engine built = ca;
  built.parts.beam_cm = (ca.L1 - ca.L2) / 2;
  built.parts.beam_inertia = ca.mb * (ca.L1 * ca.L1 - ca.L1 * ca.L2 + ca.L2 * ca.L2) / 3;
  const double difference = relative(shot_of(scaled_design(built)).release.range, reference.release.range);
  std::printf("uniform beam given as built: range %.3g from the ideal shot's\n", difference);
  CHECK(difference < 1e-9);
}

TEST_CASE("a tapered beam of equal ends is the uniform beam with its thickness", "[real]") {
  const double L1 = 4.13, L2 = 0.88, D = 0.3, rho = 700;
  const TaperedBeam beam = tapered_beam(L1, L2, D, D, rho);
  Material wood;
  wood.wood_density = rho;
  const double mb = beam_mass(D, L1 + L2, wood);  // eq:BeamMass
  // A rod from -L2 to L1: c = (L1 - L2)/2, I = mb (L1^2 - L1 L2 + L2^2)/3; each slice, a disc,
  // adds dm D^2/16 about its diameter. Gauss-Legendre is exact here: agreement to round-off.
  CHECK(relative(beam.whole.mass, mb) < 1e-14);
  CHECK(relative(beam.whole.cm, (L1 - L2) / 2) < 1e-14);
  CHECK(relative(beam.whole.inertia, mb * (L1 * L1 - L1 * L2 + L2 * L2) / 3 + mb * D * D / 16) < 1e-14);
  const double short_mass = mb * L2 / (L1 + L2);
  CHECK(relative(beam.short_section.mass, short_mass) < 1e-14);
  CHECK(relative(beam.short_section.cm, -L2 / 2) < 1e-14);
  CHECK(relative(beam.short_section.inertia, short_mass * L2 * L2 / 3 + short_mass * D * D / 16) < 1e-14);
  CHECK(beam.D_pivot == Approx(D).epsilon(1e-15));
}

TEST_CASE("a tapered beam's mass, centre and inertia agree with an independent quadrature", "[real]") {
  const double L1 = 6.0, L2 = 1.5, Dh = 0.5, Dt = 0.2, rho = 700;
  const TaperedBeam beam = tapered_beam(L1, L2, Dh, Dt, rho);
  // Midpoint sums over 200000 slices: error ~ (7.5 m / 2e5)^2, 1e-9 relative.
  const int n = 200000;
  double mass = 0, moment = 0, inertia = 0;
  for (int k = 0; k < n; ++k) {
    const double x = -L2 + (k + 0.5) * (L1 + L2) / n, D = Dh + (Dt - Dh) * (x + L2) / (L1 + L2);
    const double dm = rho * M_PI * D * D / 4 * (L1 + L2) / n;
    mass += dm, moment += x * dm, inertia += (x * x + D * D / 16) * dm;
  }
  CHECK(relative(beam.whole.mass, mass) < 1e-8);
  CHECK(relative(beam.whole.cm, moment / mass) < 1e-8);
  CHECK(relative(beam.whole.inertia, inertia) < 1e-8);
  CHECK(beam.D_pivot == Approx(Dh + (Dt - Dh) * L2 / (L1 + L2)).epsilon(1e-15));
}

TEST_CASE("an engine as built conserves energy with the work of its losses", "[real]") {
  Engine e = alcala_ca();
  e.parts.counterweight_inertia = e.M * (1.2 * 1.2 + 0.9 * 0.9) / 12;  // a 1.2 m by 0.9 m box
  e.parts.axle = {0.1, 0.05};
  e.parts.hinge = {0.15, 0.03};
  e.parts.trough_friction = 0.3;
  e.parts.rope_diameter = 0.02;
  ShotSettings settings;
  settings.air = Air{};
  settings.drag_in_sling = true;
  const Verification v = verify_engine(e, settings);
  // The integrator's error per step is 1e-11 of the state; the drift stays within 1e-10 of
  // Delta U with friction as without (1e-13 to 1e-12 on the paper's engines).
  std::printf("engine as built: energy drift %.3g of Delta U\n", v.energy_drift);
  CHECK(v.energy_drift < 1e-10);
  for (double loss : v.energy.losses) CHECK(loss > 0);
  // Delta U = the projectile's energy at level 0 + what beam and counterweight hold + losses,
  // the one balance the drift measures, closed here from the SI outputs.
  double sum = v.energy.projectile + v.energy.engine;
  for (double loss : v.energy.losses) sum += loss;
  CHECK(std::abs(sum - v.energy.delta_U) / v.energy.delta_U < 1e-10);
  // After the release the air takes more: the projectile's energy at the end is that at the
  // release less the drag's work.
  CHECK(v.energy.flight_drag > 0);
}

TEST_CASE("friction going to zero recovers the frictionless shot", "[real]") {
  const ScaledDesign ideal = scaled_design(alcala_ca());
  const double R0 = shot_of(ideal).release.range;
  ScaledDesign none = ideal;
  none.parts.axle_friction = 0;  // given as 0: the paper's equations, untouched
  CHECK(shot_of(none).release.range == R0);
  // The change is first order in mu r: a tenfold smaller coefficient, a tenfold smaller change
  // (within 5 %, the second order at 1e-3), down to where round-off (1e-10) would show.
  double previous = 0;
  for (double friction : {1e-3, 1e-4, 1e-5}) {
    ScaledDesign d = ideal;
    d.parts.axle_friction = d.parts.hinge_friction = friction;
    d.parts.trough_friction = 10 * friction;
    const double change = R0 - shot_of(d).release.range;
    std::printf("friction %.0e: range shorter by %.4g of it\n", friction, change / R0);
    CHECK(change > 0);
    if (previous > 0) CHECK(previous / change == Approx(10).epsilon(0.05));
    previous = change;
  }
}

TEST_CASE("a small friction costs the first-order work along the frictionless motion", "[real]") {
  const ScaledDesign ideal = scaled_design(alcala_ca());
  std::vector<TracePoint> trace;
  const ShotResult frictionless = shot_of(ideal, &trace, 2e-4);
  const double t_release = frictionless.release.t;
  // To first order each loss is its coefficient times an integral along the motion without it:
  // axle mu r |F_R| |th'|, hinge mu r |F_H| |psi' - th'|, trough mu N |v_x| (in the trough).
  const double axle = integral(trace, t_release, [](const TracePoint& p) {
    return std::hypot(p.snapshot.pivot_reaction.x, p.snapshot.pivot_reaction.y) * std::abs(p.state.theta_dot);
  });
  const double hinge = integral(trace, t_release, [](const TracePoint& p) {
    return std::hypot(p.snapshot.hinge_force.x, p.snapshot.hinge_force.y) * std::abs(p.state.psi_dot - p.state.theta_dot);
  });
  const double trough = integral(trace, t_release, [](const TracePoint& p) {
    return p.phase == Phase::trough ? std::max(p.snapshot.normal_force, 0.0) * std::abs(p.snapshot.projectile_velocity.x) : 0.0;
  });
  const double first_order[3] = {axle, hinge, trough};
  // The work found by the shot with friction, per unit coefficient, departs from the estimate
  // by a term of first order in the coefficient: halving the coefficient halves the departure.
  for (int k = 0; k < 3; ++k) {
    double departure[2];
    for (int half = 0; half < 2; ++half) {
      const double friction = (half ? 0.5e-3 : 1e-3) * (k == trough_loss ? 100 : 1);
      ScaledDesign d = ideal;
      (k == axle_loss ? d.parts.axle_friction : k == hinge_loss ? d.parts.hinge_friction : d.parts.trough_friction) = friction;
      departure[half] = shot_of(d).work[k] / friction / first_order[k] - 1;
    }
    std::printf("loss %d: work / first-order estimate - 1 = %.4g, halved %.4g\n", k, departure[0], departure[1]);
    CHECK(std::abs(departure[0]) < 0.05);
    CHECK(departure[0] / departure[1] == Approx(2).epsilon(0.1));
  }
}

TEST_CASE("the air before the release: none is the vacuum shot, some costs range and balances", "[real]") {
  const Engine ca = alcala_ca();
  const ScaledDesign ideal = scaled_design(ca);
  const ShotResult vacuum = shot_of(ideal);
  // A projectile of no drag area and no rope: the work's extra equations change the step
  // control's sizes, not the motion; the two agree to the integrator's error (1e-9 for R).
  ScaledDesign no_area = ideal;
  no_area.parts.drag = Drag{};
  no_area.parts.drag->drag_coefficient = 0.47;
  const double difference = relative(shot_of(no_area).release.range, vacuum.release.range);
  std::printf("drag of no area before the release: range %.3g from the vacuum shot's\n", difference);
  CHECK(difference < 1e-9);
  // Real air, on the stone and a 2 cm rope: the release is slower, and the air took work.
  Engine e = ca;
  e.parts.rope_diameter = 0.02;
  ShotSettings settings;
  settings.air = Air{};
  settings.drag_in_sling = true;
  const ShotResult dragged = simulate_shot(shot_design(e, settings), ReleaseCriterion{}, IntegratorSettings{});
  CHECK(dragged.release.range < vacuum.release.range);
  CHECK(dragged.work[projectile_drag_loss] > 0);
  CHECK(dragged.work[rope_drag_loss] > 0);
  CHECK(dragged.energy_drift < 1e-10);
}

TEST_CASE("a counterweight's own inertia enters eq:EOM_I_2 and its energy", "[real]") {
  const ScaledDesign ideal = scaled_design(alcala_ca());
  ScaledDesign boxed = ideal;
  boxed.parts.counterweight_inertia = 0.05;  // M L2^2
  const ShotResult shot = shot_of(boxed);
  CHECK(shot.energy_drift < 1e-10);
  // A textbook fact: with the beam held still (an immovable beam, its centre at the pivot), the
  // counterweight swings about the hinge as a compound pendulum, psi'' = -sin psi / L_eq with
  // L_eq = L + I_c/(M L) (scaled: L + I_c/L), the length of the simple pendulum of equal period.
  ScaledDesign held = boxed;
  held.parts.beam = BuiltParts::Beam{0, 1e15};
  const Dynamics dynamics(held);
  State s;
  s.theta = 1.2, s.psi = 0.4;
  const Snapshot snap = dynamics.snapshot(Phase::released, s);
  const double L = held.L(), equivalent = L + 0.05 / L;
  CHECK(snap.psi_ddot == Approx(-std::sin(s.psi) / equivalent).epsilon(1e-12));
  CHECK(std::abs(snap.theta_ddot) < 1e-13);
}

// As tests/test_shot.cpp checks the ideal beam: the moment at the pivot, found from the short
// section's balance (with the hinge pin's friction on it), must balance the long section too,
// whose mass, centre and inertia are the tapered beam's less the short section's; the axle's
// friction acts on the long section's side (dynamics.cpp). Round-off: 1e-12 of M g L2.
TEST_CASE("a tapered beam's bending moment balances both sections, with friction at the pins", "[real]") {
  Engine e = alcala_ca();
  e.parts.D_hinge = 0.32, e.parts.D_tip = 0.18;
  e.mb = wood_beam_mass(e);
  e.parts.axle = {0.2, 0.06}, e.parts.hinge = {0.2, 0.04};
  const ScaledDesign d = scaled_design(e);
  const BuiltParts::Section shortside = *d.short_section();
  const double m_long = d.mu_b - shortside.mass, c_long = (d.mu_b * d.beam_cm() - shortside.mass * shortside.cm) / m_long;
  const double I_long = d.beam_inertia() - shortside.inertia;
  std::vector<TracePoint> trace;
  simulate_shot(d, ReleaseCriterion{}, IntegratorSettings{}, &trace);
  double worst = 0;
  for (const TracePoint& p : trace) {
    if (p.phase == Phase::released) continue;
    const Snapshot& sn = p.snapshot;
    const double sling_moment = sn.tip.x * sn.sling_on_tip.y - sn.tip.y * sn.sling_on_tip.x;
    const double weight_moment = -m_long * c_long * std::sin(p.state.theta);
    const double axle = -d.parts.axle_friction * std::hypot(sn.pivot_reaction.x, sn.pivot_reaction.y) *
        ((p.state.theta_dot > 0) - (p.state.theta_dot < 0));
    const double long_side = I_long * sn.theta_ddot - sling_moment - weight_moment - axle;
    worst = std::max(worst, std::abs(long_side - sn.beam_moment));
  }
  INFO("worst disagreement " << worst << " M g L2");
  CHECK(worst < 1e-12);
}

TEST_CASE("parts outside what a real engine has are refused by name", "[real]") {
  const auto refused = [](auto change, const char* key) {
    Engine e = alcala_ca();
    change(e.parts);
    try {
      check_engine(e);
      FAIL("accepted");
    } catch (const Error& error) {
      INFO(error.what());
      const auto& names = error.names();
      CHECK(std::find(names.begin(), names.end(), key) != names.end());
    }
  };
  refused([](EngineParts& p) { p.axle = {3, 0.05}; }, "axle_friction");
  refused([](EngineParts& p) { p.axle = {0.1, 0}; }, "axle_radius");
  refused([](EngineParts& p) { p.hinge = {0.1, 5}; }, "hinge_radius");
  refused([](EngineParts& p) { p.trough_friction = -0.1; }, "trough_friction");
  refused([](EngineParts& p) { p.beam_cm = 1.0; }, "beam_inertia");
  refused([](EngineParts& p) { p.beam_cm = 9.0, p.beam_inertia = 100; }, "beam_cm");
  refused([](EngineParts& p) { p.beam_cm = 1.0, p.beam_inertia = 1; }, "beam_inertia");
  refused([](EngineParts& p) { p.D_hinge = 0.3; }, "D_tip");
  refused([](EngineParts& p) { p.counterweight_inertia = 1e9; }, "counterweight_inertia");
  refused([](EngineParts& p) { p.rope_diameter = 10; }, "rope_diameter");
  refused([](EngineParts& p) { p.rope_mass = -0.1; }, "rope_mass");
  refused([](EngineParts& p) { p.pouch_mass = -1e-3; }, "pouch_mass");
  refused([](EngineParts& p) { p.pouch_mass = 1e6; }, "pouch_mass");
}

TEST_CASE("calibration recovers a known friction from a synthetic measured range", "[real]") {
  ShotSettings air;
  air.air = Air{};
  // One coefficient at both pins: the engine's pins at mu = 0.12 throw R; calibrating the
  // frictionless engine with the same radii to R gives 0.12 back. R moves 2 % per 0.1 of mu, and
  // its round-off is 1e-10 relative: the coefficient is recovered to 1e-6 with room to spare.
  Engine engine = alcala_ca();
  engine.parts.axle.radius = 0.05, engine.parts.hinge.radius = 0.03;
  const double R = verify_engine(with_friction(engine, FrictionFit::pin_coefficient, 0.12), air).capacity.R;
  const Calibration pins = calibrate(engine, {R, 1.0}, air);
  std::printf("calibrated pin friction: %.10g (true 0.12)\n", pins.value);
  CHECK(pins.fitted == FrictionFit::pin_coefficient);
  CHECK(pins.value == Approx(0.12).epsilon(1e-6));
  // A longer measured range means less friction, a shorter one more.
  CHECK(pins.value_low < pins.value);
  CHECK(pins.value_high > pins.value);
  // The engine's own coefficients, scaled: 0.6 of them is found again.
  Engine own = alcala_ca();
  own.parts.axle = {0.2, 0.05}, own.parts.hinge = {0.05, 0.03}, own.parts.trough_friction = 0.3;
  const double R_scaled = verify_engine(with_friction(own, FrictionFit::scale, 0.6), air).capacity.R;
  const Calibration scaled = calibrate(own, {R_scaled, 0}, air);
  CHECK(scaled.fitted == FrictionFit::scale);
  CHECK(scaled.value == Approx(0.6).epsilon(1e-6));
  CHECK(scaled.shot.capacity.R == Approx(R_scaled).epsilon(1e-9));
  // No friction lengthens a shot: a range beyond the frictionless one is refused.
  try {
    calibrate(engine, {1.01 * pins.frictionless.capacity.R, 0}, air);
    FAIL("a range beyond the frictionless one was fitted");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::out_of_range);
  }
}

TEST_CASE("calibration with a given release explains the range step by step from the optimum to the friction", "[real][release]") {
  // The laboratory engine (arXiv 2502.19442) released by a pin of 30 deg through standard air,
  // its pins 2 cm and 1 cm: a synthetic measured range from mu = 0.3 is explained step by step,
  // each step the shot of its own conditions (the same shots made here apart), the last at the
  // measured range to the fit's 1e-9 (find_root's tolerance on R's root).
  Engine lab = testing::laboratory_engine();
  lab.parts.axle.radius = 0.02, lab.parts.hinge.radius = 0.01;
  ShotSettings settings;
  settings.air = Air{};
  settings.release_at = SetRelease{ReleaseBy::pin_angle, 30};
  const double measured = verify_engine(with_friction(lab, FrictionFit::pin_coefficient, 0.3), settings).capacity.R;
  const Calibration c = calibrate(lab, {measured, 1.5}, settings);
  REQUIRE(c.steps.size() == 4);
  ShotSettings vacuum_optimum;
  ShotSettings vacuum_release = vacuum_optimum;
  vacuum_release.release_at = settings.release_at;
  CHECK(c.steps[0].R == verify_engine(lab, vacuum_optimum).capacity.R);
  CHECK(c.steps[1].R == verify_engine(lab, vacuum_release).capacity.R);
  CHECK(c.steps[2].R == verify_engine(lab, settings).capacity.R);
  CHECK(c.steps[3].R == Approx(measured).epsilon(1e-8));
  CHECK(c.value == Approx(0.3).epsilon(1e-6));
  for (const CalibrationStep& step : c.steps) std::printf("%8.4f m  %s\n", step.R, step.what.c_str());
  // Each condition shortens this shot: the pin of 30 deg lies below the optimum's (35 deg).
  CHECK(c.steps[1].R < c.steps[0].R);
  CHECK(c.steps[2].R < c.steps[1].R);
  CHECK(c.steps[3].R < c.steps[2].R);
}

TEST_CASE("calibration works below the friction at which the engine jams", "[real]") {
  // Pins so wide that coefficients near 0.4 already stop the beam: the fit searches below the
  // jam, finds the coefficient that threw the range, and says where the jam lies.
  Engine engine = alcala_ca();
  engine.parts.axle.radius = 0.8, engine.parts.hinge.radius = 0.03;
  const double R = verify_engine(with_friction(engine, FrictionFit::pin_coefficient, 0.2), ShotSettings{}).capacity.R;
  const Calibration c = calibrate(engine, {R, 0.95 * R}, ShotSettings{});
  CHECK(c.value == Approx(0.2).epsilon(1e-6));
  REQUIRE(c.jams_at);
  CHECK(*c.jams_at < 2);
  CHECK(c.band_clipped);  // 95 % shorter lies beyond the jam
  CHECK(c.value_high < *c.jams_at);
}
