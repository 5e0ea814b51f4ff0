// The verifier against tab:Denny, tab:SketchBook-I, tab:SketchBook-II and tab:Large_Eff.
// Each printed engine is simulated as printed; tolerances are half a unit of the printed
// result plus the first-order effect of the rounding of the printed inputs.
#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "paper_rounding.hpp"
#include "trebuchet/capacity_fit.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/app/input/units.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;
using namespace trebuchet::testing;

namespace {

// tab:Denny rows: theta_i, F, then Lb, H, L4 [m], M [t], m, mb [kg]. L1 = H/cos theta_i.
Engine denny_engine(double theta_i_deg, const std::vector<double>& x) {
  Engine e;
  e.theta_i_deg = theta_i_deg;
  e.L1 = x[2] / std::cos(radians(theta_i_deg));
  e.L2 = x[1] - e.L1;
  e.L3 = counterweight_arm(e.L1, e.L2, theta_i_deg, x[0]);
  e.L4 = x[3], e.M = x[4] * 1000, e.m = x[5], e.mb = x[6];
  return e;
}

// tab:SketchBook-I and -II rows: F, theta_i, then L1, L4 [m], M [t], m, mb [kg], l.
Engine sketchbook_engine(double F, double theta_i_deg, const std::vector<double>& x) {
  Engine e;
  e.theta_i_deg = theta_i_deg;
  e.L1 = x[0], e.L2 = x[0] / x[5], e.L4 = x[1], e.M = x[2] * 1000, e.m = x[3], e.mb = x[4];
  e.L3 = counterweight_arm(e.L1, e.L2, theta_i_deg, F);
  return e;
}

struct VerifierColumn {
  const char* key;
  const char* text;
  double known = 1;  // > 1: a documented difference, allowed this multiple of the rounding tolerance
};

double shot_figure(const Verification& v, const std::string& key) {
  if (key == "R") return v.capacity.R;
  if (key == "T") return v.capacity.T / 1e3;
  if (key == "eps") return 100 * v.eps;
  if (key == "Q") return 100 * v.Q;
  if (key == "v") return v.v;
  if (key == "h") return v.h;
  if (key == "x") return -v.x;  // the paper's "6.0 m behind the pivot"; x runs toward the target
  return v.A_deg;
}

// Simulates the printed engine and checks each expected column to the rounding of inputs and
// outputs. Inputs marked exact in the paper (bold) are passed as e.g. "12" with extra digits.
void check_shot_row(const std::string& row, const std::vector<std::string>& inputs, const std::function<Engine(const std::vector<double>&)>& build,
                    const ShotSettings& settings, const std::vector<VerifierColumn>& expected) {
  std::vector<double> values;
  for (const auto& text : inputs) values.push_back(printed(text).value);
  const Verification v = verify_engine(build(values), settings);
  std::printf("%s (simulated from the printed engine)\n", row.c_str());
  for (const VerifierColumn& e : expected) {
    const std::string key = e.key;
    const double rounding = input_rounding_effect(inputs, build,
                                                  [&](const Engine& engine) { return shot_figure(verify_engine(engine, settings), key); });
    const double tolerance = e.known * (printed(e.text).half_unit + rounding);
    check_printed(row + " " + key + (e.known > 1 ? " (known)" : ""), shot_figure(v, key), e.text, tolerance - printed(e.text).half_unit);
  }
}

}  // namespace

// tab:Denny "Present": Denny's standard engine, Lb = 12 m, M = 10 t, m = 100 kg, mb = 2000 kg
// exact (bold); H = 6.15 m, L4 = 7.9 m and F = 0.93 as printed. Denny's figure is a maximum
// range, and the paper's row is the release at maximum range: released there, the engine
// reproduces R, T, eps, v and the release point of section 6.3 (20.2 m high, 6.0 m behind the
// pivot). Released at the maximum of Q instead, it gives Q = 1.7 % as printed, but 1.4 % more T.
TEST_CASE("tab:Denny Present row: Denny's standard engine released at maximum range", "[verify][paper]") {
  const auto build = [](const std::vector<double>& x) { return denny_engine(45, x); };
  const std::vector<std::string> inputs = {"0.93", "12.0000", "6.15", "7.9", "10.0000", "100.000", "2000.00"};
  ShotSettings at_max_range;
  at_max_range.criterion.release = Release::range;
  check_shot_row("tab:Denny Present, max range", inputs, build, at_max_range,
                 {{"R", "425"}, {"T", "224"}, {"eps", "48.4"}, {"Q", "1.7"}, {"v", "64"}, {"h", "20.2"}, {"x", "6.0"}});
  check_shot_row("tab:Denny Present, max Q", inputs, build, ShotSettings{}, {{"R", "425"}, {"Q", "1.7"}, {"v", "64"}});
}

