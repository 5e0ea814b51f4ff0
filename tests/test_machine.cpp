// The seam for machines (machine.hpp): the paper's engine behind it shoots as before, and a
// second machine, the fixed counterweight (fixed_counterweight.hpp), shoots through the same
// code. Its equations are held to an independently written Lagrangian, its shot to the
// conservation of energy, which the shot measures on every step, and to the hinged engine's as
// the hinged counterweight's arm shrinks to nothing.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "engines.hpp"
#include "trebuchet/fixed_counterweight.hpp"
#include "trebuchet/floating_arm.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/dynamics.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/scaling_table.hpp"
#include "trebuchet/shot.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;

namespace {

using trebuchet::testing::design_with_L;

// A fixed-counterweight engine with a uniform beam and a counterweight of its own inertia, its
// centre L = 0.3 beyond the short arm's end.
ScaledDesign fixed_design(double L = 0.3) {
  ScaledDesign d = design_with_L(4, 0.8, L, 0.01, 0.06, 45);
  d.machine = MachineKind::fixed;
  d.parts.counterweight_inertia = 0.3;
  return d;
}

// A floating arm: its counterweight hangs L = 0.4 below its pin, in the guide.
ScaledDesign floating_design() {
  ScaledDesign d = design_with_L(4.5, 0.9, 0.4, 0.012, 0.05, 40);
  d.machine = MachineKind::floating_arm;
  return d;
}

// The machines' Lagrangians in phase II, written from their bodies alone: the uniform beam (mass
// mu_b over -1..l along it: centre (l - 1)/2, inertia mu_b (l^3 + 1)/(3 (l + 1)) about the
// pivot, so mu_b (l + 1)^2/12 about its centre), the counterweight (mass 1) and the projectile
// (mass mu) on the sling of length l l4 from the tip. Positions in x right, y up; g = 1.
struct Body {
  double x, y, vx, vy;
};
double particle(double mass, const Body& b) { return mass * (b.vx * b.vx + b.vy * b.vy) / 2 - mass * b.y; }

// The beam about a pivot at (px, 0) moving at px', at angle th from the downward vertical.
double beam_and_projectile(const ScaledDesign& d, double px, double px_d, double th, double phi, double th_d, double phi_d) {
  const double l = d.l, c = (l - 1) / 2, s = l * d.l4;
  const Body centre{px + c * std::sin(th), -c * std::cos(th), px_d + c * std::cos(th) * th_d, c * std::sin(th) * th_d};
  const double own_inertia = d.mu_b * (l + 1) * (l + 1) / 12;
  const Body tip{px + l * std::sin(th), -l * std::cos(th), px_d + l * std::cos(th) * th_d, l * std::sin(th) * th_d};
  const Body projectile{tip.x - s * std::cos(phi), tip.y - s * std::sin(phi), tip.vx + s * std::sin(phi) * phi_d, tip.vy - s * std::cos(phi) * phi_d};
  return particle(d.mu_b, centre) + own_inertia * th_d * th_d / 2 + particle(d.mu, projectile);
}

double fixed_lagrangian(const ScaledDesign& d, double th, double phi, double th_d, double phi_d) {
  const double r = 1 + d.L();  // the counterweight's centre from the pivot
  const Body counterweight{-r * std::sin(th), r * std::cos(th), -r * std::cos(th) * th_d, -r * std::sin(th) * th_d};
  return beam_and_projectile(d, 0, 0, th, phi, th_d, phi_d) + particle(1, counterweight) + d.parts.counterweight_inertia * th_d * th_d / 2;
}

// Rolling: the pin, at the pivot less (sin th, -cos th), stays at x = 0.
double floating_lagrangian(const ScaledDesign& d, double th, double phi, double th_d, double phi_d) {
  const Body counterweight{0, std::cos(th) - d.L(), 0, -std::sin(th) * th_d};
  return beam_and_projectile(d, std::sin(th), std::cos(th) * th_d, th, phi, th_d, phi_d) + particle(1, counterweight);
}

// The largest residual of d/dt dL/dq' - dL/dq = 0 along a machine's phase-II accelerations over
// 50 random states, the derivatives by central differences of step 1e-4 (truncation ~1e-8 of
// terms of order 1, round-off ~1e-12).
template <class Lagrangian>
double euler_lagrange_residual(const Machine& machine, Lagrangian lagrangian) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> angle(-2, 2), speed(-3, 3);
  double worst = 0;
  for (int trial = 0; trial < 50; ++trial) {
    State s;
    s.theta = angle(random), s.phi = angle(random), s.theta_dot = speed(random), s.phi_dot = speed(random);
    std::array<double, 3> a;
    REQUIRE(machine.accelerations(Phase::lifted, s, a) == Evaluated::found);
    const double h = 1e-4;
    const double q[4] = {s.theta, s.phi, s.theta_dot, s.phi_dot};
    const auto L = [&](const double* x) { return lagrangian(machine.design(), x[0], x[1], x[2], x[3]); };
    const auto partial = [&](int i, const double* x) {
      double up[4] = {x[0], x[1], x[2], x[3]}, down[4] = {x[0], x[1], x[2], x[3]};
      up[i] += h, down[i] -= h;
      return (L(up) - L(down)) / (2 * h);
    };
    // d/dt of dL/dq'_j = sum over state k of d(dL/dq'_j)/dx_k x'_k, with x' = (th', phi', th'', phi'').
    const double rates[4] = {s.theta_dot, s.phi_dot, a[0], a[2]};
    for (int j = 0; j < 2; ++j) {
      double time_derivative = 0;
      for (int k = 0; k < 4; ++k) {
        double up[4] = {q[0], q[1], q[2], q[3]}, down[4] = {q[0], q[1], q[2], q[3]};
        up[k] += h, down[k] -= h;
        time_derivative += (partial(2 + j, up) - partial(2 + j, down)) / (2 * h) * rates[k];
      }
      worst = std::max(worst, std::abs(time_derivative - partial(j, q)));
    }
  }
  return worst;
}

}  // namespace

