// The ab-initio shot against analytic results, conservation laws, scaling and the paper.
#include <catch2/catch.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>

#include "engines.hpp"
#include "paper_rounding.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;
using namespace trebuchet::testing;

namespace {

// First-order effect on f of the rounding of the printed engine: L1, L2, L4 to 0.005 m,
// M to 0.005 t (0.05 t above 10 t), mb to 0.5 kg; L3 follows from F = 2/3.
double input_rounding(const Engine& printed_engine, const std::function<double(const Engine&)>& f) {
  const double base = f(printed_engine);
  double effect = 0;
  auto vary = [&](double Engine::*field, double half_unit) {
    Engine e = printed_engine;
    e.*field += half_unit;
    e.L3 = counterweight_arm(e.L1, e.L2, e.theta_i_deg, 2.0 / 3);
    effect += std::abs(f(e) - base);
  };
  vary(&Engine::L1, 0.005);
  vary(&Engine::L2, 0.005);
  vary(&Engine::L4, 0.005);
  vary(&Engine::M, printed_engine.M >= 1e4 ? 50 : 5);
  vary(&Engine::mb, 0.5);
  return effect;
}

void check_alcala_row(const std::string& row, const Engine& engine, double level,
                      std::initializer_list<std::pair<const char*, const char*>> expected) {
  ShotSettings settings;
  settings.target_level = level;
  std::printf("%s (simulated from the printed engine)\n", row.c_str());
  const Verification v = verify_engine(engine, settings);
  for (const auto& [name, text] : expected) {
    const std::string key = name;
    auto pick = [&](const Verification& w) {
      if (key == "R") return w.capacity.R;
      if (key == "T") return w.capacity.T / 1e3;
      if (key == "eps") return 100 * w.eps;
      if (key == "v") return w.v;
      if (key == "h") return w.h;
      return w.A_deg;
    };
    const double rounding = input_rounding(engine, [&](const Engine& e) { return pick(verify_engine(e, settings)); });
    check_printed(row + " " + key, pick(v), text, rounding);
  }
}

}  // namespace

// Section 3: at the first instant the counterweight falls straight down with
// a = g sin^2 th (1 - mu_b (l - 1)/2) / (sin^2 th + mu_b (l^2 - l + 1)/3 + mu l^2 cos^2 th),
// so the hinge carries F_H = M (g - a). Exact algebra: agreement to round-off.
TEST_CASE("section 3: the first instant of the motion is analytic", "[shot][physics]") {
  for (double theta_deg : {30.0, 45.0, 60.0})
    for (double l : {3.0, 5.0, 17.0})
      for (double mu : {0.001, 0.01}) {
        const Dynamics e(design_with_L(l, 0.9, 1.5, mu, 0.06, theta_deg));
        State s;
        s.theta = e.theta_i();
        e.complete_trough_state(s);
        const Snapshot first = e.snapshot(Phase::trough, s);
        const double sin2 = std::pow(std::sin(e.theta_i()), 2), cos2 = std::pow(std::cos(e.theta_i()), 2);
        const double mu_b = e.design().mu_b;
        const double a = sin2 * (1 - mu_b * (l - 1) / 2) / (sin2 + mu_b * (l * l - l + 1) / 3 + mu * l * l * cos2);
        CHECK(std::abs(first.hinge_force.x) < 1e-15);
        CHECK(std::abs(first.hinge_force.y - (1 - a)) < 1e-14);
        CHECK(std::abs(first.normal_force - mu) < 1e-15);  // nothing lifts the projectile yet
      }
  const Dynamics paper(design_with_L(5, 0.9, 1.5, 0.01, 0.06, 45));  // theta_i = 45 deg, l = 5, mu_b = 6%, mu = 1%
  State s;
  s.theta = paper.theta_i();
  paper.complete_trough_state(s);
  std::printf("section 3 first instant\n");
  check_printed("1 - F_H/(M g)", 1 - paper.snapshot(Phase::trough, s).hinge_force.y, "0.42", 0);
}