namespace {

// tab:Large_Eff: F = 1, theta_i = 30 deg, capacity R = 450 m, T = 232 kJ, released at the
// maximum of Q_eps = eps (appendix B). The printed shape (l, l4 = L4/L1, mu_b = mb/M) is
// fitted to the capacity (section 5, steps 2-4), then the angles at release are read.
struct LargeEffRow {
  const char* l;
  const char* L1;
  const char* L4;
  const char* M_t;
  const char* mb;
};

ScaledDesign large_eff_shape(const std::vector<double>& x) { return {x[0], x[2] / x[1], x[4] / (x[3] * 1000), 0, 30, 1}; }

// The l = 17 engine of tab:Large_Eff, fitted to the table's capacity and released at max eps.
ShotSettings at_max_efficiency() {
  ShotSettings settings;
  settings.criterion.release = Release::efficiency;
  return settings;
}

Engine large_eff_17() { return fit_capacity(large_eff_shape({17, 0.800, 0.673, 270, 14.7}), {450, 232e3}, Material{}, at_max_efficiency()).engine; }

struct ReleaseAngles {
  Engine engine;
  Verification v;
  double theta_minus_180, psi, phi_minus_180;  // [deg], as tab:Large_Eff prints them
  double counterweight_fall;  // from rest to the release [m]
};

ReleaseAngles fitted_release(const std::vector<double>& x) {
  const ShotSettings settings = at_max_efficiency();
  const CapacityFit fit = fit_capacity(large_eff_shape(x), {450, 232e3}, Material{}, settings);
  std::vector<TracePoint> trace;
  const Verification v = verify_engine(fit.engine, settings, &trace);
  const auto release = std::find_if(trace.rbegin(), trace.rend(), [](const TracePoint& p) { return p.phase == Phase::lifted; });
  const State& s = release->state;  // the last point of phase II is the release
  const double fall = (trace.front().snapshot.counterweight.y - release->snapshot.counterweight.y) * fit.engine.L2;
  return {fit.engine, v, degrees(s.theta) - 180, degrees(s.psi), std::remainder(degrees(s.phi), 360) + 180, fall};
}

}  // namespace

