// Which table's designs are better (issue 5): for capacities on the X axis of each block both
// tables cover, the calculator's design from the paper's tab:CPNC and from a re-derived table,
// each verified ab initio. A design's shape is then fitted to the capacity exactly (section 5,
// steps 2-4) so that Q compares like with like, and set beside the ab-initio optimum.
// Prints CSV and one summary line per block.
// Usage: compare-tables DERIVED_TABLE.json
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "trebuchet/app/records/table_json.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/capacity_fit.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/sweep.hpp"

using namespace trebuchet;

namespace {

struct Scored {
  double R_deviation = 0, T_deviation = 0;  // of the design as the calculator gives it, relative
  double Q_fitted = 0;  // of its shape fitted to the capacity
};

Scored score(const ScalingTable& table, double R, double T, double theta_i_deg, double F) {
  DesignRequest request;
  request.first = {Quantity::R, R};
  request.second = {Quantity::T, T};
  request.theta_i_deg = theta_i_deg, request.F = F;
  const Engine engine = design_optimal_engine(table, request).engine;
  const Verification v = verify_engine(engine, ShotSettings{});
  Scored out;
  out.R_deviation = v.capacity.R / R - 1;
  out.T_deviation = v.capacity.T / T - 1;
  out.Q_fitted = fit_capacity(scaled_design(engine), {R, T}, Material{}, ShotSettings{}).verification.Q;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: compare-tables DERIVED_TABLE.json\n");
    return 2;
  }
  try {
    const ScalingTable& paper = builtin_scaling_table();
    const ScalingTable derived = load_scaling_table(argv[1]);
    std::printf("theta_i_deg,F,X,R_m,T_J,paper_R_dev,paper_T_dev,derived_R_dev,derived_T_dev,paper_Q,derived_Q,optimum_Q\n");
    for (const TableBlock& block : paper.blocks) {
      const TableBlock* ours = derived.find_block(block.theta_i_deg, block.F);
      if (!ours) continue;
      double sum_paper = 0, sum_derived = 0;
      int count = 0, derived_wins = 0;
      for (double X : {-0.5, -0.25, 0.0, 0.25, 0.5}) {
        const Capacity capacity = capacity_at({X, 0}, paper.R0, paper.T0);
        const double R = capacity.R, T = capacity.T;
        const Scored p = score(paper, R, T, block.theta_i_deg, block.F);
        const Scored d = score(derived, R, T, block.theta_i_deg, block.F);
        OptimizeRequest request;
        request.capacity = capacity;
        request.theta_i_deg = block.theta_i_deg, request.F = block.F;
        const double optimum = best_optimum(optimize(request)).objective;
        std::printf("%g,%.4f,%+.2f,%.2f,%.0f,%+.4f,%+.4f,%+.4f,%+.4f,%.4f,%.4f,%.4f\n", block.theta_i_deg, block.F, X, R, T, p.R_deviation,
                    p.T_deviation, d.R_deviation, d.T_deviation, 100 * p.Q_fitted, 100 * d.Q_fitted, 100 * optimum);
        sum_paper += p.Q_fitted / optimum, sum_derived += d.Q_fitted / optimum;
        derived_wins += d.Q_fitted > p.Q_fitted;
        ++count;
      }
      std::printf("# theta %g F %.3f: mean Q / optimum Q: paper's table %.4f, re-derived %.4f; re-derived higher in %d of %d\n", block.theta_i_deg,
                  block.F, sum_paper / count, sum_derived / count, derived_wins, count);
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "compare-tables: %s\n", e.what());
    return 1;
  }
}