// The model has no friction: E = kinetic + potential is conserved through phases I and II
// (lift-off happens where the normal force is zero, so it does no work). With rk8pd at
// rtol = atol = 1e-11 (the defaults) the drift must stay below 1e-9 of Delta U.
TEST_CASE("energy is conserved to 1e-9 of Delta U at default settings", "[shot][physics]") {
  for (const Engine& engine : {alcala_ca(), alcala_ma_480(), denny_standard()}) {
    const Verification v = verify_engine(engine, ShotSettings{});
    INFO("L1 = " << engine.L1 << ": drift " << v.energy_drift);
    CHECK(v.energy_drift < 1e-9);
  }
}

// eq:ExtraScalings: the equations of motion see only the scaled design, so the same design at
// lambda times the size has the same eps, R ~ L2 and T ~ M L2 ~ lambda^5. The two runs differ
// only by round-off in l, l4, mu, mu_b, which the step control turns into differences of the
// order of the global integration error (rtol 1e-11 over ~50 steps): agreement to 1e-8.
TEST_CASE("the same scaled design at another size gives the same eps, R/L2 and T/(M L2)", "[shot][physics]") {
  const Engine small = alcala_ca();
  const Verification a = verify_engine(small, ShotSettings{});
  for (double lambda : {0.3, 2.5}) {
    const Verification b = verify_engine(resized(small, size_factors(small.L2, small.material, lambda * small.L2, small.material)), ShotSettings{});
    INFO("lambda " << lambda);
    CHECK(std::abs(b.eps - a.eps) < 1e-8);
    CHECK(std::abs(b.capacity.R / (a.capacity.R * lambda) - 1) < 1e-8);
    CHECK(std::abs(b.capacity.T / (a.capacity.T * std::pow(lambda, 5)) - 1) < 1e-8);
    CHECK(std::abs(b.A_deg - a.A_deg) < 1e-5);
  }
}

// Q is size-independent too. F of eq:F uses running force maxima, whose peaks usually fall
// between step ends; they are refined on the continuous solution, so Q does not depend on
// where the steps fall and agrees to the same 1e-8 as eps.
TEST_CASE("the same scaled design at another size gives the same Q", "[shot][physics]") {
  const Engine small = alcala_ca();
  const Verification a = verify_engine(small, ShotSettings{});
  for (double lambda : {0.3, 2.5}) {
    const Verification b = verify_engine(resized(small, size_factors(small.L2, small.material, lambda * small.L2, small.material)), ShotSettings{});
    INFO("lambda " << lambda << ": Q " << a.Q << " and " << b.Q);
    CHECK(std::abs(b.Q / a.Q - 1) < 1e-8);
    CHECK(std::abs(b.force_factor / a.force_factor - 1) < 1e-8);
  }
}

// tab:Alcala_la_Vieja, right-hand columns: simulate each printed engine. Tolerance: the
// printed output's half unit plus the effect of the printed engine's own rounding.
TEST_CASE("tab:Alcala_la_Vieja ab initio, row Ca", "[shot][paper]") {
  check_alcala_row("Alcala Ca", alcala_ca(), 0, {{"R", "150"}, {"T", "40.3"}, {"eps", "90.0"}, {"v", "37.7"}, {"h", "10.0"}, {"A", "40.3"}});
}

TEST_CASE("tab:Alcala_la_Vieja ab initio, row Ma 480 m", "[shot][paper]") {
  check_alcala_row("Alcala Ma 480", alcala_ma_480(), 0, {{"R", "480"}, {"T", "124"}, {"eps", "92.8"}, {"v", "68.5"}, {"A", "39.1"}});
}

// Known difference: h of row Ma 480 comes out 13.90 m against 13.8 m, 1.5 times its rounding
// tolerance, while R, T, eps, v and A agree. h is read at the release, on a flat maximum of Q
// that the force factor places (docs/verifier.md, the open point on Q). Pinned, not hidden.
TEST_CASE("tab:Alcala_la_Vieja ab initio, row Ma 480 m, release height (known difference)", "[shot][paper]") {
  const Verification v = verify_engine(alcala_ma_480(), ShotSettings{});
  std::printf("Alcala Ma 480 h: ours %.3f m, paper 13.8 m (known difference)\n", v.h);
  CHECK(v.h == Approx(13.90).margin(0.01));
}

TEST_CASE("tab:Alcala_la_Vieja ab initio, row Ma 426 m", "[shot][paper]") {
  check_alcala_row("Alcala Ma 426", alcala_ma_426(), 0, {{"R", "426"}, {"T", "111"}, {"eps", "92.5"}, {"v", "64.5"}, {"h", "13.5"}, {"A", "39.1"}});
}

