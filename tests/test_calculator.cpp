// The calculator's own physics and algebra: exact round trips, scaling laws, material,
// branches and refusals. Tolerances here are rounding of doubles (a few 1e-15 per
// operation, amplified by the condition of the inversion), not the paper's rounding.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "engines.hpp"
#include "paper_rounding.hpp"
#include "trebuchet/app/records/table_json.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

using namespace trebuchet;
using namespace trebuchet::testing;

namespace {

DesignRequest capacity(double R, double T, double theta_i_deg = 30, double F = 2.0 / 3) {
  DesignRequest r;
  r.first = {Quantity::R, R};
  r.second = {Quantity::T, T};
  r.theta_i_deg = theta_i_deg;
  r.F = F;
  return r;
}

// A capacity with the given X and Y (eq:XY_RT inverted).
DesignRequest at_XY(double X, double Y, double theta_i_deg = 30, double F = 2.0 / 3) {
  const Capacity c = capacity_at({X, Y}, 240, 26000);
  return capacity(c.R, c.T, theta_i_deg, F);
}

}  // namespace

// eq:RT_ZiZj and eq:ZiZj_RT are inverse to each other: any two quantities of an optimal
// engine give back its capacity, unless the pair is refused as ill-conditioned.
// Round-off: ~1e-15 times the amplification (<= 50). The counts pin how many of the 660
// pairs are round-tripped, refused, or shared by two capacities, so that a change which
// refuses more pairs cannot pass unseen.
TEST_CASE("any pair of an optimal engine's quantities gives back its capacity", "[calculator]") {
  int round_trips = 0, refused = 0, shared = 0;
  for (double X : {-0.4, -0.1, 0.2, 0.5})
    for (double Y : {-1.0, 0.0, 2.0}) {
      const OptimalEngine design = design_optimal_engine(builtin_scaling_table(), at_XY(X, Y));
      for (Quantity qi : all_quantities)
        for (Quantity qj : all_quantities) {
          if (qi >= qj) continue;
          DesignRequest r = at_XY(X, Y);
          r.first = {qi, quantity_value(design, qi)};
          r.second = {qj, quantity_value(design, qj)};
          INFO("X " << X << " Y " << Y << " pair " << quantity_name(qi) << ", " << quantity_name(qj));
          OptimalEngine back;
          try {
            back = design_optimal_engine(builtin_scaling_table(), r);
          } catch (const Error& e) {
            // An ill-conditioned pair is refused, and only above the limit of 50.
            const std::string message = e.what();
            REQUIRE_THAT(message, Catch::Contains("barely fixes the capacity"));
            const auto at = message.find("by up to ") + 9;
            CHECK(std::stod(message.substr(at)) > 50);
            ++refused;
            continue;
          }
          if (relative(back.capacity.R, design.capacity.R) > 1e-10) {
            // Two capacities can share the pair (two segments each consistent, or Lb with
            // another given): the one not shown must be announced with its X.
            REQUIRE(!back.warnings.empty());
            CHECK_THAT(back.warnings.front(),
                       Catch::Contains("another optimal engine") && Catch::Contains("X = " + format_significant(design.coordinates.X, 3)));
            ++shared;
            continue;
          }
          CHECK(relative(back.capacity.T, design.capacity.T) < 1e-10);
          CHECK(relative(back.engine.M, design.engine.M) < 1e-10);
          CHECK(relative(back.engine.L4, design.engine.L4) < 1e-10);
          ++round_trips;
        }
    }
  std::printf("any pair: %d round trips, %d refused as ill-conditioned, %d shared by two capacities, of 660\n", round_trips, refused, shared);
  CHECK(round_trips + refused + shared == 660);
  CHECK(round_trips == 639);
  CHECK(refused == 18);
  CHECK(shared == 3);
}

