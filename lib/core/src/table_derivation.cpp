#include "trebuchet/table_derivation.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {

ExponentialFit fit_exponential(const std::vector<double>& X, const std::vector<double>& f) {  // eq:f_MX
  if (X.size() != f.size() || X.size() < 2) throw Error(ErrorKind::data_file, "an exponential fit needs two or more points");
  const Eigen::Index n = static_cast<Eigen::Index>(X.size());
  Eigen::MatrixXd design(n, 2);  // log f = log a + b u with u = sqrt(26) X: columns (1, u)
  Eigen::VectorXd log_f(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(f[i] > 0)) throw Error(ErrorKind::data_file, "f_Z at X = " + format_number(X[i]) + " is not positive");
    design(i, 0) = 1;
    design(i, 1) = std::sqrt(26.0) * X[i];
    log_f(i) = std::log(f[i]);
  }
  const Eigen::Vector2d c = design.colPivHouseholderQr().solve(log_f);
  const Eigen::VectorXd fitted = design * c;
  return {std::exp(c(0)), c(1), ((fitted - log_f).array().exp() - 1).abs().maxCoeff()};
}

namespace {

// n_Z of eq:f_ZX, in the column order of tab:CPNC: lengths 1, D 3/2, masses 4.
const ParamVector n_Z = (ParamVector() << 1, 1, 1, 1.5, 4, 4, 4).finished();

ParamVector fitted_params(const Engine& e) { return (ParamVector() << e.L1, e.L2, e.L4, e.D, e.M, e.m, e.mb).finished(); }

struct Block {
  SweepSpec spec;  // the first part's
  std::string first_origin;
  std::map<double, SweepPoint> points;  // by X
  std::map<double, std::string> origin_of;  // the part each point came from, for messages
};

[[noreturn]] void refuse_sweep(const std::string& where, const std::string& problem) { throw Error(ErrorKind::data_file, where + ": " + problem); }

std::string block_name(const SweepSpec& spec) {
  return "block theta " + format_number(spec.theta_i_deg) + " deg" +
      (spec.machine == MachineKind::hinged ? ", F " + format_fraction(spec.F) : std::string());
}

// eq:f_ZX fitted for every parameter over the points.
struct SegmentFit {
  std::vector<const SweepPoint*> points;
  std::array<ExponentialFit, param_count> fits;
  double worst = 0;  // largest fit_max_deviation over the parameters
};

SegmentFit fit_segment(const std::vector<const SweepPoint*>& points, const ParamVector& Z0, double R0) {
  SegmentFit out;
  out.points = points;
  for (Param param : all_params) {
    std::vector<double> X, f;
    for (const SweepPoint* point : points) {
      X.push_back(point->X);
      f.push_back(fitted_params(point->engine)[index(param)] / Z0[index(param)] / std::pow(point->capacity.R / R0, n_Z[index(param)]));
    }
    out.fits[index(param)] = fit_exponential(X, f);
    out.worst = std::max(out.worst, out.fits[index(param)].max_deviation);
  }
  return out;
}

// A fit worse than this is split in two at the grid point that fits best: the optimum changes
// regime along X (docs/table_derivation.md), which one exponential cannot follow. 1 % keeps the
// table well inside the 2 % at which the verifier checks the calculator's designs.
constexpr double max_fit_deviation = 0.01;
constexpr std::size_t min_segment_points = 3;

void fit_segments(const std::vector<const SweepPoint*>& points, const ParamVector& Z0, double R0, std::vector<SegmentFit>& out) {
  SegmentFit whole = fit_segment(points, Z0, R0);
  std::optional<std::pair<SegmentFit, SegmentFit>> best;
  if (whole.worst > max_fit_deviation)
    for (std::size_t k = min_segment_points - 1; k + min_segment_points <= points.size(); ++k) {  // both share point k
      SegmentFit left = fit_segment({points.begin(), points.begin() + k + 1}, Z0, R0);
      SegmentFit right = fit_segment({points.begin() + k, points.end()}, Z0, R0);
      if (!best || std::max(left.worst, right.worst) < std::max(best->first.worst, best->second.worst)) best = {left, right};
    }
  if (!best || std::max(best->first.worst, best->second.worst) >= whole.worst) {
    out.push_back(whole);
    return;
  }
  fit_segments(best->first.points, Z0, R0, out);
  fit_segments(best->second.points, Z0, R0, out);
}

// The table block, its segments' fit quality and its sweep, from the points of one block.
void derive_block(const Block& block, double R0, DerivedTable& out) {
  const std::string name = block_name(block.spec);
  const auto zero = block.points.find(0.0);
  if (zero == block.points.end() || !zero->second.error.empty())
    refuse_sweep(name, "no optimum at X = 0, which sets Z0 (tab:CPNC); give an X interval that holds 0");
  TableBlock table_block{};
  table_block.theta_i_deg = block.spec.theta_i_deg;
  table_block.F = block.spec.machine == MachineKind::hinged ? block.spec.F : 0;  // the others' counterweight at the arm's end
  table_block.Z0 = fitted_params(zero->second.engine);
  // The paper fits below and above X = 0 separately (tab:CPNC); so do we, and split further
  // where one exponential does not fit.
  std::vector<SegmentFit> fits;
  for (const auto& [lo, hi] : {std::pair{-HUGE_VAL, 0.0}, std::pair{0.0, HUGE_VAL}}) {
    std::vector<const SweepPoint*> side;
    for (const auto& [X, point] : block.points)
      if (X >= lo && X <= hi && point.error.empty()) side.push_back(&point);
    if (side.size() >= min_segment_points) fit_segments(side, table_block.Z0, R0, fits);
  }
  if (fits.empty()) refuse_sweep(name, "fewer than three optima on each side of X = 0; use a finer X step");
  std::vector<SegmentFitQuality> qualities;
  for (const SegmentFit& fit : fits) {
    Segment segment{fit.points.front()->X, fit.points.back()->X, Branch::none, {}, {}};
    SegmentFitQuality quality{static_cast<int>(fit.points.size()), {}};
    for (Param param : all_params) {
      const ExponentialFit& f = fit.fits[index(param)];
      segment.a[index(param)] = f.a;
      segment.exponents(index(param), 0) = n_Z[index(param)] + 5 * f.b;  // eq:ZRT: p_Z
      segment.exponents(index(param), 1) = -f.b;  // q_Z
      quality.fit_max_deviation[index(param)] = f.max_deviation;
    }
    table_block.segments.push_back(segment);
    qualities.push_back(quality);
  }
  out.table.blocks.push_back(table_block);
  out.fits.push_back(qualities);
  std::vector<SweepPoint> sweep;
  for (const auto& [X, point] : block.points) sweep.push_back(point);
  out.sweeps.push_back(sweep);
}

bool same_reference(const SweepSpec& a, const SweepSpec& b) {
  return a.R0 == b.R0 && a.T0 == b.T0 && a.material.beta2 == b.material.beta2 && a.material.youngs_modulus == b.material.youngs_modulus &&
      a.material.wood_density == b.material.wood_density && a.material.g == b.material.g && a.machine == b.machine;
}

bool same_grid_and_criterion(const SweepSpec& a, const SweepSpec& b) {
  return a.X_from == b.X_from && a.X_to == b.X_to && a.X_step == b.X_step && a.criterion.release == b.criterion.release &&
      a.criterion.n == b.criterion.n;
}

}  // namespace

