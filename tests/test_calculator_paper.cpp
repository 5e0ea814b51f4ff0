// The calculator against the paper's tables, row by row. Each tolerance is half a unit of
// the printed digit plus the first-order effect of rounding every constant of tab:CPNC in
// the block to its printed digits (paper_rounding.hpp); the paper computed with the unrounded
// fits, so that is the largest difference rounding alone explains.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "paper_rounding.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;
using namespace trebuchet::testing;

namespace {

DesignRequest request(Given first, Given second, double theta_i_deg, double F) {
  DesignRequest r;
  r.first = first;
  r.second = second;
  r.theta_i_deg = theta_i_deg;
  r.F = F;
  return r;
}

struct CalculatorColumn {
  const char* name;  // quantity, as in the paper's column
  const char* text;  // printed value
  double scale;  // our SI value times scale = the paper's unit
  double known_deviation = 0;  // > 0: the printed value is off by more than rounding; bound on |ours/paper - 1|
};

double design_figure(const OptimalEngine& d, const std::string& name) {
  const Engine& e = d.engine;
  if (name == "T") return d.capacity.T;
  if (name == "L1") return e.L1;
  if (name == "L2") return e.L2;
  if (name == "L4") return e.L4;
  if (name == "D") return e.D;
  if (name == "M") return e.M;
  if (name == "mb") return e.mb;
  if (name == "Lb") return beam_length(e);
  if (name == "l") return scaled_design(e).l;
  if (name == "H") return pivot_height(e);
  throw std::logic_error("no column " + name);
}

void check_design_row(const std::string& row, const DesignRequest& r, std::initializer_list<CalculatorColumn> expected) {
  std::printf("%s\n", row.c_str());
  const OptimalEngine design = design_optimal_engine(builtin_scaling_table(), r);
  for (const CalculatorColumn& column : expected) {
    if (column.known_deviation > 0) {
      const double paper = printed(column.text).value;
      const double ours = design_figure(design, column.name) * column.scale;
      std::printf("  %-34s ours %-11.5g paper %-7s diff %+6.2f%%  known deviation beyond rounding, bound %.1f%%\n", (row + " " + column.name).c_str(),
                  ours, column.text, 100 * (ours / paper - 1), 100 * column.known_deviation);
      CHECK(std::abs(ours / paper - 1) <= column.known_deviation);
      continue;
    }
    const double rounding = table_rounding_effect(
        r.theta_i_deg, r.F, [&](const ScalingTable& table) { return design_figure(design_optimal_engine(table, r), column.name); });
    check_printed(row + " " + column.name, design_figure(design, column.name), column.text, rounding, column.scale);
  }
}

}  // namespace

// tab:Alcala_la_Vieja: theta_i = 30 deg, F = 2/3, m = 50 kg stones; R given.
// Row Ma (426 m) differs from tab:CPNC by more than rounding in M: the printed 9.70 t is
// 1.7% below the 9.86 t that the constants give (L1, L4, D, T agree; L2 = 0.75 m uses 87% of
// its tolerance). The same constants reproduce the Ma 480 m row to 2%, so the printed M of
// this row, not the table, is off; the test pins the deviation at 2%.
TEST_CASE("tab:Alcala_la_Vieja row Ca: R = 150 m, m = 50 kg", "[calculator][paper]") {
  check_design_row(
      "Alcala Ca", request({Quantity::R, 150}, {Quantity::m, 50}, 30, 2.0 / 3),
      {{"T", "40.3", 1e-3}, {"L1", "4.13", 1}, {"L2", "0.88", 1}, {"L4", "3.55", 1}, {"D", "0.25", 1}, {"M", "3.11", 1e-3}, {"mb", "174", 1}});
}

TEST_CASE("tab:Alcala_la_Vieja row Ma: R = 480 m, m = 50 kg", "[calculator][paper]") {
  check_design_row(
      "Alcala Ma 480", request({Quantity::R, 480}, {Quantity::m, 50}, 30, 2.0 / 3),
      {{"T", "124", 1e-3}, {"L1", "5.50", 1}, {"L2", "0.71", 1}, {"L4", "5.15", 1}, {"D", "0.31", 1}, {"M", "11.5", 1e-3}, {"mb", "334", 1}});
}

TEST_CASE("tab:Alcala_la_Vieja row Ma: R = 426 m (aim shortened for the -54 m target)", "[calculator][paper]") {
  check_design_row(
      "Alcala Ma 426", request({Quantity::R, 426}, {Quantity::m, 50}, 30, 2.0 / 3),
      {{"T", "111", 1e-3}, {"L1", "5.36", 1}, {"L2", "0.75", 1}, {"L4", "4.96", 1}, {"D", "0.31", 1}, {"M", "9.70", 1e-3, 0.02}, {"mb", "320", 1}});
}