// Near-singular pairs (small D_ij of eq:ZiZj_RT): the amplification of a 1 % input error is
// reported, warned above 10 and refused above 50 (docs/calculator.md argues the limits).
TEST_CASE("ill-conditioned pairs are warned or refused with the amplification named", "[calculator]") {
  const OptimalEngine design = design_optimal_engine(builtin_scaling_table(), capacity(300, 100e3));
  DesignRequest r = capacity(300, 100e3);
  r.first = {Quantity::L1, design.engine.L1};
  r.second = {Quantity::L4, design.engine.L4};
  const OptimalEngine warned = design_optimal_engine(builtin_scaling_table(), r);
  CHECK(warned.amplification > 10);
  CHECK(warned.amplification < 50);
  REQUIRE(!warned.warnings.empty());
  CHECK_THAT(warned.warnings.back(), Catch::StartsWith("ill-conditioned pair: a 1 % change of L1"));
  // Measured, not assumed: a 1 % error in L4 moves R or T by less than the amplification says.
  r.second.value *= 1.01;
  const OptimalEngine moved = design_optimal_engine(builtin_scaling_table(), r);
  const double change = std::max(relative(moved.capacity.R, design.capacity.R), relative(moved.capacity.T, design.capacity.T));
  std::printf("(L1, L4): amplification %.1f, a 1 %% change of L4 moves the capacity by %.1f %%\n", warned.amplification, 100 * change);
  CHECK(change > 0.05);
  CHECK(change < 1.1 * 0.01 * warned.amplification);
  r.first = {Quantity::L4, design.engine.L4};
  r.second = {Quantity::M, design.engine.M};
  CHECK_THROWS_WITH(design_optimal_engine(builtin_scaling_table(), r), Catch::Contains("barely fixes the capacity"));
}

// eq:ExtraScalings: along constant X a design scales with lengths ~ lambda, masses ~ lambda^4,
// T ~ lambda^5, D ~ lambda^1.5 (n_Z). The calculator at (lambda R, lambda^5 T) gives the scaled
// design, except that each fitted law obeys p_Z + 5 q_Z = n_Z only to its printed digits:
// log(direct/scaled) must be exactly (p_Z + 5 q_Z - n_Z) log(lambda), up to round-off.
TEST_CASE("the optimum at (lambda R, lambda^5 T) is the optimum at (R, T) scaled by lambda", "[calculator][scaling]") {
  const ScalingTable& table = builtin_scaling_table();
  const OptimalEngine base = design_optimal_engine(table, capacity(425, 224e3));
  const TableBlock& block = *table.find_block(30, 2.0 / 3);
  const Segment* segment = nullptr;
  for (const Segment& s : block.segments)
    if (s.X_min == base.segment_X_min) segment = &s;
  REQUIRE(segment);
  for (double lambda : {0.1, 0.5, 2.0}) {
    const OptimalEngine direct = design_optimal_engine(table, capacity(425 * lambda, 224e3 * std::pow(lambda, 5)));
    const OptimalEngine scaled = scale_optimal_engine(base, lambda);
    INFO("lambda " << lambda);
    CHECK(std::abs(direct.coordinates.X - scaled.coordinates.X) < 1e-12);
    CHECK(std::abs(direct.coordinates.Y - scaled.coordinates.Y) < 1e-12);
    const std::pair<Param, double> checks[] = {{Param::L1, direct.engine.L1 / scaled.engine.L1},
                                               {Param::L4, direct.engine.L4 / scaled.engine.L4},
                                               {Param::D, direct.engine.D / scaled.engine.D},
                                               {Param::M, direct.engine.M / scaled.engine.M},
                                               {Param::mb, direct.engine.mb / scaled.engine.mb}};
    for (const auto& [param, ratio] : checks) {
      const double p = segment->exponents(index(param), 0), q = segment->exponents(index(param), 1);
      INFO(param_name(param));
      CHECK(std::abs(std::log(ratio) - (p + 5 * q - table.n[index(param)]) * std::log(lambda)) < 1e-12);
    }
  }
}

// tab:Denny: the "Model" row is the theta_i = 30 deg, F = 2/3 "Max Q" row scaled down
// (eq:ExtraScalings). lambda = 80.0 m / 425 m carries the rounding of both ranges; each
// tolerance adds the input's printed rounding, lambda's times the power, and the output's.
TEST_CASE("tab:Denny Model row from the Max Q row above it", "[calculator][scaling][paper]") {
  Engine max_q;
  max_q.L1 = 7.06 * 0.8;  // only Lb, H, L4 and the masses are printed; split Lb arbitrarily
  max_q.L2 = 7.06 * 0.2;
  max_q.L4 = 5.57;
  max_q.M = 15.7e3;
  max_q.m = 101;
  max_q.mb = 591;
  max_q.theta_i_deg = 30;
  const double H = 5.30;
  const double lambda = 80.0 / 425;
  const double lambda_rounding = 0.05 / 80.0 + 0.5 / 425;
  const Engine model = resized(max_q, size_factors(max_q.L2, max_q.material, lambda * max_q.L2, max_q.material));
  std::printf("tab:Denny Model row\n");
  auto check = [&](const char* label, double ours, const char* paper, double input_rounding, int power) {
    check_printed(label, ours, paper, std::abs(ours) * (input_rounding + power * lambda_rounding));
  };
  check("Lb", beam_length(model), "1.33", 0.005 / 7.06, 1);
  check("H", H * lambda, "1.00", 0.005 / 5.30, 1);
  check("L4", model.L4, "1.05", 0.005 / 5.57, 1);
  check("M [kg]", model.M, "19.9", 50 / 15.7e3, 4);
  check("m [kg]", model.m, "0.127", 0.5 / 101, 4);
  check("mb [kg]", model.mb, "0.745", 0.5 / 591, 4);
  check("R [m]", 425 * lambda, "80.0", 0.5 / 425, 1);
  check("T [J]", 224e3 * std::pow(lambda, 5), "53.1", 0.5 / 224, 5);
}

