#include "trebuchet/calculator.hpp"

#include <algorithm>
#include <Eigen/Dense>
#include <cmath>
#include <string_view>
#include <functional>
#include <limits>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "solve_1d.hpp"

namespace trebuchet {
namespace {

// log(value) = c + pq (log(R/R0), log(T/T0)): a quantity that is log-linear in the capacity,
// as every entry of eq:ZRT is (one row of eq:RT_Z1Z2, or R and T themselves).
struct LogLaw {
  double c;
  Eigen::RowVector2d pq;
};

std::optional<Param> fitted_param(Quantity quantity) {
  switch (quantity) {
    case Quantity::L1: return Param::L1;
    case Quantity::L2: return Param::L2;
    case Quantity::L4: return Param::L4;
    case Quantity::D: return Param::D;
    case Quantity::M: return Param::M;
    case Quantity::m: return Param::m;
    case Quantity::mb: return Param::mb;
    default: return std::nullopt;
  }
}

LogLaw param_law(const TableBlock& block, const Segment& segment, Param param) {
  return {std::log(segment.a[index(param)] * block.Z0[index(param)]), segment.exponents.row(index(param))};
}

// Lb = L1 + L2 is the one given that is not log-linear.
std::optional<LogLaw> log_law(const ScalingTable& table, const TableBlock& block, const Segment& segment, Quantity quantity) {
  if (auto param = fitted_param(quantity)) return param_law(block, segment, *param);
  switch (quantity) {
    case Quantity::R: return LogLaw{std::log(table.R0), {1, 0}};
    case Quantity::T: return LogLaw{std::log(table.T0), {0, 1}};
    case Quantity::l: {
      const LogLaw L1 = param_law(block, segment, Param::L1);
      const LogLaw L2 = param_law(block, segment, Param::L2);
      return LogLaw{L1.c - L2.c, L1.pq - L2.pq};
    }
    default: return std::nullopt;
  }
}

// Factor from the table's material to the requested one at equal lengths (section 7).
double material_factor(Quantity quantity, const SizeFactors& factors) {
  switch (quantity_dimension(quantity)) {
    case Dimension::mass: return factors.mass;
    case Dimension::energy: return factors.energy;
    default: return quantity == Quantity::D ? factors.diameter : 1.0;
  }
}

constexpr double warn_amplification = 10, max_amplification = 50;

struct Inversion {
  const Segment* segment;
  double lr, lt;  // log(R/R0), log(T/T0)
  double amplification;
  double X() const { return capacity_coordinates(lr, lt).X; }
  bool inside() const { return X() >= segment->X_min - 1e-12 && X() <= segment->X_max + 1e-12; }
  double outside_by() const { return std::max({segment->X_min - X(), X() - segment->X_max, 0.0}); }
  double depth() const { return std::min(X() - segment->X_min, segment->X_max - X()); }
};

// eq:RT_ZiZj for two log-linear givens: the 2x2 matrix of their (p, q) rows.
Eigen::Matrix2d pair_matrix(const LogLaw& i, const LogLaw& j) {
  Eigen::Matrix2d A;
  A << i.pq, j.pq;
  return A;
}

// Largest relative change of R or T per relative change of the givens: the infinity norm of
// the inverse of eq:ZiZj_RT, (|q_i| + |q_j|, |p_i| + |p_j|)/|D_ij| row by row.
double amplification_of(const Eigen::Matrix2d& A) { return A.inverse().cwiseAbs().rowwise().sum().maxCoeff(); }

// eq:ZiZj_RT: (lr, lt) from two log-linear givens; nullopt when D_ij = 0.
std::optional<Inversion> invert_pair(const Segment& segment, const LogLaw& i, double log_i, const LogLaw& j, double log_j) {
  const Eigen::Matrix2d A = pair_matrix(i, j);
  if (std::abs(A.determinant()) < 1e-12) return std::nullopt;  // D_ij
  const Eigen::Vector2d capacity = A.inverse() * Eigen::Vector2d(log_i - i.c, log_j - j.c);
  return Inversion{&segment, capacity(0), capacity(1), amplification_of(A)};
}

// Lb = L1 + L2 together with a log-linear given A: on the line log A = const in the
// (lr, lt) plane, log Lb is the log of a sum of two exponentials of the line parameter s,
// hence convex in s, with at most two roots; each is bracketed and found by Brent's method.
struct BeamLengthLine {
  double lr0, lt0, dr, dt;  // point and unit direction of the line
  LogLaw L1, L2;
  double log_Lb;
  double lr(double s) const { return lr0 + s * dr; }
  double lt(double s) const { return lt0 + s * dt; }
  double log_of(const LogLaw& law, double s) const { return law.c + law.pq.dot(Eigen::Vector2d(lr(s), lt(s))); }
  double excess(double s) const {  // log Lb(s) - log Lb_given
    const double a1 = log_of(L1, s), a2 = log_of(L2, s);
    const double top = std::max(a1, a2);
    return top + std::log(std::exp(a1 - top) + std::exp(a2 - top)) - log_Lb;
  }
};

double brent_root(const BeamLengthLine& line, double lo, double hi) {
  return find_root([&line](double s) { return line.excess(s); }, lo, hi, 0, 1e-14);
}

// Solutions, and the span of Lb over the part of the line inside the segment (for messages).
struct BeamLengthSolutions {
  std::vector<Inversion> found;
  double Lb_min = 0, Lb_max = 0;  // [m]
};

BeamLengthSolutions invert_with_beam_length(const TableBlock& block, const Segment& segment, const LogLaw& A, double log_A, double log_Lb) {
  const double norm = A.pq.norm();
  const double b = (log_A - A.c) / norm;
  BeamLengthLine line{A.pq(0) / norm * b,
                      A.pq(1) / norm * b,
                      A.pq(1) / norm,
                      -A.pq(0) / norm,
                      param_law(block, segment, Param::L1),
                      param_law(block, segment, Param::L2),
                      log_Lb};
  // The part of the line inside the segment's X interval; X is constant along it when A
  // depends on X alone (the beam ratio l), and then the line is only bounded by sanity.
  const double dX = capacity_coordinates(line.dr, line.dt).X;  // X is linear in (lr, lt)
  const double X0 = capacity_coordinates(line.lr0, line.lt0).X;
  const double far = 50;  // |log(R/R0)|, |log(T/T0)| beyond any engine
  double lo = -far, hi = far;
  if (std::abs(dX) > 1e-12) {
    lo = (segment.X_min - X0) / dX;
    hi = (segment.X_max - X0) / dX;
    if (lo > hi) std::swap(lo, hi);
    // A line nearly along X = const (a given of X alone, as l) leaves the segment only beyond any engine.
    lo = std::max(lo, -far), hi = std::min(hi, far);
    if (lo > hi) return {};
  } else if (X0 < segment.X_min || X0 > segment.X_max) {
    return {};
  }
  BeamLengthSolutions solutions;
  // Minimum of the convex excess: where the two exponentials' slopes cancel, or an end.
  const Eigen::Vector2d direction(line.dr, line.dt);
  const double beta1 = line.L1.pq.dot(direction), beta2 = line.L2.pq.dot(direction);
  double s_min = beta1 >= 0 && beta2 >= 0 ? lo : hi;
  if (beta1 * beta2 < 0) {
    const double alpha1 = line.log_of(line.L1, 0), alpha2 = line.log_of(line.L2, 0);
    s_min = std::clamp((std::log(-beta2 / beta1) - alpha1 + alpha2) / (beta1 - beta2), lo, hi);
  }
  auto add = [&](double s) {
    // Local slopes of log Lb give the conditioning of the pair (A, Lb).
    const double w1 = std::exp(line.log_of(line.L1, s)), w2 = std::exp(line.log_of(line.L2, s));
    const LogLaw Lb{0, (w1 * line.L1.pq + w2 * line.L2.pq) / (w1 + w2)};
    solutions.found.push_back({&segment, line.lr(s), line.lt(s), amplification_of(pair_matrix(A, Lb))});
  };
  const double f_min = line.excess(s_min);
  const double given_Lb = std::exp(log_Lb);
  solutions.Lb_min = given_Lb * std::exp(f_min);
  solutions.Lb_max = given_Lb * std::exp(std::max(line.excess(lo), line.excess(hi)));
  if (f_min > 0) return solutions;
  if (f_min == 0) {
    add(s_min);
    return solutions;
  }
  if (s_min > lo && line.excess(lo) >= 0) add(brent_root(line, lo, s_min));
  if (s_min < hi && line.excess(hi) >= 0) add(brent_root(line, s_min, hi));
  return solutions;
}

bool first_is_beam_length(const Given& first, const Given&) { return first.quantity == Quantity::Lb; }

// For a request with R and a log-linear other given, the ranges of R the block covers with that
// other given held, [R_lo, R_hi] in m: in each segment, eq:RT_ZiZj with X at the segment's ends
// (X = (5 lr - lt)/sqrt(26), eq:XY_RT) fixes lr. Empty when the pair has no R.
std::optional<std::pair<double, double>> R_range_for(const ScalingTable& table, const TableBlock& block, const Given& gi, const Given& gj,
                                                     const SizeFactors& scaling) {
  const Given& other = gi.quantity == Quantity::R ? gj : gi;
  if ((gi.quantity == Quantity::R) == (gj.quantity == Quantity::R)) return std::nullopt;
  // X is log-linear in the capacity too (eq:XY_RT): with the other given, eq:ZiZj_RT fixes lr.
  const LogLaw X_law{0, {capacity_coordinates(1, 0).X, capacity_coordinates(0, 1).X}};
  const double log_other = std::log(other.value / material_factor(other.quantity, scaling));
  double lo = HUGE_VAL, hi = 0;
  for (const Segment& segment : block.segments) {
    const auto law = log_law(table, block, segment, other.quantity);
    if (!law) return std::nullopt;
    for (double X : {segment.X_min, segment.X_max})
      if (const auto at_end = invert_pair(segment, *law, log_other, X_law, X)) {
        const double R = table.R0 * std::exp(at_end->lr);
        lo = std::min(lo, R), hi = std::max(hi, R);
      }
  }
  if (!(hi > 0) || !std::isfinite(lo) || !std::isfinite(hi)) return std::nullopt;
  return std::pair{lo, hi};
}

// For a request with the beam ratio l: the span of l over the block. l = L1/L2 depends on X
// (eq:Xi) and hardly on the size Y, so l alone fixes X and no other given can move it; each
// segment's l is taken at its ends on the X axis (Y = 0, eq:XY_RT), and the span is reported to
// 3 digits, far coarser than its change with Y.
std::optional<std::pair<double, double>> l_range_for(const ScalingTable& table, const TableBlock& block) {
  double lo = HUGE_VAL, hi = 0;
  for (const Segment& segment : block.segments) {
    const LogLaw law = *log_law(table, block, segment, Quantity::l);
    for (double X : {segment.X_min, segment.X_max}) {
      const Capacity at = capacity_at({X, 0}, 1, 1);
      const double l = std::exp(law.c + law.pq.dot(Eigen::Vector2d(std::log(at.R), std::log(at.T))));
      lo = std::min(lo, l), hi = std::max(hi, l);
    }
  }
  if (!(hi > 0) || !std::isfinite(lo) || !std::isfinite(hi)) return std::nullopt;
  return std::pair{lo, hi};
}

// Two segments that meet at a seam X_s agree there only to the rounding of their constants, so
// a pair of givens near X_s can solve to just past the seam in both: the left segment's X above
// X_s and the right one's below it. Such a gap is covered: the candidate nearer its own segment
// is taken (docs/calculator.md, "Seams"). Segments of two different branches do not form a
// seam; an unlabeled segment continues whichever branch meets it.
// Only a gap that rounding can open is covered: the constants are printed to 3 significant
// digits, so two segments' laws may disagree at the seam by up to half a unit of the third, 5e-3
// in ln Z, which the pair's amplification carries into ln R and ln T, and X (eq:XY_RT, of norm
// 1) by no more. A pair whose two solutions lie further past the seam than that (an
// ill-conditioned pair such as L1 and M can put them at X = +0.4 and -1.4) has no design there.
bool same_family(Branch a, Branch b) { return a == b || a == Branch::none || b == Branch::none; }

constexpr double printed_rounding = 5e-3;  // half a unit of the constants' third significant digit, in ln Z

std::optional<Inversion> seam_candidate(const std::vector<Inversion>& candidates) {
  std::optional<Inversion> best;
  for (const Inversion& left : candidates)
    for (const Inversion& right : candidates) {
      const Segment &a = *left.segment, &b = *right.segment;
      if (&a == &b || a.X_max != b.X_min || !same_family(a.branch, b.branch)) continue;
      if (!(left.X() > a.X_max && right.X() < b.X_min)) continue;
      if (left.outside_by() > printed_rounding * left.amplification || right.outside_by() > printed_rounding * right.amplification) continue;
      const Inversion& nearer = left.outside_by() <= right.outside_by() ? left : right;
      if (!best || nearer.outside_by() < best->outside_by()) best = nearer;
    }
  return best;
}

// Every number of a design is finite, and lengths and masses are positive: extreme givens, a
// material far from wood or a huge scale factor can push one out of the range of doubles, and
// that is the input's fault, named with `cause`.
// `cause` gives the start of the message, built only when one is thrown (the calculator's hot path).
void require_representable(const OptimalEngine& d, const std::function<std::string()>& cause) {
  const Engine& e = d.engine;
  const std::pair<const char*, double> positive[] = {{"R", d.capacity.R},
                                                     {"T", d.capacity.T},
                                                     {"L1", e.L1},
                                                     {"L2", e.L2},
                                                     {"L3", e.L3},
                                                     {"L4", e.L4},
                                                     {"D", e.D},
                                                     {"M", e.M},
                                                     {"m", e.m},
                                                     {"mb", e.mb},
                                                     {"Delta U", potential_energy_drop(e)}};
  auto fail = [&](const char* name, const char* how) {
    throw Error(
        ErrorKind::bad_number,
        cause() + " gives an engine whose " + name + " is " + how + " for a number (beyond about 1e-308 to 1e308); give values of ordinary size");
  };
  for (const auto& [name, value] : positive) {
    if (!std::isfinite(value)) fail(name, "too large");
    const bool at_arm_end = e.machine != MachineKind::hinged && std::string_view(name) == "L3" && value == 0;  // the other machines' counterweight
    if (!(value > std::numeric_limits<double>::min()) && !at_arm_end) fail(name, "too small");
  }
  if (!std::isfinite(d.coordinates.X) || !std::isfinite(d.coordinates.Y)) fail("capacity (X, Y)", "too far from R0, T0");
}

std::string describe_given(const Given& given) {
  const Dimension dimension = quantity_dimension(given.quantity);
  const char* unit = dimension == Dimension::length ? " m" : dimension == Dimension::mass ? " kg" : dimension == Dimension::energy ? " J" : "";
  return std::string(quantity_name(given.quantity)) + " = " + format_significant(given.value, 6) + unit;
}

// The table in messages: tab:CPNC, or another machine's.
std::string table_words(const ScalingTable& table) {
  return table.machine == MachineKind::hinged
      ? "tab:CPNC"
      : "the " + std::string(table.machine == MachineKind::fixed ? "fixed" : "floating-arm") + " machine's table";
}

std::string describe_interval(double lo, double hi) { return "[" + format_number(lo) + ", " + format_number(hi) + "]"; }

std::string describe_block(const TableBlock& block) {
  return "theta_i = " + format_number(block.theta_i_deg) + " deg" +
      (block.F > 0 ? ", F = " + format_fraction(block.F) : std::string(", the counterweight at the short arm's end"));  // another machine's: F = 0
}

bool branch_allowed(const Inversion& candidate, BranchChoice choice) {
  const Branch branch = candidate.segment->branch;
  if (branch == Branch::none || choice == BranchChoice::automatic) return true;
  return (choice == BranchChoice::lower) == (branch == Branch::lower);
}

// Picks one candidate; fills warnings about branches and ambiguities.
Inversion choose(const std::vector<Inversion>& inside, const TableBlock& block, BranchChoice choice, std::vector<std::string>& warnings) {
  std::vector<Inversion> allowed;
  for (const Inversion& c : inside)
    if (branch_allowed(c, choice)) allowed.push_back(c);
  if (allowed.empty()) {
    // Only possible when the forced branch does not reach this X.
    const Inversion& other = inside.front();
    throw Error(ErrorKind::out_of_range,
                "the " + std::string(choice == BranchChoice::lower ? "lower" : "upper") +
                    " branch has no optimum for these givens (the solution lies at X = " + format_significant(other.X(), 3) + " on the " +
                    std::string(branch_name(other.segment->branch)) + " branch); use {{branch}} auto or {{branch}} " +
                    std::string(branch_name(other.segment->branch)));
  }
  if (choice != BranchChoice::automatic && allowed.front().segment->branch == Branch::none)
    warnings.push_back("{{branch}} " + std::string(choice == BranchChoice::lower ? "lower" : "upper") +
                       " ignored: only one optimal branch exists at X = " + format_significant(allowed.front().X(), 3));

  // In the overlap, auto takes the branch with the higher Q: lower below X_d, upper above (section 6.2).
  const double X_d = block.branch_switch_X.value_or(std::numeric_limits<double>::quiet_NaN());
  auto preferred = [&](const Inversion& c) {
    if (c.segment->branch == Branch::lower) return c.X() < X_d;
    if (c.segment->branch == Branch::upper) return c.X() >= X_d;
    return true;
  };
  std::vector<Inversion> best;
  for (const Inversion& c : allowed)
    if (choice != BranchChoice::automatic || preferred(c)) best.push_back(c);
  if (best.empty()) best = allowed;  // each branch prefers the other: take the one deepest inside
  std::stable_sort(best.begin(), best.end(), [](const Inversion& a, const Inversion& b) { return a.depth() > b.depth(); });

  // Two different capacities can match one pair of givens (Lb with another given, or two
  // branches each consistent at its own X): say so rather than hide the second.
  for (std::size_t k = 1; k < best.size(); ++k) {
    const Inversion& c = best[k];
    if (std::abs(c.X() - best.front().X()) < 1e-6 && std::abs(c.lt - best.front().lt) < 1e-6) continue;
    warnings.push_back("another optimal engine also matches these givens: X = " + format_significant(c.X(), 3) +
                       (c.segment->branch == Branch::none ? "" : " on the " + std::string(branch_name(c.segment->branch)) + " branch") +
                       "; it is not shown (use {{branch}} or other givens to select it)");
  }
  return best.front();
}

// Sets a given quantity to the value given; the inversion reproduces it only to rounding.
void copy_given(const Given& given, OptimalEngine& design) {
  Engine& e = design.engine;
  switch (given.quantity) {
    case Quantity::R: design.capacity.R = given.value; break;
    case Quantity::T: design.capacity.T = given.value; break;
    case Quantity::L1: e.L1 = given.value; break;
    case Quantity::L2: e.L2 = given.value; break;
    case Quantity::L4: e.L4 = given.value; break;
    case Quantity::D: e.D = given.value; break;
    case Quantity::M: e.M = given.value; break;
    case Quantity::m: e.m = given.value; break;
    case Quantity::mb: e.mb = given.value; break;
    case Quantity::Lb:
    case Quantity::l: break;  // not stored; L1 and L2 reproduce them to rounding
  }
}

}  // namespace

double quantity_value(const OptimalEngine& d, Quantity quantity) {
  const Engine& e = d.engine;
  switch (quantity) {
    case Quantity::R: return d.capacity.R;
    case Quantity::T: return d.capacity.T;
    case Quantity::L1: return e.L1;
    case Quantity::L2: return e.L2;
    case Quantity::L4: return e.L4;
    case Quantity::D: return e.D;
    case Quantity::M: return e.M;
    case Quantity::m: return e.m;
    case Quantity::mb: return e.mb;
    case Quantity::Lb: return beam_length(e);
    case Quantity::l: return e.L1 / e.L2;
  }
  return 0;
}

std::optional<std::array<double, param_count>> branch_steps(const TableBlock& block) {
  if (!block.branch_switch_X) return std::nullopt;
  const Segment* lower = nullptr;
  const Segment* upper = nullptr;
  for (const Segment& s : block.segments) {
    if (s.branch == Branch::lower) lower = &s;
    if (s.branch == Branch::upper) upper = &s;
  }
  if (!lower || !upper) return std::nullopt;
  // eq:ZiZj_vs_X: on the X axis (Y = 0) log(R/R0) = 5 X/sqrt26 and log(T/T0) = -X/sqrt26.
  const Capacity at_switch = capacity_at({*block.branch_switch_X, 0}, 1, 1);
  const Eigen::Vector2d log_capacity(std::log(at_switch.R), std::log(at_switch.T));
  const ParamVector steps = upper->a.cwiseQuotient(lower->a).cwiseProduct(
      ((upper->exponents - lower->exponents) * log_capacity).array().exp().matrix());
  std::array<double, param_count> out{};
  for (Param param : all_params) out[index(param)] = steps[index(param)];
  return out;
}

namespace {

// Both givens differ, each positive and finite.
void check_givens(const Given& gi, const Given& gj) {
  if (gi.quantity == gj.quantity)
    throw Error(ErrorKind::given_count,
                "both givens are " + std::string(quantity_name(gi.quantity)) + "; give two different quantities, e.g. {{R}} 150m {{m}} 50kg");
  for (const Given& g : {gi, gj})
    if (!(g.value > 0) || !std::isfinite(g.value)) throw Error(ErrorKind::bad_number, describe_given(g) + " must be a positive finite number");
}

// How the material scales the table's masses, energies and diameters, within the range of numbers.
SizeFactors checked_size_factors(const ScalingTable& table, const Material& m) {
  const SizeFactors scaling = size_factors(1, table.reference, 1, m);
  if (!(std::isfinite(scaling.mass) && std::isfinite(scaling.energy) && std::isfinite(scaling.diameter) && scaling.mass > 0 && scaling.diameter > 0 &&
        scaling.energy > 0 && scaling.mass < 1e300 && scaling.mass > 1e-300))
    throw Error(ErrorKind::bad_number,
                "the material (beta2 = " + format_significant(m.beta2, 3) + ", Young's modulus " + format_significant(m.youngs_modulus, 3) +
                    " Pa, wood density " + format_significant(m.wood_density, 3) + " kg/m^3, g = " + format_significant(m.g, 3) +
                    " m/s^2) scales the masses by " +
                    "a factor beyond the range of numbers; give values of ordinary size, e.g. the paper's 1/300, 12GPa, 700kg/m3, 9.81");
  return scaling;
}

// The solutions of the pair in every segment of the block, and, where Lb is given, the Lb that
// optimal engines reach per segment (for the message when none holds).
struct Solutions {
  std::vector<Inversion> candidates;
  std::string beam_length_spans;
};

Solutions solve_pair(const ScalingTable& table, const TableBlock& block, const Given& gi, double log_i, const Given& gj, double log_j) {
  Solutions out;
  std::vector<Inversion>& candidates = out.candidates;
  std::string& beam_length_spans = out.beam_length_spans;
  for (const Segment& segment : block.segments) {
    auto law_i = log_law(table, block, segment, gi.quantity);
    auto law_j = log_law(table, block, segment, gj.quantity);
    if (law_i && law_j) {
      if (auto c = invert_pair(segment, *law_i, log_i, *law_j, log_j)) candidates.push_back(*c);
    } else {
      const bool first_is_Lb = !law_i;
      const BeamLengthSolutions solved = invert_with_beam_length(block, segment, first_is_Lb ? *law_j : *law_i, first_is_Lb ? log_j : log_i,
                                                                 first_is_Lb ? log_i : log_j);
      candidates.insert(candidates.end(), solved.found.begin(), solved.found.end());
      // A span beyond the range of numbers (an extreme l) says nothing; the message then names the inversion.
      if (solved.Lb_max > 0 && std::isfinite(solved.Lb_min) && std::isfinite(solved.Lb_max))
        beam_length_spans += std::string(beam_length_spans.empty() ? "" : ", ") + format_significant(solved.Lb_min, 3) + " to " +
            format_significant(solved.Lb_max, 3) + " m in segment " + describe_interval(segment.X_min, segment.X_max);
    }
  }
  return out;
}

// No segment holds the pair (and no extrapolation is asked for, or none solves it): the refusal
// says where the pair lies, and in the user's terms what would bring it in.
[[noreturn]] void refuse_uncovered(const ScalingTable& table, const TableBlock& block, const DesignRequest& request, const Solutions& solutions,
                                   const SizeFactors& scaling) {
  const Given& gi = request.first;
  const Given& gj = request.second;
  const std::vector<Inversion>& candidates = solutions.candidates;
  const std::string& beam_length_spans = solutions.beam_length_spans;
  auto pair = [&] { return describe_given(gi) + ", " + describe_given(gj); };
  auto covered = [&] { return describe_interval(block.X_covered_min(), block.X_covered_max()); };
  std::string tried;
  for (const Inversion& c : candidates)
    tried += (tried.empty() ? "" : ", ") + std::string("X = ") + format_significant(c.X(), 3) + " in segment " +
        describe_interval(c.segment->X_min, c.segment->X_max);
  const bool both_capacity = (gi.quantity == Quantity::R || gi.quantity == Quantity::T) && (gj.quantity == Quantity::R || gj.quantity == Quantity::T);
  std::string message = both_capacity
      ? "capacity " + pair() + " has X = " + format_significant(candidates.front().X(), 3) + ", outside the interval " + covered() + " covered by " +
          table_words(table) + " for " + describe_block(block) + "; raise T or lower R to lower X (X = (5 ln(R/R0) - ln(T/T0))/sqrt(26))"
      : "no meaningful capacity for the pair " + pair() + " at " + describe_block(block) + ": " +
          (!beam_length_spans.empty() && candidates.empty()
               ? "optimal engines with " + describe_given(first_is_beam_length(gi, gj) ? gj : gi) + " have Lb from " + beam_length_spans
               : (tried.empty() ? std::string("no segment gives a solution") : "the inversion gives " + tried) + ", outside the covered interval " +
                   covered());
  const bool l_given = gi.quantity == Quantity::l || gj.quantity == Quantity::l;
  const auto l_range = l_given ? l_range_for(table, block) : std::nullopt;
  const double l_value = gi.quantity == Quantity::l ? gi.value : gj.value;
  // In the user's terms: the ranges that work with the other given held.
  if (l_range && (l_value < l_range->first || l_value > l_range->second)) {
    // l fixes X whatever the size: no other given can bring it in; another block may.
    message = "no optimal engine at " + describe_block(block) + " has " + describe_given(gi.quantity == Quantity::l ? gi : gj) +
        ": there l = L1/L2 runs from " + format_significant(l_range->first, 3) + " to " + format_significant(l_range->second, 3) +
        " whatever the engine's size; give l in that span";
    for (const TableBlock& other : table.blocks)
      if (&other != &block)
        if (const auto span = l_range_for(table, other); span && l_value >= span->first && l_value <= span->second)
          message += ", or the block " + describe_block(other) + " (l from " + format_significant(span->first, 3) + " to " +
              format_significant(span->second, 3) + ")";
  } else if (const auto range = R_range_for(table, block, gi, gj, scaling)) {
    const Given& other = gi.quantity == Quantity::R ? gj : gi;
    message += "; with " + describe_given(other) + " the table covers R from " + format_significant(range->first, 3) + " m to " +
        format_significant(range->second, 3) + " m: change {{R}} to lie there, or change {{" + std::string(quantity_name(other.quantity)) + "}}";
  } else if (!both_capacity) {
    message += "; give another pair";
  }
  // A model of a full-size engine lies at the full-size engine's X: design that and scale it.
  const bool short_range = (gi.quantity == Quantity::R && gi.value < 0.25 * table.R0) || (gj.quantity == Quantity::R && gj.value < 0.25 * table.R0);
  if (short_range)
    message +=
        "; for a small model of a full-size engine, design the full-size one and scale it, e.g. "
        "{{R}} 425m {{T}} 224kJ {{scale}} 80/425 (tab:Denny's 80 m model)";
  message += request.extrapolate ? "; even {{extrapolate}} finds no segment that solves the pair"
                                 : "; or add {{extrapolate}} to use the nearest segment beyond its interval";
  throw Error(ErrorKind::out_of_range, message);
}

// Where a lower and an upper branch compete at the engine's X: a warning with the jump of each
// parameter at the switch (eq:ZiZj_vs_X), and the steps themselves.
void warn_branches(const TableBlock& block, const Segment& segment, OptimalEngine& result) {
  double overlap_lo = -std::numeric_limits<double>::infinity(), overlap_hi = -overlap_lo;
  for (const Segment& s : block.segments)
    if (s.branch != Branch::none) {
      overlap_lo = std::max(overlap_lo, s.X_min);
      overlap_hi = std::min(overlap_hi, s.X_max);
    }
  if (result.coordinates.X >= overlap_lo && result.coordinates.X <= overlap_hi) {
    result.branch_steps = branch_steps(block);
    if (result.branch_steps) {
      std::string steps;
      for (Param param : all_params) {
        const double percent = 100 * ((*result.branch_steps)[index(param)] - 1);
        steps += (steps.empty() ? "" : ", ") + std::string("S_") + std::string(param_name(param)) + " = " + (percent >= 0 ? "+" : "") +
            format_significant(percent, 2) + "%";
      }
      result.warnings.push_back("X = " + format_significant(result.coordinates.X, 3) + " lies where a lower and an upper branch compete " +
                                describe_interval(overlap_lo, overlap_hi) + "; this is the " + std::string(branch_name(segment.branch)) +
                                " branch. At X_d = " + format_number(*block.branch_switch_X) + " the optimum jumps by " + steps +
                                " (eq:ZiZj_vs_X); {{branch}} lower|upper selects one");
    }
  }
}

}  // namespace

OptimalEngine design_optimal_engine(const ScalingTable& table, const DesignRequest& request) {
  const Given& gi = request.first;
  const Given& gj = request.second;
  check_givens(gi, gj);

  const TableBlock* block = &table.block(request.theta_i_deg, request.F);

  const SizeFactors scaling = checked_size_factors(table, request.material);
  const double log_i = std::log(gi.value / material_factor(gi.quantity, scaling));
  const double log_j = std::log(gj.value / material_factor(gj.quantity, scaling));

  const Solutions solutions = solve_pair(table, *block, gi, log_i, gj, log_j);
  const std::vector<Inversion>& candidates = solutions.candidates;
  std::vector<Inversion> inside;
  for (const Inversion& c : candidates)
    if (c.inside()) inside.push_back(c);
  if (inside.empty())
    if (auto seam = seam_candidate(candidates)) inside.push_back(*seam);

  OptimalEngine result;
  // Message parts, formatted only when a message needs them.
  auto pair = [&] { return describe_given(gi) + ", " + describe_given(gj); };
  auto covered = [&] { return describe_interval(block->X_covered_min(), block->X_covered_max()); };
  Inversion chosen{};
  if (!inside.empty()) {
    chosen = choose(inside, *block, request.branch, result.warnings);
  } else {
    if (candidates.empty() || !request.extrapolate) refuse_uncovered(table, *block, request, solutions, scaling);
    std::vector<Inversion> allowed;
    for (const Inversion& c : candidates)
      if (branch_allowed(c, request.branch)) allowed.push_back(c);
    if (allowed.empty()) allowed = candidates;
    chosen = *std::min_element(allowed.begin(), allowed.end(),
                               [](const Inversion& a, const Inversion& b) { return a.outside_by() < b.outside_by(); });
    result.warnings.push_back("extrapolated: X = " + format_significant(chosen.X(), 3) + " lies outside the interval " + covered() + " covered by " +
                              table_words(table) + "; constants of segment " + describe_interval(chosen.segment->X_min, chosen.segment->X_max) +
                              " used beyond it");
  }

  const Segment& segment = *chosen.segment;
  // eq:RT_Z1Z2: the seven logarithms at once, then eq:ZRT.
  const ParamVector Z = segment.a.cwiseProduct(block->Z0).cwiseProduct(
      (segment.exponents * Eigen::Vector2d(chosen.lr, chosen.lt)).array().exp().matrix());
  Engine& e = result.engine;
  e.L1 = Z[index(Param::L1)];
  e.L2 = Z[index(Param::L2)];
  e.L4 = Z[index(Param::L4)];
  e.D = Z[index(Param::D)] * scaling.diameter;
  e.M = Z[index(Param::M)] * scaling.mass;
  e.m = Z[index(Param::m)] * scaling.mass;
  e.mb = Z[index(Param::mb)] * scaling.mass;
  e.theta_i_deg = request.theta_i_deg;
  e.material = request.material;
  result.capacity.R = table.R0 * std::exp(chosen.lr);
  result.capacity.T = table.T0 * std::exp(chosen.lt) * scaling.energy;
  for (const Given& given : {gi, gj}) copy_given(given, result);  // exact, not a round trip through logarithms
  e.machine = table.machine;
  e.L3 = table.machine == MachineKind::hinged ? counterweight_arm(e.L1, e.L2, e.theta_i_deg, request.F) : 0;  // the others' at the arm's end
  if (table.machine == MachineKind::hinged && !(e.L3 > 0))
    throw Error(ErrorKind::out_of_range,
                "the design for " + pair() + " has no room for the counterweight arm (L3 = " + format_significant(e.L3, 3) +
                    " m); stay inside the covered interval " + covered());
  result.coordinates = capacity_coordinates(chosen.lr, chosen.lt);
  result.branch = segment.branch;
  result.segment_X_min = segment.X_min;
  result.segment_X_max = segment.X_max;
  result.F = table.machine == MachineKind::hinged ? request.F : arm_fraction(e);
  result.amplification = chosen.amplification;
  // The constants of tab:CPNC reproduce the ab-initio optimum to about 1 % (docs/verifier.md);
  // the inversion multiplies that, and any error of the givens, by the amplification. Above
  // 50 the capacity is uncertain by more than half and the pair is refused; above 10, warned.
  // The message is built only when it is printed: this is the calculator's hot path.
  auto conditioning = [&] {
    return "a 1 % change of " + pair() + " moves R or T by up to " + format_significant(chosen.amplification, 2) + " % (amplification, eq:ZiZj_RT)";
  };
  if (chosen.amplification > max_amplification)
    throw Error(ErrorKind::given_count,
                "the pair " + pair() + " barely fixes the capacity: " + conditioning() + ", above the limit of " +
                    format_significant(max_amplification, 2) + "; give a better-conditioned pair such as R and m, or M and m");
  if (chosen.amplification > warn_amplification) result.warnings.push_back("ill-conditioned pair: " + conditioning());
  require_representable(result, [&] { return "the request " + pair(); });

  if (segment.branch != Branch::none) warn_branches(*block, segment, result);
  return request.scale == 1 ? result : scale_optimal_engine(result, request.scale);
}

OptimalEngine scale_optimal_engine(const OptimalEngine& design, double lambda) {
  const Material& material = design.engine.material;
  const SizeFactors factors = size_factors(design.engine.L2, material, lambda * design.engine.L2, material);  // eq:ExtraScalings
  OptimalEngine scaled = design;
  scaled.scaled_from = OptimalEngine::Scaling{lambda * (design.scaled_from ? design.scaled_from->factor : 1),
                                              design.scaled_from ? design.scaled_from->full_size : design.capacity};
  scaled.engine = resized(design.engine, factors);
  scaled.capacity.R *= factors.length;
  scaled.capacity.T *= factors.energy;
  // The capacity moves along a line of constant X (section 6.1): X stays, Y grows.
  const CapacityCoordinates shift = capacity_coordinates(std::log(factors.length), std::log(factors.energy));
  scaled.coordinates.Y += shift.Y;
  require_representable(scaled, [&] { return "scaling by " + format_significant(lambda, 3); });
  return scaled;
}

}  // namespace trebuchet