TEST_CASE("tab:Alcala_la_Vieja ab initio, row Sa", "[shot][paper]") {
  check_alcala_row("Alcala Sa", alcala_sa(), 0, {{"R", "250"}, {"T", "66.0"}, {"eps", "91.4"}, {"v", "49.1"}, {"h", "11.7"}, {"A", "39.7"}});
}

// Section 7.1 (sec:AVS): the Ma engine aimed at 426 m flies on to the target 54 m below, landing near
// 481 m with about 137 kJ ("near" and "about": read to their last printed digit).
TEST_CASE("tab:Alcala_la_Vieja row Ma at a target 54 m below", "[shot][paper]") {
  check_alcala_row("Alcala Ma 426 at -54 m", alcala_ma_426(), -54, {{"R", "481"}, {"T", "137"}});
}

TEST_CASE("a beam too heavy to turn is a named error", "[shot]") {
  Engine heavy = alcala_ca();
  heavy.mb = 3000;
  CHECK_THROWS_WITH(verify_engine(heavy, ShotSettings{}), Catch::StartsWith("the beam cannot turn"));
}

// Degenerate engines end in a named error, never in a number (issue 3's list of errors).
TEST_CASE("degenerate engines are named errors", "[shot]") {
  auto message = [](const ScaledDesign& e) {
    try {
      simulate_shot(e, ReleaseCriterion{}, IntegratorSettings{});
    } catch (const Error& error) {
      CHECK(error.kind() == ErrorKind::numerical);
      return std::string(error.what());
    }
    return std::string("no error");
  };
  // A sling three times the long arm: it is still slack in the trough when the beam is upright.
  CHECK_THAT(message(design_with_L(4.7, 3.0, 1.5, 0.3, 0.056, 30)), Catch::StartsWith("the projectile never lifts off"));
  // A projectile of 30 % of M: the trough carries it until the sling stands vertical.
  CHECK_THAT(message(design_with_L(4.7, 0.86, 1.5, 0.3, 0.056, 30)), Catch::StartsWith("the sling stands vertical in the trough"));
  // Found by the random search of docs/verifier.md: the projectile only ever flies backwards.
  CHECK_THAT(message(design_with_L(54.7282, 1.56034, 1.66527, 0.0406626, 0.0027864, 50.6807)),
             Catch::StartsWith("no release sends the projectile forward"));
  // A beam whose long arm outweighs the counterweight's pull (eq:DU).
  CHECK_THAT(message(design_with_L(48.2, 1.7, 0.15, 0.03, 0.044, 30)), Catch::StartsWith("the beam cannot turn"));
}

// Loose, low-order integration must end in a named error rather than a wrong number: the
// energy monitor catches rk2 at rtol 1e-3 on the ordinary Ca engine.
TEST_CASE("loose integration is caught by the energy monitor", "[shot][physics]") {
  ShotSettings loose;
  loose.integrator.stepper = Stepper::rk2;
  loose.integrator.rtol = 1e-3;
  loose.integrator.atol = 1e-3;
  CHECK_THROWS_WITH(verify_engine(alcala_ca(), loose), Catch::Contains("energy drift"));
}

// Issue 12: where the model stops holding before the release, the shot says when. The
// counterweight hangs at most F l cos(theta_i) below the pivot, the base lies l cos(theta_i)
// below it: with F > 1 it can pass below the base, with F <= 1 it cannot. At the start its
// height above the base is cos(theta_i) + 1 + l cos(theta_i) (1 - F), negative for Ca at F = 1.5.
TEST_CASE("a counterweight below the base is warned with its time, and only when F > 1 allows it", "[shot][physics]") {
  auto onset = [](double F) {
    Engine e = alcala_ca();
    e.L3 = counterweight_arm(e.L1, e.L2, e.theta_i_deg, F);
    return simulate_shot(scaled_design(e), ReleaseCriterion{}, IntegratorSettings{});
  };
  const ShotResult hanging = onset(1.5), dipping = onset(1.2);
  REQUIRE(hanging.counterweight_below_base);
  CHECK(*hanging.counterweight_below_base == 0);
  REQUIRE(dipping.counterweight_below_base);
  CHECK(*dipping.counterweight_below_base > 0);
  CHECK(*dipping.counterweight_below_base < dipping.release.t);
  for (double F : {1.0, 2.0 / 3}) {
    INFO("F = " << F);
    CHECK(!onset(F).counterweight_below_base);
    CHECK(!onset(F).slack_sling);
    CHECK(!onset(F).tip_below_base);
  }
  const Verification v = verify_engine(
      [] {
        Engine e = alcala_ca();
        e.L3 = counterweight_arm(e.L1, e.L2, e.theta_i_deg, 1.2);
        return e;
      }(),
      ShotSettings{});
  // And such an engine cannot be built: hanging straight down its counterweight reaches
  // (F - 1) H = 0.2 H below the ground (the clearance's warning, after the model's).
  REQUIRE(v.warnings.size() == 2);
  CHECK_THAT(v.warnings.front(), Catch::StartsWith("the counterweight passes below the engine's base at t = 0.7028 s"));
  CHECK_THAT(v.warnings.back(), Catch::StartsWith("hanging straight down, the counterweight's centre reaches"));
  CHECK(!v.clearance.buildable());
}

