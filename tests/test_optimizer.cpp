// The ab-initio optimizer (issue 5, first part): it never returns a design that misses the
// capacity, it improves on its start, and it is deterministic.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "paper_rounding.hpp"
#include "trebuchet/optimizer.hpp"

namespace {

// The optimum's engine, shot anew, delivers the capacity: to the fit's 1e-6 in T (R is exact
// by construction), plus the shot's own 1e-8 (docs/performance.md) from the SI round trip.
void check_delivers(const trebuchet::Optimum& optimum, const trebuchet::Capacity& capacity) {
  const trebuchet::Verification fresh = trebuchet::verify_engine(optimum.fit.engine, trebuchet::ShotSettings{});
  CHECK(std::abs(fresh.capacity.R / capacity.R - 1) < 1e-6 + 1e-8);
  CHECK(std::abs(fresh.capacity.T / capacity.T - 1) < 1e-6 + 1e-8);
}

}  // namespace

using namespace trebuchet;
using trebuchet::testing::check_printed;

TEST_CASE("the optimum for (425 m, 224 kJ) delivers the capacity and beats its start", "[optimizer]") {
  OptimizeRequest request;
  request.capacity = {425, 224e3};
  request.F = 1;
  const std::vector<Optimum> optima = optimize(request);
  REQUIRE(!optima.empty());
  for (const Optimum& o : optima) {
    INFO(o.start);
    check_delivers(o, request.capacity);
    // The calculator's design, fitted to the capacity ab initio, is where the search began.
    const CapacityFit start = fit_capacity(o.start_design, request.capacity, Material{}, ShotSettings{});
    CHECK(o.objective > start.verification.Q);
    const ScaledDesign& d = o.fit.design;
    std::printf("start Q %.4f %% -> optimum (%s): Q %.4f %%, eps %.2f %%, l %.3f, l4 %.4f, mu_b %.5f, %d shots\n", 100 * start.verification.Q,
                o.start.c_str(), 100 * o.objective, 100 * o.fit.verification.eps, d.l, d.l4, d.mu_b, o.simulations);
  }
  // Same inputs, same numbers, bit for bit.
  const std::vector<Optimum> again = optimize(request);
  REQUIRE(again.size() == optima.size());
  CHECK(again[0].objective == optima[0].objective);
  CHECK(again[0].fit.engine.L4 == optima[0].fit.engine.L4);
}

// Section 6.2: for theta_i = 30 deg, F = 1 the paper finds two optima at X_d = 0.34, a lower
// branch (l4 = 0.965, released before the beam is upright) and an upper one (l4 = 1.075,
// released just after). Under our Q (the open point of docs/verifier.md) the calculator's two
// branch designs, used as starts, climb to one optimum between them, released just before
// upright: the border of the paper's branches (docs/table_derivation.md). This pins that
// finding; a second, distinct optimum would fail it and must then be reported as a branch.
TEST_CASE("at X = 0.34 both branch starts meet at one optimum on the border of the branches", "[optimizer][branches]") {
  const double X = 0.34;
  OptimizeRequest request;
  request.capacity = capacity_at({X, 0}, 240, 26e3);
  request.theta_i_deg = 30, request.F = 1;
  const std::vector<Optimum> optima = optimize(request);
  REQUIRE(optima.size() == 2);
  CHECK(optima[0].start == "calculator, lower branch");
  CHECK(optima[1].start == "calculator, upper branch");
  // The starts are the paper's branches: l4 below and above one, 11 % apart.
  CHECK(optima[0].start_design.l4 < 0.97);
  CHECK(optima[1].start_design.l4 > 1.07);
  for (const Optimum& o : optima) {
    std::printf("%s: l4 %.4f -> %.4f, Q %.5f %%, beam at release %.2f deg\n", o.start.c_str(), o.start_design.l4, o.fit.design.l4, 100 * o.objective,
                o.fit.verification.theta_release_deg);
    check_delivers(o, request.capacity);
    // Released before upright (180 deg), within 2 deg of it.
    CHECK(o.fit.verification.theta_release_deg < 180);
    CHECK(o.fit.verification.theta_release_deg > 178);
  }
  // One optimum: Q equal to the search's resolution (simplex size 1e-4 in log shape, where Q
  // is flat to second order), shapes within 1 %.
  CHECK(optima[1].objective == Approx(optima[0].objective).epsilon(1e-4));
  CHECK(std::abs(std::log(optima[1].fit.design.l4 / optima[0].fit.design.l4)) < 0.01);
  CHECK(std::abs(std::log(optima[1].fit.design.l / optima[0].fit.design.l)) < 0.01);
}