TEST_CASE("tab:Alcala_la_Vieja row Sa: R = 250 m, m = 50 kg", "[calculator][paper]") {
  check_design_row(
      "Alcala Sa", request({Quantity::R, 250}, {Quantity::m, 50}, 30, 2.0 / 3),
      {{"T", "66.0", 1e-3}, {"L1", "4.72", 1}, {"L2", "0.85", 1}, {"L4", "4.19", 1}, {"D", "0.28", 1}, {"M", "5.16", 1e-3}, {"mb", "242", 1}});
}

// tab:SketchBook-I, rows with n = 1 (found algebraically in the paper): R = 450 m, m = 100 kg.
TEST_CASE("tab:SketchBook-I n = 1, F = 1, theta_i = 30 deg", "[calculator][paper]") {
  check_design_row(
      "SketchBook-I F=1 30deg", request({Quantity::R, 450}, {Quantity::m, 100}, 30, 1),
      {{"T", "235", 1e-3}, {"L1", "6.13", 1}, {"L4", "5.80", 1}, {"M", "14.3", 1e-3}, {"mb", "660", 1}, {"Lb", "7.21", 1}, {"l", "5.68", 1}});
}

TEST_CASE("tab:SketchBook-I n = 1, F = 2/3, theta_i = 30 deg", "[calculator][paper]") {
  check_design_row(
      "SketchBook-I F=2/3 30deg", request({Quantity::R, 450}, {Quantity::m, 100}, 30, 2.0 / 3),
      {{"T", "234", 1e-3}, {"L1", "6.20", 1}, {"L4", "5.69", 1}, {"M", "16.9", 1e-3}, {"mb", "601", 1}, {"Lb", "7.12", 1}, {"l", "6.77", 1}});
}

// The theta_i = 40 deg row differs from tab:CPNC by more than rounding in L4 (printed 5.55 m,
// the constants give 5.65 m: +1.8%) and M (19.1 t against 18.85 t: -1.3%); T, L1, Lb, l and
// mb agree. The block's constants satisfy p + 5q = n_Z (eq:ZRT) to their last digit, so they
// are self-consistent; the printed row does not follow from them.
TEST_CASE("tab:SketchBook-I n = 1, F = 2/3, theta_i = 40 deg", "[calculator][paper]") {
  check_design_row("SketchBook-I F=2/3 40deg", request({Quantity::R, 450}, {Quantity::m, 100}, 40, 2.0 / 3),
                   {{"T", "234", 1e-3},
                    {"L1", "6.48", 1},
                    {"L4", "5.55", 1, 0.02},
                    {"M", "19.1", 1e-3, 0.015},
                    {"mb", "622", 1},
                    {"Lb", "7.35", 1},
                    {"l", "7.51", 1}});
}

// Section 6.3: Denny's standard parameters Lb = 12 m, M = 10 t, m = 100 kg, mb = 2 t with
// theta_i = 30 deg, F = 2/3. Of the six pairs only (M, m) has a capacity inside tab:CPNC.
TEST_CASE("section 6.3: Denny's standard parameters, pair (M, m)", "[calculator][paper]") {
  const DesignRequest r = request({Quantity::M, 10000}, {Quantity::m, 100}, 30, 2.0 / 3);
  const OptimalEngine design = design_optimal_engine(builtin_scaling_table(), r);
  std::printf("section 6.3 (M, m)\n");
  auto rounding = [&](auto pick_value) {
    return table_rounding_effect(30, 2.0 / 3, [&](const ScalingTable& t) { return pick_value(design_optimal_engine(t, r)); });
  };
  check_printed("R", design.capacity.R, "288", rounding([](const OptimalEngine& d) { return d.capacity.R; }));
  check_printed("T", design.capacity.T, "152", rounding([](const OptimalEngine& d) { return d.capacity.T; }), 1e-3);
  check_printed("X", design.coordinates.X, "-0.17", rounding([](const OptimalEngine& d) { return d.coordinates.X; }));
  check_printed("Lb", beam_length(design.engine), "6.6", rounding([](const OptimalEngine& d) { return beam_length(d.engine); }));
  // "mb ~ 475 kg": read as 475 +- 5 kg (the paper writes ~, we take the last printed digit as tens).
  check_printed("mb", design.engine.mb, "475", 4.5 + rounding([](const OptimalEngine& d) { return d.engine.mb; }));
  // "The efficiency of the optimized engine is ~92%": the calculator's engine shot ab initio,
  // within half a unit of "92" and the change the table's rounding makes in it.
  auto eps = [](const OptimalEngine& d) { return 100 * verify_engine(d.engine, ShotSettings{}).eps; };
  check_printed("eps [%]", eps(design), "92", rounding(eps));
}