// Issue 46: every shot reports the counterweight's clearance above the ground, hanging straight
// down (H - L2 - L3 - half its box, for every machine) and the lowest in the shot, which follows
// it past the release for as long again. Row Ca (F = 2/3) hangs (1 - F) H = H/3 clear; in the
// shot it swings no lower than that, and its swing after the release brings it within 5 % of
// the geometry's bound (it hangs nearly straight down at the bottom of its swing; measured: 0.5 %).
// A box 0.6 m high lowers both by exactly 0.3 m.
TEST_CASE("a shot reports the counterweight's clearance above the ground", "[shot][physics]") {
  Engine ca = alcala_ca();
  const double H = ca.L1 * std::cos(radians(ca.theta_i_deg));
  const Verification v = verify_engine(ca, ShotSettings{});
  std::printf("row Ca: clearance %.6g m hanging straight down (H/3 = %.6g m), %.6g m lowest in the shot\n", v.clearance.geometric, H / 3,
              v.clearance.in_shot.value_or(-1));
  CHECK(v.clearance.geometric == Approx(H / 3).epsilon(1e-12));  // (1 - F) H, F = 2/3 as the table gives it
  REQUIRE(v.clearance.in_shot);
  CHECK(*v.clearance.in_shot >= v.clearance.geometric - 1e-9);  // the geometry's bound holds in the shot
  CHECK(*v.clearance.in_shot < 1.05 * v.clearance.geometric);
  CHECK(v.clearance.buildable());
  ca.parts.box_width = 1, ca.parts.box_height = 0.6;
  ca.parts.counterweight_inertia = ca.M * (1 + 0.36) / 12;  // the box's, as a design's reader sets it
  const Verification boxed = verify_engine(ca, ShotSettings{});
  CHECK(boxed.clearance.geometric == Approx(v.clearance.geometric - 0.3).epsilon(1e-12));
  // F = 1: the counterweight hanging straight down touches the ground, within round-off; buildable.
  Engine touching = alcala_ca();
  touching.L3 = counterweight_arm(touching.L1, touching.L2, touching.theta_i_deg, 1);
  const Verification touches = verify_engine(touching, ShotSettings{});
  CHECK(touches.clearance.geometric == 0);
  CHECK(touches.clearance.buildable());
}

// A heavy projectile (2.5 % of M) on a sling longer than the beam, found in the random set of
// docs/stability.md: the sling would push it before the release. The onset is the root of the
// tension on the continuous solution, so the traced step ends change sign around it.
TEST_CASE("a slack sling is warned at the time its tension changes sign", "[shot][physics]") {
  Engine e;
  e.theta_i_deg = 46.14, e.L1 = 8.1534, e.L2 = 2.7885, e.L3 = 1.41903, e.L4 = 10.1182, e.M = 54672.5, e.m = 1360.62, e.mb = 112.258;
  std::vector<TracePoint> trace;
  const ShotResult shot = simulate_shot(scaled_design(e), ReleaseCriterion{}, IntegratorSettings{}, &trace);
  REQUIRE(shot.slack_sling);
  CHECK(*shot.slack_sling < shot.release.t);
  double last_before = 0, first_after = 0;
  for (const TracePoint& p : trace) {
    if (p.phase == Phase::released) break;
    if (p.t <= *shot.slack_sling)
      last_before = p.snapshot.sling_tension;
    else if (first_after == 0)
      first_after = p.snapshot.sling_tension;
    if (p.t < *shot.slack_sling) CHECK(p.snapshot.sling_tension > -1e-9);  // taut until the onset
  }
  CHECK(last_before >= -1e-9);
  CHECK(first_after < 0);
}