// Section 7: beta2 from 1/300 to 1/200 at the same lengths keeps R and scales masses, T and
// the beam cross-section by 2/3. Checked on the calculator (exact up to round-off) and on the
// paper's example, row 7 of tab:SketchBook-II: 858 kJ becomes 572 kJ, R stays 297 m.
TEST_CASE("section 7: beta2 = 1/200 keeps lengths and R, scales masses and T by 2/3", "[calculator][material][paper]") {
  const SizeFactors s = size_factors(1, Material{}, 1, Material{1.0 / 200});
  CHECK(s.length == 1);
  CHECK(s.mass == Approx(2.0 / 3).epsilon(1e-14));
  CHECK(s.energy == Approx(2.0 / 3).epsilon(1e-14));
  CHECK(s.diameter * s.diameter == Approx(2.0 / 3).epsilon(1e-14));
  std::printf("section 7, beta2 = 1/200\n");
  check_printed("T of SketchBook-II row 7 [kJ]", 858 * s.energy, "572", 0.5 * s.energy);

  DesignRequest r;
  r.first = {Quantity::Lb, 9};
  r.second = {Quantity::l, 6.0};
  const OptimalEngine stiff = design_optimal_engine(builtin_scaling_table(), r);
  r.material.beta2 = 1.0 / 200;
  const OptimalEngine weak = design_optimal_engine(builtin_scaling_table(), r);
  CHECK(relative(weak.capacity.R, stiff.capacity.R) < 1e-12);
  CHECK(relative(weak.engine.L1, stiff.engine.L1) < 1e-12);
  CHECK(relative(weak.engine.L4, stiff.engine.L4) < 1e-12);
  CHECK(relative(weak.engine.M, stiff.engine.M * 2 / 3) < 1e-12);
  CHECK(relative(weak.engine.mb, stiff.engine.mb * 2 / 3) < 1e-12);
  CHECK(relative(weak.capacity.T, stiff.capacity.T * 2 / 3) < 1e-12);
  CHECK(relative(weak.engine.D * weak.engine.D, stiff.engine.D * stiff.engine.D * 2 / 3) < 1e-12);
}

// Section 7: "a trebuchet on a special mission to the moon". With g = 1.62 m/s^2, k_M and k_D
// scale with g (eq:kMkD); the optimum for (R, m) is the earth optimum for (R, m g0/g) with
// masses times g/g0 and T times (g/g0)^2. eq:ExtraScalings then holds with the moon's k_M.
TEST_CASE("section 7: a trebuchet for the moon", "[calculator][material]") {
  const double g_moon = 1.62, g_earth = 9.81;
  DesignRequest moon_request;
  moon_request.first = {Quantity::R, 400};
  moon_request.second = {Quantity::m, 50};
  moon_request.material.g = g_moon;
  const OptimalEngine moon = design_optimal_engine(builtin_scaling_table(), moon_request);
  DesignRequest earth_request = moon_request;
  earth_request.material.g = g_earth;
  earth_request.second = {Quantity::m, 50 * g_earth / g_moon};
  const OptimalEngine earth = design_optimal_engine(builtin_scaling_table(), earth_request);
  CHECK(relative(moon.engine.L2, earth.engine.L2) < 1e-12);
  CHECK(relative(moon.engine.L4, earth.engine.L4) < 1e-12);
  CHECK(relative(moon.engine.M, earth.engine.M * g_moon / g_earth) < 1e-12);
  CHECK(relative(moon.capacity.T, earth.capacity.T * (g_moon / g_earth) * (g_moon / g_earth)) < 1e-12);
  CHECK(std::abs(moon.coordinates.X - earth.coordinates.X) < 1e-12);
  auto bending_law = [](const OptimalEngine& d) {  // M / (K^2 (k_M/beta2) L2^4), eq:ExtraScalings, written out
    const ScaledDesign s = scaled_design(d.engine);
    const Material& m = d.engine.material;
    return d.engine.M / (s.K() * s.K() * k_M(m) / m.beta2 * std::pow(d.engine.L2, 4));
  };
  CHECK(relative(bending_law(moon), bending_law(earth)) < 1e-12);
  // The fits themselves obey eq:ExtraScalings to their accuracy (a few per cent).
  CHECK(std::abs(bending_law(earth) - 1) < 0.05);
}