// Besides the angles, the table's absolute engine (L2 and m follow from the fit to the
// capacity) and appendix B's words: the release "from a low position ~2 m" (l = 17) and "a high
// position ~40 m" (l = 59), read to the unit of their last digit; "the 270 ton counterweight
// falls only ~9 cm" and "the 71 ton counterweight now falls about 1/2 m" up to the release,
// read as 9 +- 1 cm and 0.5 +- 0.1 m.
TEST_CASE("tab:Large_Eff with Q_eps: efficiencies near 99.5 % and the angles at release", "[verify][paper][stiff]") {
  const std::vector<std::pair<std::vector<std::string>, std::vector<VerifierColumn>>> rows = {
      {{"17", "0.800", "0.673", "270", "14.7"},
       {{"eps", "99.53"},
        {"theta", "-1.95"},
        {"psi", "-1.98"},
        {"phi", "45.1"},
        {"A", "44.9"},
        {"L1", "0.800"},
        {"L2", "0.047"},
        {"L4", "0.673"},
        {"M", "270"},
        {"m", "104", 1.5},
        {"mb", "14.7"},
        {"h", "2", 0.5},
        {"fall", "0.09", 0.01}}},
      {{"59", "14.9", "18.2", "71.5", "729"},
       {{"eps", "99.50"},
        {"theta", "-1.22"},
        {"psi", "-0.91"},
        {"phi", "47.6"},
        {"A", "42.6"},
        {"L1", "14.9"},
        {"L2", "0.25"},
        {"L4", "18.2"},
        {"M", "71.5"},
        {"m", "93.5"},
        {"mb", "729"},
        {"h", "40", 5},
        {"fall", "0.5", 0.1}}},
  };
  for (const auto& [inputs, expected] : rows) {
    std::vector<double> x;
    for (const auto& text : inputs) x.push_back(printed(text).value);
    auto value = [](const ReleaseAngles& r, const std::string& key) {
      if (key == "eps") return 100 * r.v.eps;
      if (key == "theta") return r.theta_minus_180;
      if (key == "psi") return r.psi;
      if (key == "phi") return r.phi_minus_180;
      if (key == "L1") return r.engine.L1;
      if (key == "L2") return r.engine.L2;
      if (key == "L4") return r.engine.L4;
      if (key == "M") return r.engine.M / 1e3;
      if (key == "m") return r.engine.m;
      if (key == "mb") return r.engine.mb;
      if (key == "h") return r.v.h;
      if (key == "fall") return r.counterweight_fall;
      return r.v.A_deg;
    };
    const ReleaseAngles ours = fitted_release(x);
    std::printf("tab:Large_Eff l = %s (shape fitted to 450 m, 232 kJ): F_R = %.2f Mg, F_S_perp = %.0f mg\n", inputs[0].c_str(), ours.v.FR_Mg,
                ours.v.FS_perp_mg);
    const double sling_tension_mg = ours.v.loads[sling_tension_load].value / (ours.engine.m * ours.engine.material.g);
    std::printf("  sling tension up to the release %.0f mg, release height %.2f m, counterweight fall %.3f m\n", sling_tension_mg, ours.v.h,
                ours.counterweight_fall);
    if (inputs[0] == "17") {
      // Appendix B on the l = 17 engine: the fulcrum's force "reaches nearly 10 Mg" (read as
      // 8-10 Mg) and the sling's tension "rises to 350 mg" (the slips test pins it to rounding).
      CHECK(ours.v.FR_Mg > 8);
      CHECK(ours.v.FR_Mg < 10);
      CHECK(sling_tension_mg > 300);
      CHECK(sling_tension_mg < 400);
    } else {
      // On the l = 59 engine the force "rises only a little above Mg" (read as 1-1.5 Mg) and
      // "the sling tension stays below 20 mg".
      CHECK(ours.v.FR_Mg > 1);
      CHECK(ours.v.FR_Mg < 1.5);
      CHECK(sling_tension_mg < 20);
    }
    for (const VerifierColumn& e : expected) {
      // Rounding of the printed shape, first order, each input in turn.
      double rounding = 0;
      for (std::size_t k = 0; k < x.size(); ++k) {
        std::vector<double> moved = x;
        moved[k] += printed(inputs[k]).half_unit;
        rounding += std::abs(value(fitted_release(moved), e.key) - value(ours, e.key));
      }
      // Appendix B's "~2 m", "~40 m", "~9 cm" and "about 1/2 m": read as +- the width given in
      // the row's third field, on top of the rounding.
      // Elsewhere a third field above 1 is a documented difference (docs/verifier.md, "Known
      // differences"), allowed that multiple of the tolerance.
      const bool words = std::string(e.key) == "h" || std::string(e.key) == "fall";
      const double extra = words ? rounding + e.known : e.known * rounding + (e.known - 1) * printed(e.text).half_unit;
      check_printed(std::string("tab:Large_Eff l = ") + inputs[0] + " " + e.key, value(ours, e.key), e.text, extra);
    }
  }
}