// A free ball lands where it would wherever along its flight it is let go, so the range's slope
// in the release time is the sling's pull times the range's gradient along the sling: the range
// peaks where the tension falls through 0, and the best release is the sling going slack. The
// school's hinged engine releases so. Its tension at the release is 0 to the release's resolution: the slope's
// root is found to 1e-11 in time, and the tension is then within 1e-8 of its peak (measured: 5e-10
// to 8e-9); 1e-5 allowed. Before mark_onsets took that root as the release itself, one L3 in
// two (0.611, 0.613 …) was warned "slack before the release" for a root 1e-11 earlier, and a
// contest lost those engines.
namespace {
// A contest's hinged engine for a school (0.5 kg, 66 kg, its counterweight just clear of the ground).
Engine school_snap(double L3) {
  Engine e;
  e.machine = MachineKind::hinged;
  e.L1 = 1.5267264580503566, e.L2 = 0.6969208550234084, e.L3 = L3, e.L4 = 1.3739445267594228;
  e.M = 65.94936088199641, e.m = 0.5, e.mb = 3.3354709696106473;
  return e;
}
}  // namespace

TEST_CASE("the range peaks where the sling stops pulling, and that release is no slack sling", "[shot][physics]") {
  for (double L3 : {0.610, 0.611, 0.613, 0.625}) {
    const Engine e = school_snap(L3);
    ShotSettings settings;
    settings.criterion.release = Release::range;
    const ScaledDesign d = shot_design(e, settings);
    std::vector<TracePoint> trace;
    const ShotResult shot = simulate_shot(d, release_criterion(e, settings), settings.integrator, &trace);
    const double at_release = Dynamics(d).snapshot(Phase::lifted, shot.release.state).sling_tension;
    double peak = 0;  // sampled: a scale
    for (const TracePoint& p : trace) peak = std::max(peak, p.snapshot.sling_tension);
    std::printf("L3 = %.3f m: tension at the range's best release %.3g of its peak\n", L3, at_release / peak);
    CHECK_FALSE(shot.slack_sling);
    CHECK(std::abs(at_release) <= 1e-5 * peak);
    // Either side of it (1e-3, scaled time), a release given by time throws shorter, the sling
    // pulling before it and pushing after.
    for (double step : {-1e-3, 1e-3}) {
      ReleaseCriterion beside = release_criterion(e, settings);
      beside.given = GivenRelease{ReleaseBy::time, shot.release.t + step, 1};
      const ShotResult other = simulate_shot(d, beside, settings.integrator);
      const double tension = Dynamics(d).snapshot(Phase::lifted, other.release.state).sling_tension;
      CHECK(other.release.range < shot.release.range);
      CHECK((step < 0 ? tension > 0 : tension < 0));
    }
  }
}

// A sling slack for a moment before the range's peak (12 ms here, the tension down to -0.43 m g)
// pulls the ball again: the model stops holding at the onset, the shot says so, and its release
// is the whole window's best, the sling pulling there. (Releasing at the onset instead threw
// 1.7 m, not 32.5.) An engine of the random set of docs/stability.md, found by a review.
TEST_CASE("a sling slack for a moment before the range's peak is warned, not taken as the release", "[shot][physics]") {
  Engine e;
  e.theta_i_deg = 59.0128, e.L1 = 3.2258, e.L2 = 1.3506, e.L4 = 1.2627, e.M = 1000, e.mb = 119.467, e.m = 34.5986;
  e.L3 = counterweight_arm(e.L1, e.L2, e.theta_i_deg, 0.9301);
  ShotSettings settings;
  settings.criterion.release = Release::range;
  const ScaledDesign d = shot_design(e, settings);
  const ShotResult shot = simulate_shot(d, release_criterion(e, settings), settings.integrator);
  REQUIRE(shot.slack_sling);
  CHECK(*shot.slack_sling < shot.release.t);
  CHECK_FALSE(shot.release_before_slack);
  CHECK(Dynamics(d).snapshot(Phase::lifted, shot.release.state).sling_tension > 0);
  const Verification v = verify_engine(e, settings);
  REQUIRE(v.warnings.size() == 1);
  CHECK(v.warnings[0].find("the sling goes slack") != std::string::npos);
  CHECK(v.notes.empty());
  // Through air, a floating arm whose sling, slack from 1.231 s, pulls again 0.6 ms before the
  // range's peak, after the last step end (+0.21 m g there): warned too, its release the peak.
  Engine floating;
  floating.machine = MachineKind::floating_arm, floating.theta_i_deg = 36.5135, floating.L1 = 5.3142, floating.L2 = 2.3658,
  floating.L3 = counterweight_arm(5.3142, 2.3658, 36.5135, 0.7026), floating.L4 = 1.751, floating.M = 739.3055, floating.m = 4.6519,
  floating.mb = 74.3639;
  settings.air = Air{};
  const Verification in_air = verify_engine(floating, settings);
  REQUIRE(in_air.warnings.size() == 1);
  CHECK(in_air.warnings[0].find("the sling goes slack") != std::string::npos);
  CHECK(in_air.notes.empty());
}