// A sign or a factor wrong in a machine's equations leaves a residual of order 0.1 to 1.
TEST_CASE("the fixed counterweight's and the floating arm's phase II follow from their Lagrangians", "[machine]") {
  const double fixed = euler_lagrange_residual(FixedCounterweight(fixed_design()), fixed_lagrangian);
  const double floating = euler_lagrange_residual(FloatingArm(floating_design()), floating_lagrangian);
  INFO("largest Euler-Lagrange residual: fixed " << fixed << ", floating arm " << floating);
  CHECK(fixed < 1e-5);
  CHECK(floating < 1e-5);
}

// The shot tracks the bodies' energy against its start on every accepted step, both phases,
// and fails above 1e-6 of Delta U (IntegratorSettings): a phase-I equation or a lift-off state
// out of step with the energy would show here. At the default tolerances the drift of a
// consistent machine stays near 1e-13, as the paper's engine's does (docs/performance.md).
// Delta U itself (ScaledDesign::energy_drop) is checked as the bodies' energy at rest less
// theirs with the beam upright and the projectile at the pivot's level, from the snapshots.
TEST_CASE("the fixed counterweight and the floating arm shoot through the seam, conserving their energy", "[machine]") {
  for (const ScaledDesign& d : {fixed_design(), floating_design()}) {
    const auto machine = machine_of(d);
    const ShotResult shot = simulate_shot(*machine, ReleaseCriterion{}, IntegratorSettings{});
    INFO((d.machine == MachineKind::fixed ? "fixed" : "floating arm")
         << ": lift-off at t = " << shot.t_liftoff << ", release at t = " << shot.release.t << ", range " << shot.release.range << " L2, eps "
         << shot.release.efficiency << ", energy drift " << shot.energy_drift);
    CHECK(shot.t_liftoff > 0);
    CHECK(shot.release.t > shot.t_liftoff);
    CHECK(shot.release.range > 0);
    CHECK(shot.release.efficiency > 0);
    CHECK(shot.release.efficiency < 1);
    CHECK(shot.energy_drift < 1e-11);  // issue 36's bound; a wrong phase I gave 1e-2
    State rest, upright;
    rest.theta = machine->theta_i(), upright.theta = M_PI;
    const Snapshot start = machine->snapshot(Phase::released, rest), end = machine->snapshot(Phase::released, upright);
    CHECK(start.energy - end.energy == Approx(d.energy_drop()).epsilon(1e-14));
    // At rest the trough carries the projectile's weight.
    CHECK(machine->snapshot(Phase::trough, rest).normal_force == Approx(d.mu).epsilon(1e-12));
  }
}