namespace {

// tab:SketchBook-II rows: Lb = 9 m and l exact (bold), so L1 = Lb l/(l + 1); then L4 [m],
// M [t], m, mb [kg] as printed.
Engine sketchbook2_engine(double F, double theta_i_deg, double l, const std::vector<double>& x) {
  return sketchbook_engine(F, theta_i_deg, {9 * l / (l + 1), x[0], x[1], x[2], x[3], l});
}

struct QRow {
  std::string name;
  std::vector<std::string> inputs;
  std::function<Engine(const std::vector<double>&)> build;
  double n;
  std::vector<VerifierColumn> expected;  // R, T, eps
  const char* Q;  // the paper's
  const char* Q_ours;  // ours at 4 digits, as docs/verifier.md lists it: pinned, so that a change of eq:F shows
};

std::vector<QRow> optimised_rows() {
  auto sb1 = [](double F, double th) { return [=](const std::vector<double>& x) { return sketchbook_engine(F, th, x); }; };
  auto sb2 = [](double F, double th, double l) { return [=](const std::vector<double>& x) { return sketchbook2_engine(F, th, l, x); }; };
  auto dn = [](double th) { return [=](const std::vector<double>& x) { return denny_engine(th, x); }; };
  return {
      {"SketchBook-I n=1 F=1 30",
       {"6.13", "5.80", "14.3", "100.000", "660", "5.68"},
       sb1(1, 30),
       1,
       {{"R", "450"}, {"T", "235"}, {"eps", "93.1", 1.5}},
       "7.41",
       "6.963"},
      {"SketchBook-I n=1 F=2/3 30",
       {"6.20", "5.69", "16.9", "100.000", "601", "6.77"},
       sb1(2.0 / 3, 30),
       1,
       {{"R", "450"}, {"T", "234"}, {"eps", "92.6"}},
       "6.43",
       "5.942"},
      {"SketchBook-I n=1 F=2/3 40",
       {"6.48", "5.55", "19.1", "100.000", "622", "7.51"},
       sb1(2.0 / 3, 40),
       1,
       {{"R", "450"}, {"T", "234"}, {"eps", "91.6"}},
       "5.55",
       "5.258"},
      {"SketchBook-I n=5",
       {"6.31", "6.68", "15.6", "101", "611", "6.64"},
       sb1(1, 30),
       5,
       {{"R", "450"}, {"T", "235"}, {"eps", "97.5", 1.5}},
       "6.38",
       "6.351"},
      {"SketchBook-I n=0",
       {"6.60", "6.04", "13.4", "98.3", "807", "5.29"},
       sb1(1, 30),
       0,
       {{"R", "450"}, {"T", "235", 2.5}, {"eps", "87.8", 6}},
       "8.11",
       "7.339"},
      {"SketchBook-II #1", {"7.00", "26.8", "301", "1696"}, sb2(1, 25, 4.5), 1, {{"R", "426"}, {"T", "677"}, {"eps", "93.3", 2}}, "10.4", "9.400"},
      {"SketchBook-II #2", {"6.80", "26.0", "298", "1682"}, sb2(1, 30, 4.5), 1, {{"R", "407"}, {"T", "641"}, {"eps", "92.9"}}, "10.2", "9.359"},
      {"SketchBook-II #3", {"6.20", "23.7", "299", "1589"}, sb2(1, 40, 4.5), 1, {{"R", "341"}, {"T", "540"}, {"eps", "91.5", 3}}, "10.2", "9.485"},
      {"SketchBook-II #4", {"7.16", "33.4", "248", "1605"}, sb2(1, 30, 5.5), 1, {{"R", "540"}, {"T", "700", 1.5}, {"eps", "93.2"}}, "7.71", "7.203"},
      {"SketchBook-II #5",
       {"6.76", "34.9", "343", "1653"},
       sb2(2.0 / 3, 30, 5.5),
       1,
       {{"R", "401"}, {"T", "726", 1.5}, {"eps", "91.6"}},
       "8.79",
       "8.004"},
      {"SketchBook-II #6",
       {"6.98", "38.7", "299", "1623"},
       sb2(2.0 / 3, 30, 6.0),
       1,
       {{"R", "482"}, {"T", "752"}, {"eps", "92.0", 2}},
       "7.55",
       "6.922"},
      {"SketchBook-II #7", {"6.41", "45.9", "538", "1746"}, sb2(0.5, 30, 6.0), 1, {{"R", "297"}, {"T", "858"}, {"eps", "88.1", 2}}, "9.01", "8.183"},
      {"Denny Max Q 45",
       {"0.93", "8.67", "5.25", "6.19", "13.3", "101", "629"},
       dn(45),
       1,
       {{"R", "425"}, {"T", "224"}, {"eps", "91.4"}},
       "7.0",
       "6.701"},
      {"Denny Max Q 30 F=1",
       {"1.00000", "7.15", "5.23", "5.69", "13.3", "101", "647"},
       dn(30),
       1,
       {{"R", "425"}, {"T", "224"}, {"eps", "93.3"}},
       "7.8",
       "7.312"},
      {"Denny Max Q 30 F=2/3",
       {"0.666667", "7.06", "5.30", "5.57", "15.7", "101", "591"},
       dn(30),
       1,
       {{"R", "425"}, {"T", "224"}, {"eps", "92.2"}},
       "6.7",
       "6.222"},
  };
}

}  // namespace