DerivedTable derive_table(const std::vector<SweepPart>& parts) {
  if (parts.empty()) throw Error(ErrorKind::data_file, "no sweep parts to merge; give the parts of every shard ({{shard}} k/N)");
  std::map<std::pair<double, double>, Block> blocks;  // by (theta_i, F)
  const SweepPart& first = parts.front();
  for (const SweepPart& part : parts) {
    if (!same_reference(part.spec, first.spec))
      refuse_sweep(part.origin,
                   "its R0, T0, reference_material or machine differs from that of " + first.origin + "; merge sweeps of one reference only");
    // Another machine's counterweight sits at the short arm's end: its blocks differ in theta_i alone.
    Block& block = blocks[{part.spec.theta_i_deg, part.spec.machine == MachineKind::hinged ? part.spec.F : 0}];
    if (block.first_origin.empty()) {
      block.spec = part.spec;
      block.first_origin = part.origin;
    }
    if (!same_grid_and_criterion(part.spec, block.spec))
      refuse_sweep(part.origin,
                   "its X grid or quality differs from that of " + block.first_origin + " for the same " + block_name(part.spec) +
                       "; run every shard with the same {{X}} and {{quality}}");
    for (const SweepPoint& point : part.points) {
      if (!block.points.emplace(point.X, point).second)
        refuse_sweep(
            part.origin,
            block_name(part.spec) + ": X = " + format_number(point.X) + " is also in " + block.origin_of[point.X] + "; give each shard once");
      block.origin_of[point.X] = part.origin;
    }
  }
  DerivedTable out;
  ScalingTable& table = out.table;
  table.name = "tab:CPNC re-derived ab initio";
  table.machine = first.spec.machine;
  table.provenance = {
      {"source", "trebuchet-verify derive-table: the ab-initio optimum (appendix A, section 5) at each X point of the sweep, Y = 0 (eq:XY_RT)"},
      {"law", "Z/Z0 = a_Z (R/R0)^p_Z (T/T0)^q_Z (eq:ZRT), p_Z = n_Z + 5 b_Z, q_Z = -b_Z from f_Z = a_Z exp(b_Z sqrt(26) X) (eq:f_ZX)"},
      {"fit",
       "least squares of log f_Z against X, separately for X <= 0 and X >= 0; fit_max_deviation is the largest |fit/f_Z - 1| over a segment's "
       "points"},
      {"branches", "one optimum per X point under this program's Q (docs/table_derivation.md); optima_found counts distinct optima from the starts"}};
  table.R0 = first.spec.R0;
  table.T0 = first.spec.T0;
  table.reference = first.spec.material;
  table.n = n_Z;
  for (auto& [key, block] : blocks) {
    const std::string name = block_name(block.spec);
    const std::vector<double> grid = sweep_grid(block.spec);
    for (double X : grid)
      if (!block.points.count(X)) refuse_sweep(name, "X = " + format_number(X) + " is missing; merge every shard k/N of the sweep");
    if (block.points.size() != grid.size()) refuse_sweep(name, "points off the X grid; merge parts of one sweep only");
    derive_block(block, table.R0, out);
  }
  return out;
}

std::vector<double> failed_points(const DerivedTable& derived) {
  std::vector<double> failed;
  for (const auto& sweep : derived.sweeps)
    for (const SweepPoint& point : sweep)
      if (!point.error.empty()) failed.push_back(point.X);
  return failed;
}

}  // namespace trebuchet