// The floating arm's pin stays on the guide's line, its counterweight falls straight, and the
// rail takes no horizontal force: the frame's reaction on the axle is vertical all through.
TEST_CASE("the floating arm's counterweight falls in its guide and its rail pushes only up", "[machine]") {
  const FloatingArm machine(floating_design());
  std::vector<TracePoint> trace;
  simulate_shot(machine, ReleaseCriterion{}, IntegratorSettings{}, &trace);
  double worst_x = 0, worst_rail = 0;
  for (const TracePoint& p : trace) {
    worst_x = std::max(worst_x, std::abs(p.snapshot.hinge.x) + std::abs(p.snapshot.counterweight.x));
    worst_rail = std::max(worst_rail, std::abs(p.snapshot.pivot_reaction.x));
  }
  INFO(trace.size() << " points: largest |x| of the pin and the counterweight " << worst_x << ", of the rail's force " << worst_rail << " M g");
  CHECK(worst_x < 1e-15);
  CHECK(worst_rail < 1e-12);
}

// Issue 36's limit case: a floating arm whose rail is locked and whose guide is taken away, with
// its counterweight's centre on its pin and no inertia of its own, is the fixed counterweight's
// point at the short arm's end. Their equations are written apart (floating_arm.cpp's
// counterweight moves with the pin, fixed_counterweight.cpp's turns with the beam) and round
// differently, the adaptive steps differ: at rtol = atol = 1e-13 the two shots' global errors
// (some 1e-12 of the range, docs/performance.md's convergence) bound how near they come, and
// 1e-11 allows for that. A counterweight a part in 1e6 heavier moves the range by about 1e-6.
TEST_CASE("a floating arm with its rail locked and no guide is the fixed counterweight at the arm's end", "[machine]") {
  ScaledDesign d = fixed_design(0);
  d.parts.counterweight_inertia = 0;
  IntegratorSettings tight;
  tight.rtol = tight.atol = 1e-13;
  const ShotResult fixed = simulate_shot(FixedCounterweight(d), ReleaseCriterion{}, tight);
  const ShotResult locked = simulate_shot(FloatingArm(d, FloatingArm::Rail::locked), ReleaseCriterion{}, tight);
  std::printf("fixed: range %.15g L2 at t = %.15g; locked floating arm: %.15g at %.15g\n", fixed.release.range, fixed.release.t, locked.release.range,
              locked.release.t);
  CHECK(locked.release.range == Approx(fixed.release.range).epsilon(1e-11));
  CHECK(locked.release.t == Approx(fixed.release.t).epsilon(1e-11));
  CHECK(locked.release.efficiency == Approx(fixed.release.efficiency).epsilon(1e-11));
  CHECK_THROWS_AS(FloatingArm(fixed_design(0.3), FloatingArm::Rail::locked), Error);  // a hanging counterweight would swing
}

// The paper's engine behind the seam is the same engine: the overload for a design checks it and
// hands its Dynamics over, and the two give the same shot to the last bit.
TEST_CASE("the paper's engine shoots the same through the seam", "[machine]") {
  ScaledDesign d;
  d.l = 5, d.l4 = 0.9, d.mu_b = 0.06, d.mu = 0.01, d.theta_i_deg = 45;
  const ShotResult by_design = simulate_shot(d, ReleaseCriterion{}, IntegratorSettings{});
  const ShotResult by_machine = simulate_shot(Dynamics(d), ReleaseCriterion{}, IntegratorSettings{});
  CHECK(by_design.release.t == by_machine.release.t);
  CHECK(by_design.release.quality == by_machine.release.quality);
  CHECK(by_design.steps == by_machine.steps);
}