// eq:BeamMass: D^2 = 4 mb / (pi rho_d (L1 + L2)). The table fits D and mb separately; over the
// covered X range they agree with this law to the fits' accuracy (1.5% in D).
TEST_CASE("fitted D and mb agree with eq:BeamMass", "[calculator]") {
  for (double X : {-0.5, -0.2, 0.1, 0.35, 0.5}) {
    const OptimalEngine d = design_optimal_engine(builtin_scaling_table(), at_XY(X, 0.5));
    const double D_beam = std::sqrt(4 * d.engine.mb / (M_PI * d.engine.material.wood_density * beam_length(d.engine)));
    INFO("X " << X << " D " << d.engine.D << " from eq:BeamMass " << D_beam);
    CHECK(relative(d.engine.D, D_beam) < 0.015);
  }
}

TEST_CASE("auto takes the lower branch below X_d and the upper above, with the steps reported", "[calculator][branch]") {
  const OptimalEngine below = design_optimal_engine(builtin_scaling_table(), at_XY(0.33, 0, 30, 1));
  const OptimalEngine above = design_optimal_engine(builtin_scaling_table(), at_XY(0.35, 0, 30, 1));
  CHECK(below.branch == Branch::lower);
  CHECK(above.branch == Branch::upper);
  REQUIRE(below.branch_steps);
  CHECK_THAT(below.warnings.front(), Catch::Contains("S_L4 = +16%"));
  // The optimum jumps at X_d: l4 on the upper branch is ~11% longer (section 6.2).
  CHECK(scaled_design(above.engine).l4 / scaled_design(below.engine).l4 > 1.1);

  DesignRequest forced = at_XY(0.35, 0, 30, 1);
  forced.branch = BranchChoice::lower;
  CHECK(design_optimal_engine(builtin_scaling_table(), forced).branch == Branch::lower);
  forced = at_XY(0.2, 0, 30, 1);
  forced.branch = BranchChoice::upper;
  CHECK_THROWS_WITH(design_optimal_engine(builtin_scaling_table(), forced), Catch::Contains("upper branch has no optimum"));
  const OptimalEngine plain = design_optimal_engine(builtin_scaling_table(), at_XY(0.1, 0));
  CHECK(plain.branch == Branch::none);
  CHECK(!plain.branch_steps);
  CHECK(plain.warnings.empty());
}

// The span of l a message names is the table's: an l just inside either end of it designs, one
// just outside is refused (the ends are printed to 3 digits, so 0.3 % either side is outside the
// rounding; l changes with the size far less than that, as these designs at Lb = 9 m show).
TEST_CASE("an l no optimal engine of the block has is refused with the block's span of l", "[calculator][range]") {
  DesignRequest r;
  r.first = {Quantity::Lb, 9};
  r.F = 2.0 / 3;
  r.second = {Quantity::l, 4.5};
  try {
    design_optimal_engine(builtin_scaling_table(), r);
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::out_of_range);
    CHECK_THAT(e.what(), Catch::Contains("runs from 4.69 to 9.04") && Catch::Contains("F = 1 (l from 3.48 to 7.63)") && !Catch::Contains("Lb from"));
  }
  for (const auto& [F, lo, hi] : {std::tuple{2.0 / 3, 4.69, 9.04}, std::tuple{1.0, 3.48, 7.63}}) {
    r.F = F;
    for (const auto& [l, designs] : {std::pair{lo * 0.997, false}, {lo * 1.003, true}, {hi * 0.997, true}, {hi * 1.003, false}}) {
      r.second = {Quantity::l, l};
      bool designed = true;
      try {
        design_optimal_engine(builtin_scaling_table(), r);
      } catch (const Error& e) {
        designed = false;
        CHECK_THAT(e.what(), Catch::Contains("whatever the engine's size"));
      }
      INFO("F = " << F << ", l = " << l);
      CHECK(designed == designs);
    }
  }
}