// The optimised engines of tab:SketchBook-I, tab:SketchBook-II and tab:Denny, simulated as
// printed and released at the maximum of Q (or Q_n). R agrees with every row to the rounding
// of inputs and outputs, T with all but three, eps with nine of fifteen. The others are marked
// "known": T and eps are read at the release, which sits on a flat maximum of Q and moves with
// the force factor F, so they carry the verifier issue's open point on Q. Under the literal
// reading of eq:F, Q matches the n = 5 row, while the paper's Q is 4-11 % higher for the other
// rows (docs/verifier.md has the table and what was tried). Each row's Q is pinned to our own
// value to the 4 digits docs/verifier.md prints (half a unit: 0.007 % of Q), far below what a
// change of the force factor moves; it prints each row for the docs.
TEST_CASE("optimised engines of the paper: R, T and eps to rounding, and Q as documented", "[verify][paper][q-table]") {
  std::printf("%-28s %8s %8s %7s\n", "row", "Q ours", "Q paper", "ratio");
  for (const QRow& row : optimised_rows()) {
    ShotSettings settings;
    settings.criterion.n = row.n;
    check_shot_row(row.name, row.inputs, row.build, settings, row.expected);
    std::vector<double> x;
    for (const auto& text : row.inputs) x.push_back(printed(text).value);
    const double Q = 100 * verify_engine(row.build(x), settings).Q;
    const double ratio = printed(row.Q).value / Q;
    std::printf("  %-28s Q ours %.3f %% paper %s %% ratio %.3f\n", row.name.c_str(), Q, row.Q, ratio);
    check_printed(row.name + " Q ours", Q, row.Q_ours, 0);
    if (row.n == 5)
      check_printed(row.name + " Q_5", Q, row.Q,
                    input_rounding_effect(row.inputs, row.build, [&](const Engine& e) { return 100 * verify_engine(e, settings).Q; }));
  }
}

// Appendix B: after the fall, beam and counterweight ring about theta - psi = pi at
// omega = {L/(L+1) I_P}^(-1/2) (scaled), a small-amplitude, first-order result. Read from the
// simulated series (phase III of the fitted l = 17 engine) as the spacing of alternate zeros of
// theta' - psi', the frequency must match it to 1 %. The paper prints f = 42.2 Hz for this
// engine; the series and the formula both give 33.8 Hz (docs/verifier.md, known difference).
TEST_CASE("tab:Large_Eff l = 17 rings at appendix B's frequency", "[verify][paper][stiff]") {
  const ShotSettings settings = at_max_efficiency();
  const Engine engine = large_eff_17();
  std::vector<TracePoint> trace;
  verify_engine(engine, settings, &trace);
  std::vector<double> zeros;  // of theta' - psi', scaled time, by linear interpolation
  for (std::size_t k = 1; k < trace.size(); ++k) {
    const double a = trace[k - 1].state.theta_dot - trace[k - 1].state.psi_dot;
    const double b = trace[k].state.theta_dot - trace[k].state.psi_dot;
    if (trace[k].phase == Phase::released && a * b < 0) zeros.push_back(trace[k - 1].t + (trace[k].t - trace[k - 1].t) * a / (a - b));
  }
  REQUIRE(zeros.size() >= 5);
  const double period = (zeros.back() - zeros[1]) / ((zeros.size() - 2) / 2.0);  // skip the first, transient zero
  const double time_unit = std::sqrt(engine.L2 / engine.material.g);  // section 3 [s]
  const ScaledDesign e = scaled_design(engine);
  const double omega = 1 / std::sqrt(e.L() / (e.L() + 1) * e.beam_inertia());
  const double simulated_hz = 1 / (period * time_unit), formula_hz = omega / (2 * M_PI * time_unit);
  std::printf("tab:Large_Eff l = 17 ringing: simulated %.2f Hz, appendix B formula %.2f Hz, paper prints 42.2 Hz\n", simulated_hz, formula_hz);
  CHECK(std::abs(simulated_hz / formula_hz - 1) < 0.01);
}