// As the hinged counterweight's arm L = L3/L2 shrinks, the hinged engine (a point counterweight
// on an ever shorter pendulum) tends to the fixed one: its counterweight stays within L of the
// hinge, swinging about the angle the beam's acceleration tilts it to, ever faster (as L^-1/2).
// Both are released at the fixed machine's optimal time, and their ranges compared over eight
// arms from L = 0.04 down by halves to 3.1e-4. The swing's phase at the release scatters each
// difference below an envelope C L (measured: 0.04 L to 1.4 L), so the rate is tested as that
// envelope: every relative difference below 2 L, over two and a half decades. A fixed machine
// whose range were off by a part in a hundred fails it from L = 2.5e-3 down.
TEST_CASE("the hinged engine tends to the fixed one as its counterweight arm shrinks", "[machine]") {
  ScaledDesign fixed = fixed_design(0);
  fixed.parts.counterweight_inertia = 0;  // a point at the short arm's end, as the hinged engine's
  const ShotResult reference = simulate_shot(FixedCounterweight(fixed), ReleaseCriterion{}, IntegratorSettings{});
  ReleaseCriterion at_that_time;
  at_that_time.given = GivenRelease{ReleaseBy::time, reference.release.t, 1};
  for (int k = 0; k < 8; ++k) {
    const double L = 0.04 / std::pow(2, k);
    ScaledDesign hinged = design_with_L(fixed.l, fixed.l4, L, fixed.mu, fixed.mu_b, fixed.theta_i_deg);
    const ShotResult shot = simulate_shot(hinged, at_that_time, IntegratorSettings{});
    const double difference = std::abs(shot.release.range / reference.release.range - 1);
    std::printf("L3/L2 = %.3g: range %.10g L2 against the fixed machine's %.10g: %.2e = %.3f L\n", L, shot.release.range, reference.release.range,
                difference, difference / L);
    CHECK(difference < 2 * L);
  }
}

// The other machines' scaling tables (data/cpnc-fixed.json, data/cpnc-floating-arm.json, derived
// ab initio by scripts/derive-tables.sh): the calculator's design for a capacity, shot ab initio
// as its machine, delivers that capacity. Seven capacities along the table's X (Y = 0), both
// blocks. The designs come from the fitted power laws, whose largest deviation from the optima
// is 0.57 % for the fixed machine and, in one parameter of the floating arm's first segment,
// 15 % (each segment's fit_max_deviation in the file); R and T, which depend on all the lengths
// and masses together, came within 0.16 % and 0.9 % when measured. The bound, 2 %, allows for
// the fits. The paper's engine for 150 m and 40 kJ (tab:CPNC), built as the fixed machine, misses
// T by 4.4 %, and as the floating arm R by 3.2 %: a table of the wrong machine fails here.
TEST_CASE("the fixed machine's and the floating arm's tables design engines that deliver their capacity", "[machine][table]") {
  for (MachineKind machine : {MachineKind::fixed, MachineKind::floating_arm})
    for (double theta : {30.0, 40.0})
      for (double X = -0.5; X <= 0.51; X += 1.0 / 6) {
        const double lt = -X / std::sqrt(26.0), lr = -5 * lt;  // Y = 0 (eq:XY_RT)
        DesignRequest request;
        request.first = {Quantity::R, 240 * std::exp(lr)}, request.second = {Quantity::T, 26e3 * std::exp(lt)};
        request.theta_i_deg = theta;
        const OptimalEngine design = design_optimal_engine(builtin_scaling_table(machine), request);
        REQUIRE(design.engine.machine == machine);
        CHECK(design.engine.L3 == 0);
        const Verification shot = verify_engine(design.engine, ShotSettings{});
        const double dR = shot.capacity.R / request.first.value - 1, dT = shot.capacity.T / request.second.value - 1;
        std::printf("machine %d, theta %g, X = %+.3f: R %+.2e, T %+.2e\n", static_cast<int>(machine), theta, X, dR, dT);
        CHECK(std::abs(dR) < 0.02);
        CHECK(std::abs(dT) < 0.02);
      }
}