// Section 7 (eq:ExtraScalings): beta2 from 1/300 to 1/200 multiplies masses and energies by 2/3
// at equal lengths and scaled design. So the optimum for (R, 2T/3) with beta2 = 1/200 must be
// the optimum for (R, T) with 1/300 with masses times 2/3: the same shape and Q to the search's
// resolution (simplex size 1e-4 in log shape), lengths and masses to 1e-3.
TEST_CASE("the optimum follows beta2 as section 7 says", "[optimizer]") {
  OptimizeRequest stiff;
  stiff.capacity = {300, 60e3};
  stiff.theta_i_deg = 30, stiff.F = 2.0 / 3;
  OptimizeRequest supple = stiff;
  supple.material.beta2 = 1.0 / 200;
  supple.capacity.T = stiff.capacity.T * 2 / 3;
  const Optimum a = best_optimum(optimize(stiff));
  const Optimum b = best_optimum(optimize(supple));
  std::printf("beta2 1/300: Q %.5f %%, L1 %.4f m, M %.1f kg; beta2 1/200: Q %.5f %%, L1 %.4f m, M %.1f kg (ratio %.5f)\n", 100 * a.objective,
              a.fit.engine.L1, a.fit.engine.M, 100 * b.objective, b.fit.engine.L1, b.fit.engine.M, b.fit.engine.M / a.fit.engine.M);
  CHECK(b.objective == Approx(a.objective).epsilon(1e-4));
  CHECK(b.fit.engine.L1 == Approx(a.fit.engine.L1).epsilon(1e-3));
  CHECK(b.fit.engine.L4 == Approx(a.fit.engine.L4).epsilon(1e-3));
  CHECK(b.fit.engine.M == Approx(a.fit.engine.M * 2 / 3).epsilon(1e-3));
  CHECK(b.fit.engine.m == Approx(a.fit.engine.m * 2 / 3).epsilon(1e-3));
}

// Issue 14, part 4: a capacity as historians state it, the range and the stone (tab:SketchBook-I
// takes R = 450 m and m = 100 kg). The optimum throws exactly that: R by construction (L2 =
// R/rho), m = mu M to the fit's 1e-6, plus the shot's 1e-8 from the SI round trip. Its engine
// also delivers (R, T) at the T it found, so the search for that (R, T), where m is free, must
// reach at least its Q (less the search's ~1e-6 on a flat top), and lands near it: m and L4
// within 0.5 % (measured: m 0.05 % off, Q 5e-5 higher).
TEST_CASE("the optimum for a range and a stone delivers both, and is the optimum for its (R, T)", "[optimizer]") {
  OptimizeRequest by_mass;
  by_mass.capacity = {450, 0};
  by_mass.projectile_mass = 100;
  by_mass.F = 1;
  const Optimum with_m = best_optimum(optimize(by_mass));
  const Verification fresh = verify_engine(with_m.fit.engine, ShotSettings{});
  std::printf("(450 m, 100 kg), F = 1: T %.4f kJ, Q %.4f %%, L1 %.3f m, L4 %.3f m, M %.0f kg, %d shots\n", fresh.capacity.T / 1e3,
              100 * with_m.objective, with_m.fit.engine.L1, with_m.fit.engine.L4, with_m.fit.engine.M, with_m.simulations);
  CHECK(std::abs(fresh.capacity.R / 450 - 1) < 1e-8);
  CHECK(std::abs(with_m.fit.engine.m / 100 - 1) < 1e-6);

  OptimizeRequest by_energy;
  by_energy.capacity = {450, with_m.fit.verification.capacity.T};
  by_energy.F = 1;
  const Optimum with_T = best_optimum(optimize(by_energy));
  std::printf("(450 m, %.4f kJ): m %.4f kg, Q %.4f %%\n", by_energy.capacity.T / 1e3, with_T.fit.engine.m, 100 * with_T.objective);
  CHECK(with_T.objective >= with_m.objective * (1 - 1e-6));
  CHECK(std::abs(with_T.fit.engine.m / 100 - 1) < 5e-3);
  CHECK(std::abs(with_T.fit.engine.L4 / with_m.fit.engine.L4 - 1) < 5e-3);
}