// Issue 4: loose or low-order integration of the stiff engine (tab:Large_Eff l = 17) must end
// in a named error, never in a wrong number. Every accepted run kept the energy drift under
// 1e-8 of Delta U; the work-precision chart shows such runs within 3e-7 of the reference, so
// an accepted result further than 1e-5 from it would be a wrong number that slipped through.
TEST_CASE("loose integration of the stiff engine is an error or a right number", "[verify][stiff]") {
  const ShotSettings settings = at_max_efficiency();
  const Engine engine = large_eff_17();
  const Verification reference = verify_engine(engine, settings);
  int refused = 0, accepted = 0;
  bool loosest_refused = false;
  for (Stepper stepper : {Stepper::rk2, Stepper::rk4, Stepper::rkf45, Stepper::rkck, Stepper::rk8pd, Stepper::msadams, Stepper::rk2imp})
    for (double tol : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-9}) {
      ShotSettings loose = settings;
      loose.integrator.stepper = stepper;
      loose.integrator.rtol = tol;
      loose.integrator.atol = tol;
      loose.integrator.max_steps = 20000;
      INFO(stepper_name(stepper) << " at " << tol);
      try {
        const Verification v = verify_engine(engine, loose);
        ++accepted;
        CHECK(std::abs(v.capacity.R / reference.capacity.R - 1) < 1e-5);
        CHECK(std::abs(v.capacity.T / reference.capacity.T - 1) < 1e-5);
        CHECK(std::abs(v.eps / reference.eps - 1) < 1e-5);
      } catch (const Error& e) {
        ++refused;
        CHECK(e.kind() == ErrorKind::numerical);
        loosest_refused = loosest_refused || (stepper == Stepper::rk2 && tol == 1e-2);
      }
    }
  std::printf("stiff engine, 42 loose settings: %d refused with a named error, %d accepted and right\n", refused, accepted);
  // Both paths are exercised; and the second-order method at 1e-2 per step, whose error over a
  // shot of ~10^2 steps is far above the 1e-8 of Delta U the drift monitor allows, is refused.
  CHECK(accepted > 0);
  CHECK(loosest_refused);
}

// Issue 12, part 4: the open point on Q, closed with the optimizer. For every optimised row of
// tab:Denny and tab:SketchBook-I, the ab-initio optimum for the row's capacity, theta_i, F and n
// (section 5), under eq:F as written, searched from the calculator's designs and from the
// printed engine, the better kept. Where even the optimum falls short of the printed Q by
// more than its rounding, no design and no release reproduces the row: the printed Q does not
// follow from eq:F. Each optimum's Q is pinned to its own 4 digits (half a unit: < 0.01 % of Q;
// the optimizer finds Q to ~1e-8, bench-optimizer), so that a change of eq:F or of the search
// shows; the rows print the table of docs/verifier.md.
TEST_CASE("the optimum's Q for each optimised row of tab:Denny and tab:SketchBook-I", "[verify][paper][q-optimum]") {
  struct Row {
    const char* name;
    double R, T, theta_i_deg, F, n;  // [m], [J], [deg], scaled, eq:Q_n
    double beta2;  // the row's: Denny's 0.66 % at 45 deg, else 1/300
    const char* Q_paper;
    const char* Q_optimum;  // ours, pinned
  };
  const Row rows[] = {
      {"Denny Max Q 45", 425, 224e3, 45, 0.93, 1, 0.0066, "7.0", "6.854"},
      {"Denny Max Q 30 F=1", 425, 224e3, 30, 1, 1, 1.0 / 300, "7.8", "7.678"},
      {"Denny Max Q 30 F=2/3", 425, 224e3, 30, 2.0 / 3, 1, 1.0 / 300, "6.7", "6.499"},
      {"SketchBook-I n=1 F=1 30", 450, 235e3, 30, 1, 1, 1.0 / 300, "7.41", "7.310"},
      {"SketchBook-I n=1 F=2/3 30", 450, 234e3, 30, 2.0 / 3, 1, 1.0 / 300, "6.43", "6.220"},
      {"SketchBook-I n=1 F=2/3 40", 450, 234e3, 40, 2.0 / 3, 1, 1.0 / 300, "5.55", "5.441"},
      {"SketchBook-I n=5", 450, 235e3, 30, 1, 5, 1.0 / 300, "6.38", "6.391"},
      {"SketchBook-I n=0", 450, 235e3, 30, 1, 0, 1.0 / 300, "8.11", "7.834"},
  };
  std::printf("%-28s %9s %9s %8s %6s %6s %7s %7s %8s\n", "row", "Q optimum", "Q paper", "paper/opt", "L1", "L4", "M", "mb", "eps");
  for (const Row& row : rows) {
    OptimizeRequest request;
    request.capacity = {row.R, row.T};
    request.theta_i_deg = row.theta_i_deg;
    request.F = row.F;
    request.material.beta2 = row.beta2;
    request.settings.criterion.n = row.n;
    Optimum best = best_optimum(optimize(request));
    for (const QRow& printed_row : optimised_rows()) {
      if (printed_row.name != row.name) continue;
      std::vector<double> x;
      for (const auto& text : printed_row.inputs) x.push_back(printed(text).value);
      request.starts = {scaled_design(printed_row.build(x))};
      const Optimum from_printed = best_optimum(optimize(request));
      std::printf("  (%s: from the calculator Q %.4f %%, from the printed engine %.4f %%)\n", row.name, 100 * best.objective,
                  100 * from_printed.objective);
      if (from_printed.objective > best.objective) best = from_printed;
    }
    const double Q = 100 * best.objective;
    const Engine& e = best.fit.engine;
    std::printf("%-28s %9.3f %9s %8.3f %6.2f %6.2f %7.1f %7.0f %8.1f\n", row.name, Q, row.Q_paper, printed(row.Q_paper).value / Q, e.L1, e.L4,
                e.M / 1000, e.mb, 100 * best.fit.verification.eps);
    check_printed(std::string(row.name) + " Q optimum", Q, row.Q_optimum, 0);
    // The finding: for n <= 1 the printed Q lies above the best any design reaches, beyond the
    // rounding of the printed value; for n = 5 some design reaches it.
    const double lowest_printed = printed(row.Q_paper).value - printed(row.Q_paper).half_unit;
    if (row.n <= 1)
      CHECK(lowest_printed > Q);
    else
      CHECK(Q >= lowest_printed);
  }
}