TEST_CASE("X outside the covered interval is refused, or extrapolated with a warning", "[calculator][range]") {
  DesignRequest r = at_XY(0.8, 0);
  try {
    design_optimal_engine(builtin_scaling_table(), r);
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::out_of_range);
    CHECK_THAT(e.what(), Catch::Contains("X = 0.8") && Catch::Contains("[-0.55, 0.57]") && Catch::Contains("add extrapolate"));
    // The givens and the setting are named by their names in the API (the givens first: what to
    // change); a program writes its own word for each.
    CHECK(e.names() == std::vector<std::string>{"R", "T", "extrapolate"});
    CHECK_THAT(e.message([](std::string_view name) { return "--" + std::string(name); }), Catch::Contains("add --extrapolate"));
  }
  r.extrapolate = true;
  const OptimalEngine d = design_optimal_engine(builtin_scaling_table(), r);
  CHECK(std::abs(d.coordinates.X - 0.8) < 1e-12);
  REQUIRE(d.warnings.size() == 1);
  CHECK_THAT(d.warnings.front(), Catch::StartsWith("extrapolated"));
  CHECK_THROWS_WITH(design_optimal_engine(builtin_scaling_table(), capacity(150, 40e3, 35, 1)), Catch::Contains("no constants for theta_i = 35"));
}

// eq:ZiZj_RT: a 1% error in either given moves log R and log T by up to
// (|q_i| + |q_j|)/|D_ij| or (|p_i| + |p_j|)/|D_ij| per cent.
TEST_CASE("near-singular pairs report how much they amplify input errors", "[calculator]") {
  const OptimalEngine design = design_optimal_engine(builtin_scaling_table(), at_XY(0.1, 0));
  DesignRequest r = at_XY(0.1, 0);
  CHECK(design.amplification == Approx(1).epsilon(1e-12));  // R and T given
  r.first = {Quantity::L1, design.engine.L1};
  r.second = {Quantity::L4, design.engine.L4};
  const OptimalEngine lengths = design_optimal_engine(builtin_scaling_table(), r);
  CHECK(lengths.amplification > 10);  // two lengths barely fix the capacity
  r.first = {Quantity::R, design.capacity.R};
  r.second = {Quantity::m, design.engine.m};
  CHECK(design_optimal_engine(builtin_scaling_table(), r).amplification < 3);
}

// Seams (issue 11): where two segments meet, their constants agree only to their rounding, so
// for a fixed second given (m, M or L1) each segment reaches the seam X_s at a slightly
// different R; between those two ranges a request could solve to just past the seam in both.
// Every seam of both tables is probed across that interval (its ends, its middle and beyond
// it); each probe must give an engine, none may be refused as outside the table.
TEST_CASE("no gap at any seam of either table", "[calculator][range]") {
  const ScalingTable derived = load_scaling_table(TREBUCHET_DATA_DIR "/cpnc-derived.json");
  int probes = 0, seams = 0, gaps = 0;
  for (const ScalingTable* table : {&builtin_scaling_table(), &derived})
    for (const TableBlock& block : table->blocks)
      for (const Segment& left : block.segments)
        for (const Segment& right : block.segments) {
          const bool one_family = left.branch == right.branch || left.branch == Branch::none || right.branch == Branch::none;
          if (left.X_max != right.X_min || !one_family) continue;
          ++seams;
          const double X_s = left.X_max;
          for (double Y : {-1.0, 0.5})
            for (Param second : {Param::m, Param::M, Param::L1}) {
              const Capacity c = capacity_at({X_s, Y}, table->R0, table->T0);
              const OptimalEngine design = design_optimal_engine(*table, capacity(c.R, c.T, block.theta_i_deg, block.F));
              const Quantity q = second == Param::m ? Quantity::m : second == Param::M ? Quantity::M : Quantity::L1;
              const double Z = quantity_value(design, q);
              // The R at which each segment puts the seam for this Z: log Z = log(a Z0) + p lr + q lt
              // and X_s = (5 lr - lt)/sqrt(26) (eq:XY_RT), solved for lr.
              auto R_at_seam = [&](const Segment& s) {
                const double p = s.exponents(index(second), 0), qz = s.exponents(index(second), 1);
                const double b = std::log(Z / (s.a[index(second)] * block.Z0[index(second)]));
                const double lr = (b + qz * std::sqrt(26.0) * X_s) / (p + 5 * qz);
                return table->R0 * std::exp(lr);
              };
              const double R_left = R_at_seam(left), R_right = R_at_seam(right);
              for (double f : {-0.5, 0.0, 0.25, 0.5, 0.75, 1.0, 1.5}) {
                DesignRequest r = capacity(c.R, c.T, block.theta_i_deg, block.F);
                r.first = {Quantity::R, R_left + f * (R_right - R_left)};
                r.second = {q, Z};
                INFO(table->origin << " block " << block.theta_i_deg << "/" << block.F << " seam " << X_s << " " << quantity_name(q) << " f " << f);
                try {
                  const OptimalEngine d = design_optimal_engine(*table, r);
                  gaps += !(d.coordinates.X >= d.segment_X_min && d.coordinates.X <= d.segment_X_max);
                } catch (const Error& e) {
                  FAIL_CHECK(e.what());
                }
                ++probes;
              }
            }
        }
  std::printf("seams: %d seams, %d probes, %d of them in a gap between two segments\n", seams, probes, gaps);
  // tab:CPNC's 3 seams, and the derived table's 22: 3 + 3 + 6 + 3 for the blocks of issue 5,
  // 3 for (25 deg, F = 1) and 4 for (30 deg, F = 1/2) of issue 14.
  CHECK(seams == 25);
  CHECK(gaps > 0);  // the probes do reach the gaps this guards
}