TEST_CASE("a slack that sets in and ends between two step ends is warned, without flickering", "[shot][physics]") {
  // The engine above, its sling lengthened toward where the slack disappears (near L4 = 1.3213 m):
  // the tension dips below 0 for a moment that a step of the integrator can span. Read at the
  // step ends alone, the warning came and went with where they fell (at 1.3200 and 1.3204 m
  // none, at 1.3202 m one, the true least pull there about -0.008 of the ball's weight). The
  // minimum between the step ends, found on the interpolant, gives the same answer at each.
  Engine e;
  e.theta_i_deg = 59.0128, e.L1 = 3.2258, e.L2 = 1.3506, e.M = 1000, e.mb = 119.467, e.m = 34.5986;
  e.L3 = counterweight_arm(e.L1, e.L2, e.theta_i_deg, 0.9301);
  ShotSettings settings;
  settings.criterion.release = Release::range;
  const auto warned_at = [&](double L4) {
    e.L4 = L4;
    const Verification v = verify_engine(e, settings);
    return !v.warnings.empty() && v.warnings[0].find("the sling goes slack") != std::string::npos;
  };
  for (int i = 0; i <= 10; ++i) {
    const double L4 = 1.3190 + 2e-4 * i;
    INFO("L4 = " << L4 << " m");
    CHECK(warned_at(L4));
  }
  CHECK_FALSE(warned_at(1.3220));
}

// Through air on the flight alone, the range grows on past that root: the model keeps the ball
// on the sling's circle, pushed, and out of the drag it would meet free. The sling stays slack
// from there, so the release is the best before the onset, and a note says so; nothing is
// warned. With the drag in the sling too, the free ball's argument holds again: the root is the
// range's own peak, and nothing is noted.
TEST_CASE("through air a sling slack up to the range's peak releases before it", "[shot][physics]") {
  ShotSettings settings;
  settings.criterion.release = Release::range;
  settings.air = Air{};
  const Verification held = verify_engine(school_snap(0.611), settings);
  CHECK(held.warnings.empty());
  REQUIRE(held.notes.size() == 1);
  CHECK(held.notes[0].find("stays slack up to the range's peak") != std::string::npos);
  settings.drag_in_sling = true;
  const Verification in_sling = verify_engine(school_snap(0.611), settings);
  CHECK(in_sling.warnings.empty());
  CHECK(in_sling.notes.empty());
}