// Issue 12, part 4, the paper's slips. Appendix B: for the l = 17 engine of tab:Large_Eff "the
// tension of the sling rises to 350 mg shortly before release". At two printed digits
// (345-355 mg) that is the sling's full tension, the largest over the step ends and the release;
// its component perpendicular to the beam, F_S_perp of eq:F, stays at 328 mg.
TEST_CASE("appendix B's 350 mg is the sling's full tension, not F_S_perp", "[verify][paper][slips]") {
  std::vector<TracePoint> trace;
  const Engine engine = large_eff_17();
  const Verification v = verify_engine(engine, at_max_efficiency(), &trace);
  const double mu = engine.m / engine.M;
  double tension = 0;
  for (const TracePoint& p : trace)
    if (p.phase != Phase::released) tension = std::max(tension, p.snapshot.sling_tension / mu);
  std::printf("tab:Large_Eff l = 17: largest sling tension %.1f mg, F_S_perp %.1f mg (appendix B: 350 mg)\n", tension, v.FS_perp_mg);
  const double two_digits = 5;  // "350" read as 3.5e2: half a unit of the second digit
  check_printed("appendix B sling tension", tension, "350", two_digits - printed("350").half_unit);
  CHECK(std::abs(v.FS_perp_mg - 350) > two_digits);
}

// tab:SketchBook-II rows 6 and 7 print L1 = 7.74 m and 7.69 m, where the bold Lb = 9 m and
// l = 6.0 give Lb l/(l + 1) = 7.714 m. Both readings reproduce R, T and eps within rounding;
// the printed L1 comes closer in each, so the printed L1 is what was simulated and the bold Lb
// and l are its rounding (7.74 m is Lb = 9.03 m).
TEST_CASE("tab:SketchBook-II rows 6 and 7: the printed L1 against Lb and l", "[verify][paper][slips]") {
  struct Row {
    const char* name;
    double F, L1_printed, L4, M_t, m, mb;
    double R, T_kJ, eps_percent;  // printed
  };
  for (const Row& row :
       {Row{"#6", 2.0 / 3, 7.74, 6.98, 38.7, 299, 1623, 482, 752, 92.0}, Row{"#7", 0.5, 7.69, 6.41, 45.9, 538, 1746, 297, 858, 88.1}}) {
    const double l = 6.0, from_bold = 9 * l / (l + 1);
    CHECK(std::abs(row.L1_printed - from_bold) > printed("7.74").half_unit);
    auto miss = [&](double L1) {
      const Verification v = verify_engine(sketchbook_engine(row.F, 30, {L1, row.L4, row.M_t, row.m, row.mb, l}), ShotSettings{});
      return std::array<double, 3>{std::abs(v.capacity.R - row.R), std::abs(v.capacity.T / 1e3 - row.T_kJ), std::abs(100 * v.eps - row.eps_percent)};
    };
    const auto printed_miss = miss(row.L1_printed), bold_miss = miss(from_bold);
    std::printf(
        "tab:SketchBook-II %s: |R, T, eps - printed| with L1 = %.2f m: %.2f m, %.2f kJ, %.2f %%; with L1 = %.3f m: %.2f m, %.2f kJ, %.2f %%\n",
        row.name, row.L1_printed, printed_miss[0], printed_miss[1], printed_miss[2], from_bold, bold_miss[0], bold_miss[1], bold_miss[2]);
    for (int k = 0; k < 3; ++k) CHECK(printed_miss[k] < bold_miss[k]);
  }
}