// An ill-conditioned pair past a seam by far more than the constants' rounding can open (issue
// 49's review: L1 = 6.928 m, M = 20.67 t solves to X = 2.27 left and -0.312 right of X = 0) is
// no seam gap: refused, as a pair outside the table, not designed at X = -0.312.
TEST_CASE("a pair far past a seam is refused, not taken as a seam gap", "[calculator][range]") {
  for (const double M : {20670.0, 12000.0}) {
    DesignRequest r;
    r.first = {Quantity::L1, 6.928};
    r.second = {Quantity::M, M};
    INFO("M = " << M);
    CHECK_THROWS_WITH(design_optimal_engine(builtin_scaling_table(), r), Catch::Contains("outside the covered interval"));
  }
}

// The issue's example: (321.294 m, 66.484 kg) fell between the two segments of (30 deg, 2/3).
TEST_CASE("the seam example of issue 11 gives an engine", "[calculator][range]") {
  DesignRequest r;
  r.first = {Quantity::R, 321.294};
  r.second = {Quantity::m, 66.484};
  const OptimalEngine d = design_optimal_engine(builtin_scaling_table(), r);
  CHECK(std::abs(d.coordinates.X) < 1e-4);
  CHECK(d.warnings.empty());
}

// Issue 14, part 5: the blocks (25 deg, F = 1) and (30 deg, F = 1/2) re-derived ab initio, and
// with them tab:SketchBook-II rows 1, 3 and 7, which the paper calculated "a priori", from its
// bold (Lb, l). Row 2 (30 deg, F = 1) is there by both tables, as the yardstick.
TEST_CASE("tab:SketchBook-II rows 1, 3 and 7 from (Lb, l) with the re-derived blocks", "[calculator][derived][paper]") {
  const ScalingTable derived = load_scaling_table(TREBUCHET_DATA_DIR "/cpnc-derived.json");
  struct Row {
    int number;
    double theta, F, l, R, T;  // as printed [deg], scaled, scaled, [m], [kJ]
  };
  const Row rows[] = {{1, 25, 1, 4.5, 426, 677}, {2, 30, 1, 4.5, 407, 641}, {3, 40, 1, 4.5, 341, 540}, {7, 30, 0.5, 6.0, 297, 858}};
  std::vector<double> ratios;
  for (const Row& row : rows) {
    DesignRequest r;
    r.first = {Quantity::Lb, 9};
    r.second = {Quantity::l, row.l};
    r.theta_i_deg = row.theta, r.F = row.F;
    try {
      const OptimalEngine d = design_optimal_engine(derived, r);
      // The derived table's design, shot ab initio: within the 2 % its constants hold to.
      const Verification v = verify_engine(d.engine, ShotSettings{});
      std::printf(
          "SketchBook-II row %d (%g deg, F = %g, l = %g): derived R = %.0f m, T = %.0f kJ at X = %.3f (printed %g m, %g kJ); "
          "verified R = %.0f m, eps = %.1f %%\n",
          row.number, row.theta, row.F, row.l, d.capacity.R, d.capacity.T / 1e3, d.coordinates.X, row.R, row.T, v.capacity.R, 100 * v.eps);
      CHECK(std::abs(v.capacity.R / d.capacity.R - 1) < 0.02);
      CHECK(std::abs(v.capacity.T / d.capacity.T - 1) < 0.02);
      ratios.push_back(d.capacity.R / row.R);
    } catch (const Error& e) {
      // Row 7: the re-derived optima at F = 1/2 have l >= 6.6 over the whole X range, so none
      // has the printed l = 6.0 (docs/table_derivation.md).
      std::printf("SketchBook-II row %d: %s\n", row.number, e.what());
      CHECK(row.number == 7);
    }
  }
  // The explanation of the differences: (Lb, l) fixes X through l alone, and the re-derived
  // optima have a larger l at each X than the paper's (a flat direction of Q). So every row
  // moves to a lower X by the same shift and its R by the same factor: rows 1, 2 and 3 agree on
  // it to 2 %, though row 2 comes from a block the paper had and rows 1 and 3 from new ones.
  REQUIRE(ratios.size() == 3);
  const auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
  std::printf("derived R / printed R: %.3f to %.3f\n", *lo, *hi);
  CHECK(*hi / *lo - 1 < 0.02);
}