// The fixed counterweight and the floating arm as built: Coulomb friction at the axle (and at
// the floating arm's pin), in the trough, and the air on the projectile before the release. The
// shot integrates each loss's power beside the motion, and the bodies' energy plus the work of
// the losses is conserved (drift < 1e-11 of Delta U, as for the ideal machines): a friction
// force whose power were not the one its generalized force does would break that balance at
// the size of the loss (here 0.3 % to 1 % of Delta U). Each loss takes energy, and together they
// shorten the range. (The air alone is held to an independent integration,
// tests/machines/independent.py.)
TEST_CASE("the fixed counterweight and the floating arm with friction and air balance their energy", "[machine]") {
  for (ScaledDesign d : {fixed_design(), floating_design()}) {
    const ShotResult ideal = simulate_shot(d, ReleaseCriterion{}, IntegratorSettings{});
    d.parts.axle_friction = 0.004;  // mu r/L2: 0.1 on an axle of 4 % of L2
    if (d.machine == MachineKind::floating_arm)
      d.parts.hinge_friction = 0.003;
    else
      d.parts.counterweight_inertia = 0.3;
    d.parts.trough_friction = 0.3;
    d.parts.drag = Drag{1e-3, 0.47, 0, 0};  // rho A/(2 m) in 1/L2: a 50 kg stone's, 1.1e-3 per metre, at L2 = 1 m
    const ShotResult shot = simulate_shot(d, ReleaseCriterion{}, IntegratorSettings{});
    double lost = 0;
    for (double w : shot.work) lost += w;
    std::printf("%s as built: range %.6g L2 (ideal %.6g), losses %.3g %.3g %.3g %.3g of Delta U, drift %.2e\n",
                d.machine == MachineKind::fixed ? "fixed" : "floating arm", shot.release.range, ideal.release.range,
                shot.work[axle_loss] / d.energy_drop(), shot.work[hinge_loss] / d.energy_drop(), shot.work[trough_loss] / d.energy_drop(),
                shot.work[projectile_drag_loss] / d.energy_drop(), shot.energy_drift);
    CHECK(shot.energy_drift < 1e-11);
    CHECK(shot.work[axle_loss] > 0);
    CHECK(shot.work[trough_loss] > 0);
    CHECK(shot.work[projectile_drag_loss] > 0);
    CHECK((d.machine == MachineKind::fixed) == (shot.work[hinge_loss] == 0));
    CHECK(lost > 1e-3 * d.energy_drop());
    CHECK(shot.release.range < ideal.release.range);
  }
  // The fixed counterweight has no hinge pin: its friction is refused, not ignored.
  ScaledDesign bolted = fixed_design();
  bolted.parts.hinge_friction = 0.003;
  CHECK_THROWS_AS(FixedCounterweight(bolted), Error);
}

// The fixed counterweight's centre lies L3 beyond the short arm's end: held level, it bends the
// beam at the pivot by M g (L2 + L3), and the stress at rest is that moment over the section
// modulus pi D^3/32 (the hinged engine's hangs from the arm's end: M g L2).
TEST_CASE("the fixed counterweight's beam at rest carries its weight at its own lever", "[machine]") {
  Engine e = trebuchet::testing::alcala_ca();
  e.D = 0.3;
  e.L3 = 0.4;
  ShotSettings settings;
  for (MachineKind machine : {MachineKind::hinged, MachineKind::fixed}) {
    e.machine = machine;
    const Verification v = verify_engine(e, settings);
    REQUIRE(v.beam);
    const double lever = machine == MachineKind::fixed ? e.L2 + e.L3 : e.L2;
    const double expected = e.M * e.material.g * lever * 32 / (M_PI * e.D * e.D * e.D);
    std::printf("%s: stress at rest %.9g Pa, M g lever 32/(pi D^3) = %.9g Pa\n", machine == MachineKind::fixed ? "fixed" : "hinged",
                v.beam->stress_at_rest, expected);
    CHECK(v.beam->stress_at_rest == Approx(expected).epsilon(1e-12));  // two orders of the same products
  }
}