// Section 4's beam. eq:Strain: S = (3D/(2 L2)) beta2, so "D/L2 = 1/3 ... S^max = 1/600 for
// beta2 = 1/300" holds exactly for a beam sized by eq:bend_L2 (bending_diameter) at that D/L2.
TEST_CASE("section 4: a beam with D/L2 = 1/3 at beta2 = 1/300 has a strain of 1/600", "[verifier][paper]") {
  const Material wood;  // eq:kMkD
  const double L2 = 1.2, D = L2 / 3;
  // The counterweight that bends this beam by beta2 = 1/300: eq:bend_L2 solved for M.
  const double M = 3 * wood.youngs_modulus * (M_PI / 64 * std::pow(D, 4)) * wood.beta2 / (wood.g * L2 * L2);
  CHECK(std::abs(bending_diameter(M, L2, wood) / D - 1) < 1e-14);
  const BeamStrength beam = beam_strength(D, L2, M, 0, wood);
  std::printf("section 4: beta2 %.6g (1/300), strain at rest %.6g (1/600)\n", beam.beta2, beam.strain_at_rest);
  CHECK(std::abs(beam.beta2 * 300 - 1) < 1e-13);
  CHECK(std::abs(beam.strain_at_rest * 600 - 1) < 1e-13);
  // The moment that loads it at rest, M g L2 (eq:Strain), gives the same stress as the peak.
  CHECK(std::abs(beam_strength(D, L2, M, M * wood.g * L2, wood).stress_peak / beam.stress_at_rest - 1) < 1e-14);
}

// tab:Denny prints beta2 in % for its engines: the bending that the counterweight gives the
// beam of mass mb (eq:BeamMass, rho_d = 700 kg/m3) by eq:bend_L2. beta2 ~ M L2^2 / D^4 and
// D^4 ~ (mb/Lb)^2, so the printed 3 digits of Lb, H (L2 = Lb - H/cos theta_i, a difference),
// M and mb carry into it: Denny's engine is given exactly (bold), the Max Q rows to their
// rounding, worked out below as the first-order sum over the printed inputs.
TEST_CASE("tab:Denny beta2 from the engines' own beams", "[verifier][paper]") {
  struct Row {
    const char* name;
    double theta, Lb, H, M_t, mb;
    const char* beta2_percent;
  };
  const Row rows[] = {{"Present", 45, 12, 6.15, 10, 2000, "0.66"},
                      {"Max Q 45", 45, 8.67, 5.25, 13.3, 629, "0.66"},
                      {"Max Q 30 F 1", 30, 7.15, 5.23, 13.3, 647, "0.33"},
                      {"Max Q 30 F 2/3", 30, 7.06, 5.30, 15.7, 591, "0.33"}};
  const Material wood;
  for (const Row& r : rows) {
    auto beta2 = [&](double Lb, double H, double M, double mb) {
      const double L2 = Lb - H / std::cos(radians(r.theta));
      return 100 * beam_strength(beam_diameter(mb, Lb, wood), L2, M, 0, wood).beta2;
    };
    const bool exact = std::string(r.name) == "Present";
    const double value = beta2(r.Lb, r.H, r.M_t * 1000, r.mb);
    double rounding = 0;
    if (!exact) {
      rounding += std::abs(beta2(r.Lb + 0.005, r.H, r.M_t * 1000, r.mb) - value);
      rounding += std::abs(beta2(r.Lb, r.H + 0.005, r.M_t * 1000, r.mb) - value);
      rounding += std::abs(beta2(r.Lb, r.H, r.M_t * 1000 + 50, r.mb) - value);
      rounding += std::abs(beta2(r.Lb, r.H, r.M_t * 1000, r.mb + 0.5) - value);
    } else {
      rounding += std::abs(beta2(r.Lb, r.H + 0.005, r.M_t * 1000, r.mb) - value);  // H = 6.15 is printed, not given
    }
    check_printed(std::string("tab:Denny ") + r.name + " beta2 [%]", value, r.beta2_percent, rounding);
  }
}