namespace {

// Appendix B's capacity: R = 450 m, T = 232 kJ, theta_i = 30 deg, F = 1, released at the
// maximum of Q_eps = eps, with l held fixed.
std::vector<Optimum> at_fixed_l(double l) {
  OptimizeRequest r;
  r.capacity = {450, 232e3, 0};
  r.theta_i_deg = 30, r.F = 1;
  r.settings.criterion.release = Release::efficiency;
  r.fixed_l = l;
  return optimize(r);
}

const Optimum& branch(const std::vector<Optimum>& optima, const std::string& name) {
  for (const Optimum& o : optima)
    if (o.start == name) return o;
  FAIL("no " << name);
  return optima.front();
}

}  // namespace

// Appendix B: "Calculations with the same capacity and Q = Q_eps show an increase of eps above
// 99.5 % at l = 16.2 on the smaller-l4 branch". At l = 16.2 the best eps with l4 < 1 is 99.50 %
// to half a unit of its last printed digit, widened by what the rounding of l (0.05) moves it:
// eps grows by 0.03 % per unit of l here (99.502 % at 16.2, 99.527 % at 17). At l = 17 the
// search finds at least the eps of tab:Large_Eff's l = 17 engine (99.526 % when shot as printed,
// tests/test_verifier_paper.cpp; shot here again), less the search's tolerance on a flat top (1e-5).
TEST_CASE("appendix B: at l = 16.2 the smaller-l4 branch reaches 99.5 %", "[optimizer][paper]") {
  const Optimum at_16 = branch(at_fixed_l(16.2), "smaller-l4 branch");
  const Optimum at_17 = branch(at_fixed_l(17), "smaller-l4 branch");
  std::printf("appendix B, smaller-l4 branch: eps %.4f %% at l = 16.2 (l4 %.3f), %.4f %% at l = 17 (l4 %.3f)\n", 100 * at_16.objective,
              at_16.fit.design.l4, 100 * at_17.objective, at_17.fit.design.l4);
  const double slope = (at_17.objective - at_16.objective) / 0.8;  // per unit of l
  check_printed("eps at l = 16.2, smaller-l4 branch [%]", 100 * at_16.objective, "99.50", 100 * std::abs(slope) * 0.05);
  CHECK(at_16.fit.design.l4 < 1);
  // tab:Large_Eff's l = 17 engine, its printed shape fitted to the same capacity.
  ShotSettings at_max_eps;
  at_max_eps.criterion.release = Release::efficiency;
  const double paper_eps = fit_capacity({17, 0.673 / 0.800, 14.7 / 270e3, 0, 30, 1}, {450, 232e3}, Material{}, at_max_eps).verification.eps;
  CHECK(at_17.objective > paper_eps - 1e-5);
  CHECK(at_16.note.empty());  // an interior maximum
}

// "... and at l = 58.5 on the larger-l4 branch": here eps exceeds 99.5 % on that side by far
// (99.87 %), but at its edge l4 = 1, which the result says: in this model the paper's l = 59
// engine of tab:Large_Eff is no maximum of its own (docs/verifier.md, "Known differences").
TEST_CASE("appendix B: at l = 58.5 eps exceeds 99.5 % on both sides of l4 = 1", "[optimizer][paper]") {
  const std::vector<Optimum> optima = at_fixed_l(58.5);
  const Optimum& larger = branch(optima, "larger-l4 branch");
  const Optimum& smaller = branch(optima, "smaller-l4 branch");
  std::printf("appendix B, l = 58.5: larger-l4 side eps %.4f %% at l4 %.4f (%s); smaller-l4 side %.4f %% at l4 %.4f, mu_b %.2g (%s)\n",
              100 * larger.objective, larger.fit.design.l4, larger.note.c_str(), 100 * smaller.objective, smaller.fit.design.l4,
              smaller.fit.design.mu_b, smaller.note.c_str());
  CHECK(larger.objective > 0.995);
  CHECK(smaller.objective > 0.995);
  CHECK(larger.fit.design.l4 >= 1);
  CHECK(smaller.fit.design.l4 < 1);
  CHECK_FALSE(larger.note.empty());
}
