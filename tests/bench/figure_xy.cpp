// fig:XY remade (issue 13): prints a gnuplot script that draws the (R, T) plane with the X, Y axes
// of eq:XY_RT through (R0, T0), the band of X each block of tab:CPNC covers (lines of constant X
// are where optimal engines scale), and the capacities of the paper's cases. scripts/figures.sh
// runs it. Usage: figure-xy > docs/figures/xy.gp
#include <cmath>
#include <cstdio>

#include "trebuchet/capacity.hpp"
#include "trebuchet/scaling_table.hpp"

using namespace trebuchet;

int main() {
  const ScalingTable& table = builtin_scaling_table();
  const double R0 = table.R0, T0 = table.T0 / 1000, r26 = std::sqrt(26.0);  // [m], [kJ]
  struct Case {
    const char* label;  // one label for a group of close cases
    double R, T_kJ;  // as the paper prints them
  };
  const Case cases[] = {{"Alcalá Ca", 150, 40.3},
                        {"Alcalá Ma (480 m and 426 m)", 480, 124},
                        {"", 426, 111},
                        {"Alcalá Sa", 250, 66.0},
                        {"tab:Denny, tab:SketchBook-I, tab:Large_Eff", 425, 224},
                        {"", 450, 235},
                        {"", 450, 232},
                        {"tab:SketchBook-II rows 1-7", 540, 700},
                        {"", 426, 677},
                        {"", 407, 641},
                        {"", 341, 540},
                        {"", 401, 726},
                        {"", 482, 752},
                        {"", 297, 858}};
  std::printf(
      "# Made by figure-xy (tests/bench/figure_xy.cpp) for scripts/figures.sh.\n"
      "set encoding utf8\nset terminal svg size 900,700 dynamic font 'sans,12'\nset output 'docs/figures/xy.svg'\n"
      "set logscale xy\nset xrange [40:1500]\nset yrange [1:5000]\nset xlabel 'range R [m]'\nset ylabel 'energy at the target T [kJ]'\n"
      "set grid\nset key bottom right box opaque noenhanced\nset samples 400\n"
      "set title \"fig:XY: the coordinates (X, Y) of eq:XY_RT about (R0, T0) = (%g m, %g kJ)\\n"
      "optimal engines scale along lines of constant X; the dashed lines bound the X each block covers\" noenhanced\n",
      R0, T0);
  // A line of constant X: T = T0 (R/R0)^5 exp(-sqrt(26) X).
  std::printf("T_at(R, X) = %.10g * (R / %.10g)**5 * exp(-%.10g * X)\n", T0, R0, r26);
  std::printf("set arrow from %g,%g to %g,%g lw 2 lc rgb 'black' front\n", R0 * std::exp(-5 * 1.2 / r26), T0 * std::exp(1.2 / r26),
              R0 * std::exp(5 * 1.2 / r26), T0 * std::exp(-1.2 / r26));
  std::printf("set label 'X' at %g,%g offset 0.5,0 front\n", R0 * std::exp(5 * 1.2 / r26), T0 * std::exp(-1.2 / r26));
  std::printf("set arrow from %g,%g to %g,%g lw 2 lc rgb 'black' front\n", R0 * std::exp(-0.6 / r26), T0 * std::exp(-3 / r26),
              R0 * std::exp(1.0 / r26), T0 * std::exp(5 / r26));
  std::printf("set label 'Y' at %g,%g offset 0.5,0 front\n", R0 * std::exp(1.0 / r26), T0 * std::exp(5 / r26));
  std::printf("set object circle at %g,%g size screen 0.006 fc rgb 'black' fs solid front\n", R0, T0);
  std::printf("plot ");
  const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728"};
  int k = 0;
  for (const TableBlock& b : table.blocks) {
    std::printf(
        "T_at(x, %.6g) with lines dt %d lw 2 lc rgb '%s' title 'θi = %g°, F = %s: X in [%.2f, %.2f]', T_at(x, %.6g) with lines dt %d lw 2 lc rgb "
        "'%s' notitle, \\\n     ",
        b.X_covered_min(), k + 2, colours[k % 4], b.theta_i_deg,
        std::abs(b.F - 2.0 / 3) < 1e-9   ? "2/3"
            : std::abs(b.F - 0.5) < 1e-9 ? "1/2"
                                         : "1",
        b.X_covered_min(), b.X_covered_max(), b.X_covered_max(), k + 2, colours[k % 4]);
    ++k;
  }
  std::printf(
      "'-' using 1:2 with points pt 7 ps 1.2 lc rgb 'black' title \"the paper's cases\", \\\n     '-' using 1:2:3 with labels left offset 1,0 font "
      "',9' noenhanced notitle\n");
  for (int pass = 0; pass < 2; ++pass) {
    for (const Case& c : cases) {
      const CapacityCoordinates xy = capacity_coordinates(std::log(c.R / R0), std::log(c.T_kJ / T0));
      if (pass == 0)
        std::printf("%g %g\n", c.R, c.T_kJ);
      else if (*c.label)
        std::printf("%g %g \"%s (X %.2f)\"\n", c.R, c.T_kJ, c.label, xy.X);
    }
    std::printf("e\n");
  }
}