// tab:SketchBook-II rows 2, 4 and 5 lie in the built-in blocks (30 deg; F = 1 and 2/3): the
// calculator from their bold (Lb, l) against the printed engine. The pair (Lb, l) has an
// amplification of about 5.3 (the calculator's JSON), and the table's constants reproduce the
// ab-initio capacity to about 1 % (docs/calculator.md): R and T may differ by 5.3 % times that,
// the lengths and masses (which follow the capacity with exponents up to 5/4 for masses) by
// 1.5 %, each on top of half a unit of the printed digit.
TEST_CASE("tab:SketchBook-II rows 2, 4 and 5 from the calculator's (Lb, l)", "[calculator][paper]") {
  struct Row {
    int number;
    double F, l;
    const char *R, *T, *L1, *L4, *M, *m, *mb;  // as printed [m], [kJ], [m], [m], [t], [kg], [kg]
  };
  const Row rows[] = {{2, 1, 4.5, "407", "641", "7.36", "6.80", "26.0", "298", "1682"},
                      {4, 1, 5.5, "540", "700", "7.62", "7.16", "33.4", "248", "1605"},
                      {5, 2.0 / 3, 5.5, "401", "726", "7.62", "6.76", "34.9", "343", "1653"}};
  for (const Row& row : rows) {
    DesignRequest r;
    r.first = {Quantity::Lb, 9};
    r.second = {Quantity::l, row.l};
    r.F = row.F;
    const OptimalEngine d = design_optimal_engine(builtin_scaling_table(), r);
    const Engine& e = d.engine;
    std::printf("tab:SketchBook-II row %d from (Lb 9 m, l %g), amplification %.2f\n", row.number, row.l, d.amplification);
    const std::string name = "SketchBook-II #" + std::to_string(row.number) + " ";
    const double capacity_share = 0.01 * d.amplification, engine_share = 0.015;
    check_printed(name + "R [m]", d.capacity.R, row.R, capacity_share * d.capacity.R);
    check_printed(name + "T [kJ]", d.capacity.T / 1e3, row.T, capacity_share * d.capacity.T / 1e3);
    check_printed(name + "L1 [m]", e.L1, row.L1, engine_share * e.L1);
    check_printed(name + "L4 [m]", e.L4, row.L4, engine_share * e.L4);
    check_printed(name + "M [t]", e.M / 1e3, row.M, engine_share * e.M / 1e3);
    check_printed(name + "m [kg]", e.m, row.m, engine_share * e.m);
    check_printed(name + "mb [kg]", e.mb, row.mb, engine_share * e.mb);
  }
}

