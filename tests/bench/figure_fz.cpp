// fig:fZ_vs_X remade (issue 13): for each block of a re-derived table (data/cpnc-derived.json),
// one gnuplot script per block that draws, for each of the seven parameters Z, the sweep's
// optima as points, the re-derived f_Z as lines and the paper's (tab:CPNC) beside them, on the
// paper's axes: (Z/Z0)/(R/R0)^n_Z against X, semi-log. Within a segment eq:ZRT with p + 5q = n
// and ln(T/T0) = 5 ln(R/R0) - sqrt(26) X (eq:Xi) gives f_Z(X) = a_Z exp(-sqrt(26) q_Z X).
// Everything is over the paper's Z0, so that the two tables' lines compare.
// Usage: figure-fz DERIVED.json OUTDIR   (writes OUTDIR/fz_THETA_F.gp, which write .svg beside)
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "trebuchet/scaling_table.hpp"
#include "trebuchet/app/records/table_json.hpp"

using namespace trebuchet;

namespace {

// The lines of one table's block for parameter k, over the paper's Z0, as a gnuplot plot clause.
std::string f_lines(const TableBlock& b, int k, double paper_Z0, const char* colour, const char* dash) {
  std::ostringstream out;
  for (const Segment& s : b.segments) {
    out << "[" << s.X_min << ":" << s.X_max << "] '+' using 1:(" << s.a(k) * b.Z0(k) / paper_Z0 << "*exp(-sqrt(26)*" << s.exponents(k, 1)
        << "*$1)) with lines lw 2 dt " << dash << " lc rgb '" << colour << "' notitle, ";
  }
  return out.str();
}

std::string block_tag(const TableBlock& b) {
  char tag[64];
  std::snprintf(tag, sizeof tag, "fz_%g_%s", b.theta_i_deg, std::abs(b.F - 2.0 / 3) < 1e-9 ? "2-3" : std::abs(b.F - 0.5) < 1e-9 ? "1-2" : "1");
  return tag;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: figure-fz DERIVED.json OUTDIR\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const ScalingTable derived = parse_scaling_table(text, argv[1]);
  const nlohmann::json raw = nlohmann::json::parse(text);
  const ScalingTable& paper = builtin_scaling_table();
  for (std::size_t bi = 0; bi < derived.blocks.size(); ++bi) {
    const TableBlock& ours = derived.blocks[bi];
    const TableBlock* theirs = paper.find_block(ours.theta_i_deg, ours.F);
    if (!theirs) continue;
    const std::string tag = block_tag(ours);
    std::ofstream gp(std::string(argv[2]) + "/" + tag + ".gp");
    gp << "# Made by figure-fz (tests/bench/figure_fz.cpp) for scripts/figures.sh.\nset encoding utf8\n"
       << "set terminal svg size 1200,650 dynamic font 'sans,11'\nset output '" << argv[2] << "/" << tag << ".svg'\n"
       << "set logscale y\nset grid\nset samples 60\nset xrange [-0.6:0.6]\nunset key\n"
       << "set multiplot layout 2,4 title \"fig:fZ_vs_X for θi = " << ours.theta_i_deg << "°, F = " << (tag.substr(tag.rfind('_') + 1))
       << ": the sweep's optima (points), our fitted f_Z (lines) and the paper's (dashed)\\nall over the paper's Z0; X of eq:Xi\" noenhanced\n";
    for (Param param : all_params) {
      const int k = index(param);
      const std::string name(param_name(param));
      gp << "set title '" << name << "' noenhanced\nset xlabel 'X'\nset ylabel '(" << name << "/" << name << "_0)/(R/R_0)^{n_Z}'\n"
         << "$points << EOD\n";
      for (const auto& point : raw["blocks"][bi]["sweep"]) {
        if (!point.contains(name) || !point[name].is_number()) continue;
        const double R = point["R"].get<double>(), X = point["X"].get<double>(), Z = point[name].get<double>();
        gp << X << " " << Z / theirs->Z0(k) / std::pow(R / paper.R0, paper.n(k)) << "\n";
      }
      gp << "EOD\nplot sample " << f_lines(ours, k, theirs->Z0(k), "#1f77b4", "1") << f_lines(*theirs, k, theirs->Z0(k), "#d62728", "2")
         << "$points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle\n";
    }
    // The eighth cell holds the legend.
    gp << "unset title\nunset xlabel\nunset ylabel\nunset tics\nunset border\nunset grid\nset key center center box font ',12'\nset yrange [1:2]\n"
       << "plot NaN with points pt 7 lc rgb 'black' title 'the sweep’s optima', NaN with lines lw 2 lc rgb '#1f77b4' title 'our f_Z (re-derived)', "
       << "NaN with lines lw 2 dt 2 lc rgb '#d62728' title 'the paper’s f_Z (tab:CPNC)'\nunset multiplot\n";
    std::printf("%s/%s.gp\n", argv[2], tag.c_str());
  }
}