// The bending moment at the pivot is computed from the short section's balance (dynamics.cpp).
// The long section, a rod of l L2 from the pivot to the tip, must balance it too: the moment it
// takes is I_long th'' - (moment of the sling's pull at the tip) - (its weight's moment), with
// I_long = (mu_b/(l + 1)) l^3/3. Both follow from the equations of motion, which conserve the
// beam's angular momentum about the pivot only if they agree: round-off (1e-13 of M g L2).
TEST_CASE("the beam's bending moment at the pivot balances both sections", "[shot][physics]") {
  for (const Engine& engine : {alcala_ca(), denny_standard(), alcala_ma_480()}) {
    std::vector<TracePoint> trace;
    simulate_shot(scaled_design(engine), ReleaseCriterion{}, IntegratorSettings{}, &trace);
    const ScaledDesign d = scaled_design(engine);
    const double per_length = d.mu_b / (d.l + 1), I_long = per_length * d.l * d.l * d.l / 3;
    double worst = 0;
    for (const TracePoint& p : trace) {
      if (p.phase == Phase::released) continue;
      const Snapshot& s = p.snapshot;
      const double st = std::sin(p.state.theta);
      const double sling_moment = s.tip.x * s.sling_on_tip.y - s.tip.y * s.sling_on_tip.x;
      const double weight_moment = -per_length * d.l * d.l * st / 2;
      const double long_side = I_long * s.theta_ddot - sling_moment - weight_moment;
      worst = std::max(worst, std::abs(long_side - s.beam_moment));
    }
    INFO("L1 = " << engine.L1 << ": worst disagreement " << worst << " M g L2");
    CHECK(worst < 1e-12);
  }
}

// The peak of each load is searched on the continuous solution. It must be at least every
// value of a dense series (every 1e-4 of the shot; the series is the interpolant, good to
// ~1e-10), and above the series' largest by no more than a smooth peak can rise between two
// samples, (dt/2)^2 |f''| / 2 = |second difference| / 8, taken twice over. The pivot force's
// peak is also F_R of eq:F, found by the running extremes: the two searches agree to 1e-9.
TEST_CASE("a builder's load peaks are the largest values up to the release", "[shot][physics]") {
  for (const Engine& engine : {alcala_ca(), denny_standard()}) {
    const Verification v = verify_engine(engine, ShotSettings{});
    std::vector<TracePoint> trace;
    verify_engine(engine, ShotSettings{}, &trace, v.t_release / 1e4);
    const double time_unit = std::sqrt(engine.L2 / engine.material.g);
    std::vector<std::array<double, load_count>> series;
    for (const TracePoint& p : trace)
      if (p.phase != Phase::released && p.t * time_unit <= v.t_release) series.push_back(load_values(p.snapshot));
    const double Mg = engine.M * engine.material.g, unit[load_count] = {Mg, Mg, Mg, Mg * engine.L2};
    for (int k = 0; k < load_count; ++k) {
      std::size_t top = 0;
      for (std::size_t i = 0; i < series.size(); ++i)
        if (series[i][k] > series[top][k]) top = i;
      const double largest = series[top][k];
      const double rise = top > 0 && top + 1 < series.size() ? std::abs(series[top - 1][k] - 2 * largest + series[top + 1][k]) / 8 : 0;
      const double peak = v.loads[k].value / unit[k];
      INFO("load " << k << ": peak " << peak << " at " << v.loads[k].t << " s, dense series " << largest << ", rise allowed " << rise);
      CHECK(peak >= largest * (1 - 1e-9));
      CHECK(peak <= largest * (1 + 1e-9) + 2 * rise);
      CHECK(v.loads[k].t <= v.t_release);
    }
    CHECK(std::abs(v.loads[pivot_load].value / v.FR - 1) < 1e-9);
  }
}

// Section 7, Malvecino: "The potential energy stored in the engine before the shot is
// 111kJ/0.925=120kJ" for the row Ma 426 m engine: Delta U of eq:DU from the printed engine,
// within half a unit of "120" and the rounding of the printed engine.
TEST_CASE("section 7: the Malvecino engine stores 120 kJ", "[shot][paper]") {
  std::printf("section 7, Malvecino (row Ma 426 m)\n");
  const Engine e = alcala_ma_426();
  check_printed("Delta U [kJ]", potential_energy_drop(e) / 1e3, "120",
                input_rounding(e, [](const Engine& x) { return potential_energy_drop(x) / 1e3; }));
}

// Section 7, Saone: the row Sa engine's 50 kg stones "arriving at ~185 km/h": the speed at the
// target level from the shot's T = m v^2/2, within half a unit of "185" and the rounding of the
// printed engine.
TEST_CASE("section 7: Saone's stones arrive at 185 km/h", "[shot][paper]") {
  std::printf("section 7, Saone (row Sa)\n");
  auto arrival_km_h = [](const Engine& x) { return std::sqrt(2 * verify_engine(x, ShotSettings{}).capacity.T / x.m) * 3.6; };
  const Engine e = alcala_sa();
  check_printed("arrival speed [km/h]", arrival_km_h(e), "185", input_rounding(e, arrival_km_h));
}