// Row 6 (F = 2/3, l = 6.0) from its bold (Lb 9 m, l 6.0) comes out 4.5 % low in T. Not the
// table's fault: the printed row is the table's own optimum for its printed capacity, 482 m and
// 752 kJ, whose engine has Lb = 9.08 m at l = 6.03 (its L1 = 7.74 m is printed; Lb l/(l + 1)
// gives 7.714 m, docs/verifier.md "The paper's slips"). T goes as the fifth power of the size
// (eq:ExtraScalings), so 0.9 % in Lb is 4.5 % in T. Pinned both ways: from (R, T) the printed
// engine within the tolerances of the rows above; from (Lb, l) T between 3 and 6 % low and R
// within 2 %.
TEST_CASE("tab:SketchBook-II row 6: the printed engine is the optimum for its capacity, at Lb = 9.08 m", "[calculator][paper]") {
  DesignRequest from_capacity;
  from_capacity.first = {Quantity::R, 482};
  from_capacity.second = {Quantity::T, 752e3};
  from_capacity.F = 2.0 / 3;
  const OptimalEngine d = design_optimal_engine(builtin_scaling_table(), from_capacity);
  const Engine& e = d.engine;
  std::printf("tab:SketchBook-II row 6 from (R 482 m, T 752 kJ): Lb = %.3f m, l = %.3f\n", beam_length(e), e.L1 / e.L2);
  check_printed("SketchBook-II #6 L1 [m]", e.L1, "7.74", 0.015 * e.L1);
  check_printed("SketchBook-II #6 L4 [m]", e.L4, "6.98", 0.015 * e.L4);
  check_printed("SketchBook-II #6 M [t]", e.M / 1e3, "38.7", 0.015 * e.M / 1e3);
  check_printed("SketchBook-II #6 m [kg]", e.m, "299", 0.015 * e.m);
  check_printed("SketchBook-II #6 mb [kg]", e.mb, "1623", 0.015 * e.mb);
  check_printed("SketchBook-II #6 l", e.L1 / e.L2, "6.0", 0.015 * e.L1 / e.L2);

  DesignRequest from_beam = from_capacity;
  from_beam.first = {Quantity::Lb, 9};
  from_beam.second = {Quantity::l, 6.0};
  const OptimalEngine b = design_optimal_engine(builtin_scaling_table(), from_beam);
  const double T_low = 1 - b.capacity.T / 752e3, R_off = b.capacity.R / 482 - 1;
  std::printf("tab:SketchBook-II row 6 from (Lb 9 m, l 6.0): T %.1f %% low, R %+.1f %%; (9.08/9)^5 = %.3f\n", 100 * T_low, 100 * R_off,
              std::pow(beam_length(e) / 9, 5));
  CHECK(T_low > 0.03);
  CHECK(T_low < 0.06);
  CHECK(std::abs(R_off) < 0.02);
}

// Section 7: cutting row 7's 45.9 t counterweight to 30 t by shrinking the engine. The paper
// linearises, dR/R = dL/L = dM/M / 4, "about 8 %", R "reduced by 22 m to 275 m", and writes
// "T drops strongly to 102 kJ". By eq:ExtraScalings exactly, lengths go as M^(1/4) and T as
// M^(5/4): R = 297 (30/45.9)^(1/4) = 267 m and T = 858 (30/45.9)^(5/4) = 504 kJ. 102 kJ fits
// no reading (T/M would have to fall by 5); docs/verifier.md lists it among the slips. The
// numbers are printed; what is checked is that the calculator's scaling obeys these laws.
TEST_CASE("section 7: row 7 of tab:SketchBook-II shrunk to a 30 t counterweight", "[calculator][paper][slips]") {
  const double ratio = 30 / 45.9;
  const double R = 297 * std::pow(ratio, 0.25), T = 858 * std::pow(ratio, 1.25);
  std::printf("section 7, row 7 at 30 t: R = %.1f m (paper 275 m by the linearised 8 %%), T = %.0f kJ (paper 102 kJ)\n", R, T);
  // The calculator shrinks an optimum by exactly these laws (--scale): shown on row 6's block,
  // as the (30 deg, F = 1/2) block of row 7 is not built in.
  DesignRequest r;
  r.first = {Quantity::Lb, 9};
  r.second = {Quantity::l, 6.0};
  r.F = 2.0 / 3;
  const OptimalEngine full = design_optimal_engine(builtin_scaling_table(), r);
  const OptimalEngine shrunk = scale_optimal_engine(full, std::pow(30e3 / full.engine.M, 0.25));
  CHECK(std::abs(shrunk.engine.M / 30e3 - 1) < 1e-12);
  CHECK(std::abs(shrunk.capacity.T / full.capacity.T - std::pow(30e3 / full.engine.M, 1.25)) < 1e-12);
  CHECK(std::abs(shrunk.capacity.R / full.capacity.R - std::pow(30e3 / full.engine.M, 0.25)) < 1e-12);
}