// eq:kMkD: k_M = (4 pi/3) g rho_d^2/M_e = 1.68e-3 kg/m^4 and k_D = (16/3) g rho_d/M_e =
// 3.06e-6 1/m for M_e = 12 GPa, rho_d = 700 kg/m^3 and g = 9.81 m/s^2. k_M agrees to half a
// unit of its printed third digit. k_D does not: the formula gives 3.052e-6, which prints as
// 3.05; 3.06 would need g = 9.84 m/s^2. A slip of the last digit (docs/verifier.md, "The
// paper's slips"), pinned at that: within a unit and a half of the printed digit, not half.
TEST_CASE("eq:kMkD: k_M and k_D of the paper's wood", "[calculator][paper][slips]") {
  std::printf("eq:kMkD\n");
  check_printed("k_M [1e-3 kg/m^4]", k_M(Material{}) * 1e3, "1.68", 0);
  check_printed("k_D [1e-6 1/m] (printed one unit high)", k_D(Material{}) * 1e6, "3.06", 0.01);
  CHECK(std::abs(k_D(Material{}) * 1e6 - 3.06) > 0.005);  // the slip: not a rounding of 3.052
}

TEST_CASE("section 6.3: the other five of Denny's pairs have no meaningful capacity", "[calculator][paper]") {
  const Given Lb{Quantity::Lb, 12}, M{Quantity::M, 10000}, m{Quantity::m, 100}, mb{Quantity::mb, 2000};
  const std::pair<Given, Given> pairs[] = {{Lb, M}, {Lb, m}, {Lb, mb}, {M, mb}, {m, mb}};
  for (const auto& [first, second] : pairs) {
    INFO(quantity_name(first.quantity) << " with " << quantity_name(second.quantity));
    try {
      design_optimal_engine(builtin_scaling_table(), request(first, second, 30, 2.0 / 3));
      FAIL("a capacity was returned");
    } catch (const Error& e) {
      CHECK(e.kind() == ErrorKind::out_of_range);
      CHECK_THAT(e.what(), Catch::Contains("no meaningful capacity"));
      std::printf("  refused: %s\n", e.what());
    }
  }
}

// Section 6.2, theta_i = 30 deg, F = 1: the steps S_Z of eq:ZiZj_vs_X at X_d = 0.34.
TEST_CASE("section 6.2: steps S_Z between the branches at X_d", "[calculator][paper]") {
  const TableBlock& block = *builtin_scaling_table().find_block(30, 1);
  const auto steps = branch_steps(block);
  REQUIRE(steps);
  std::printf("section 6.2 steps at X_d (percent)\n");
  auto rounding = [&](Param param) {
    return 100 * table_rounding_effect(30, 1, [&](const ScalingTable& t) { return (*branch_steps(*t.find_block(30, 1)))[index(param)]; });
  };
  check_printed("S_L4", 100 * ((*steps)[index(Param::L4)] - 1), "16.3", rounding(Param::L4));
  check_printed("S_L1", 100 * ((*steps)[index(Param::L1)] - 1), "4.4", rounding(Param::L1));
  check_printed("S_M", 100 * ((*steps)[index(Param::M)] - 1), "-8.7", rounding(Param::M));
  // "m increases by less than 1%"
  CHECK((*steps)[index(Param::m)] > 1.0);
  CHECK((*steps)[index(Param::m)] < 1.01);
}

// Section 6.2: l4 = 0.965 (1 + 0.119 (X - X_d)) on the lower branch and
// 1.075 (1 - 0.024 (X - X_d)) on the upper one, read off the calculator's designs.
TEST_CASE("section 6.2: expansions of l4 near X_d on both branches", "[calculator][paper]") {
  const double X_d = 0.34;
  auto l4_at = [&](const ScalingTable& table, double X, BranchChoice branch) {
    // A capacity on the X axis (Y = 0), eq:XY_RT.
    const Capacity capacity = capacity_at({X, 0}, table.R0, table.T0);
    DesignRequest r = request({Quantity::R, capacity.R}, {Quantity::T, capacity.T}, 30, 1);
    r.branch = branch;
    return scaled_design(design_optimal_engine(table, r).engine).l4;
  };
  auto slope_at = [&](const ScalingTable& table, BranchChoice branch) {  // d ln l4 / dX, exact for eq:ZRT
    const double h = 1e-4;
    return (std::log(l4_at(table, X_d + h, branch)) - std::log(l4_at(table, X_d - h, branch))) / (2 * h);
  };
  std::printf("section 6.2 l4 near X_d\n");
  for (auto [choice, value, slope] : {std::tuple{BranchChoice::lower, "0.965", "0.119"}, std::tuple{BranchChoice::upper, "1.075", "-0.024"}}) {
    const BranchChoice branch = choice;  // a lambda may not capture a structured binding before C++20 in clang 14
    const std::string name = branch == BranchChoice::lower ? "lower" : "upper";
    check_printed(name + " l4(X_d)", l4_at(builtin_scaling_table(), X_d, branch), value,
                  table_rounding_effect(30, 1, [&](const ScalingTable& t) { return l4_at(t, X_d, branch); }));
    check_printed(name + " d ln l4/dX", slope_at(builtin_scaling_table(), branch), slope,
                  table_rounding_effect(30, 1, [&](const ScalingTable& t) { return slope_at(t, branch); }));
  }
}
