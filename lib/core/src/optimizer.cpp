#include "trebuchet/optimizer.hpp"

#include <gsl/gsl_errno.h>

#include <cmath>
#include <memory>

#include "gsl_errors.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/error.hpp"
#include "simplex.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/machine.hpp"
#include "trebuchet/angles.hpp"

namespace trebuchet {
namespace {

struct Start {
  std::string name;
  ScaledDesign shape;
};

// The lightest beam of a fixed-l search's grid, mu_b = mb/M.
constexpr double least_searched_mu_b = 1e-6;

// The shape built as the request's machine: the paper's holds F; the fixed counterweight and the
// floating arm hold their counterweight at the short arm's end (L3 = 0: F = 1/(l cos theta_i)),
// where a builder puts it and where F, which would move it along the arm, means nothing.
void build_as_requested(ScaledDesign& shape, const OptimizeRequest& r) {
  shape.machine = r.machine;
  if (r.machine != MachineKind::hinged) shape.F = 1 / (shape.l * std::cos(radians(shape.theta_i_deg)));
}

// The calculator's optimum for the capacity on each branch it has, as starting shapes.
std::vector<Start> starts_for(const OptimizeRequest& r) {
  std::vector<Start> starts;
  if (r.fixed_l) {
    // Appendix B: at a fixed l the efficiency has one maximum with l4 < 1 and one with l4 > 1;
    // each search keeps to its side, from the best point of a grid there (search_from).
    starts.push_back({"smaller-l4 branch", {*r.fixed_l, 0.85, 1e-3, 0, r.theta_i_deg, r.F}});
    starts.push_back({"larger-l4 branch", {*r.fixed_l, 1.2, 1e-3, 0, r.theta_i_deg, r.F}});
    for (Start& s : starts) build_as_requested(s.shape, r);
    return starts;
  }
  for (ScaledDesign shape : r.starts) {
    shape.theta_i_deg = r.theta_i_deg, shape.F = r.F;
    starts.push_back({"given shape " + std::to_string(starts.size() + 1), shape});
  }
  if (!starts.empty()) return starts;
  for (BranchChoice branch : {BranchChoice::lower, BranchChoice::upper, BranchChoice::automatic}) {
    DesignRequest d;
    d.first = {Quantity::R, r.capacity.R};
    d.second = r.projectile_mass ? Given{Quantity::m, *r.projectile_mass} : Given{Quantity::T, r.capacity.T};
    d.theta_i_deg = r.theta_i_deg;
    d.F = r.F;
    d.branch = branch;
    d.extrapolate = true;
    try {
      const OptimalEngine design = design_optimal_engine(builtin_scaling_table(), d);
      const std::string name = branch == BranchChoice::automatic ? "calculator"
          : branch == BranchChoice::lower                        ? "calculator, lower branch"
                                                                 : "calculator, upper branch";
      const ScaledDesign shape = scaled_design(design.engine);
      bool seen = false;
      for (const Start& s : starts) seen = seen || (std::abs(s.shape.l / shape.l - 1) < 1e-9 && std::abs(s.shape.l4 / shape.l4 - 1) < 1e-9);
      if (!seen) starts.push_back({name, shape});
    } catch (const Error&) {
      // no block or branch here: the other starts, or the generic one, remain
    }
    if (branch == BranchChoice::upper && starts.size() == 2) break;  // both branches found
  }
  if (starts.empty()) starts.push_back({"generic shape", {5.5, 0.9, 0.045, 0, r.theta_i_deg, r.F}});
  // A shape has a counterweight arm only for l > 1/(F cos theta_i) (L > 0, eq:Design): a start
  // without one is moved to half as long again.
  const double l_min = 1 / (r.F * std::cos(radians(r.theta_i_deg)));
  for (Start& s : starts) {
    s.shape.theta_i_deg = r.theta_i_deg, s.shape.F = r.F;
    if (!(s.shape.L() > 0)) s.shape.l = 1.5 * l_min;
    build_as_requested(s.shape, r);
  }
  return starts;
}

struct OptimumSearch {
  const OptimizeRequest* request = nullptr;
  int simulations = 0;
  double best = -1;
  CapacityFit best_fit;
  bool branch_below_one = true;  // with a fixed l: the side of l4 = 1 this search keeps to
  std::string last_failure;  // why the last shape that could not deliver the capacity failed
  bool only_integration_failed = true;  // every shape tried failed in its integration

  // Minus the quality of the shape at log coordinates x, its mu fitted to the capacity; a
  // shape that cannot deliver it, or fails, scores 0.
  double cost(const std::vector<double>& x, double theta, double F, bool warm = true) {
    // mu starts from the best fit so far: the simplex moves in small steps, so its mu is close.
    // A grid's far points start cold, as the fit would on its own.
    const double warm_mu = warm && best > 0 ? best_fit.design.mu : 0;
    // With a fixed l the simplex moves in (log l4, log mu_b) alone.
    const std::size_t at = request->fixed_l ? 0 : 1;
    const double l = request->fixed_l ? *request->fixed_l : std::exp(x[0]);
    ScaledDesign shape{l, std::exp(x[at]), std::exp(x[at + 1]), warm_mu, theta, F};
    build_as_requested(shape, *request);
    // Each branch keeps its side of l4 = 1 (appendix B): a step across it scores nothing.
    if (request->fixed_l && (shape.l4 < 1) != (branch_below_one)) return 0;
    try {
      const CapacityFit fit = request->projectile_mass
          ? fit_range_and_mass(shape, request->capacity.R, *request->projectile_mass, request->material, request->settings)
          : fit_capacity(shape, request->capacity, request->material, request->settings);
      simulations += fit.simulations;
      // The model must hold up to the release (no warning: the sling pulls, the counterweight
      // and the tip stay above the base); an optimum outside it is no engine.
      if (!fit.verification.warnings.empty()) throw Error(ErrorKind::out_of_range, fit.verification.warnings.front());
      const double q = objective_of(fit.verification);
      if (q > best) best = q, best_fit = fit;
      return -q;
    } catch (const Error& e) {
      simulations += 1;
      last_failure = e.named_message();
      only_integration_failed = only_integration_failed && integration_failed(e);
      return 0;
    }
  }

  double objective_of(const Verification& v) const { return request->settings.criterion.release == Release::efficiency ? v.eps : v.Q; }
};

Optimum search_from(const OptimizeRequest& request, const Start& start) {
  OptimumSearch search;
  search.request = &request;
  const ScaledDesign fixed = start.shape;
  Optimum out;
  out.start = start.name;
  out.start_design = start.shape;
  // 5 % steps in each shape parameter, in (log l, log l4, log mu_b).
  search.branch_below_one = start.shape.l4 < 1;
  std::vector<double> x{std::log(start.shape.l4), std::log(start.shape.mu_b)};
  if (!request.fixed_l) x.insert(x.begin(), std::log(start.shape.l));
  if (request.fixed_l) {
    // With a fixed l, in (log l4, log mu_b). The maxima's beams span decades (tab:Large_Eff:
    // mu_b = 5.4e-5 at l = 17, 0.01 at l = 59) and sit on narrow ridges, between shapes that
    // cannot deliver the capacity at all (the release jumps from one maximum to another as
    // mu changes). A grid over the branch's side finds the ridge to climb: l4 from 0.70 to 0.95
    // or 1.05 to 1.40, mu_b from 1e-6 to 0.1 in quarter decades.
    std::vector<double> best_point = x;
    double best_cost = 0;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j <= 20; ++j) {
        const std::vector<double> point{std::log(search.branch_below_one ? 0.70 + 0.05 * i : 1.05 + 0.07 * i),
                                        std::log(least_searched_mu_b) + j * std::log(10) / 4};
        const double c = search.cost(point, fixed.theta_i_deg, fixed.F, false);
        if (c < best_cost) best_cost = c, best_point = point;
      }
    x = best_point;
    out.start_design.l4 = std::exp(x[0]), out.start_design.mu_b = std::exp(x[1]);
  }
  out.iterations = minimize_simplex([&](const std::vector<double>& point) { return search.cost(point, fixed.theta_i_deg, fixed.F); }, x, 0.05,
                                    request.shape_tolerance, 400);
  // A search in which every shape failed in its integration is a numerical failure, named by the last.
  if (!(search.best > 0))
    throw Error(search.only_integration_failed ? ErrorKind::numerical : ErrorKind::out_of_range,
                "no shape near the " + start.name + " start delivers " + format_significant(request.capacity.R, 4) + " m with " +
                    (request.projectile_mass ? format_significant(*request.projectile_mass, 4) + " kg stones"
                                             : format_significant(request.capacity.T / 1e3, 4) + " kJ") +
                    " (the last shape tried: " + search.last_failure + "); try another capacity, theta_i or F");
  out.fit = search.best_fit;
  out.objective = search.best;
  out.simulations = search.simulations;
  if (request.fixed_l) {
    const ScaledDesign& found = out.fit.design;
    if (std::abs(found.l4 - 1) < 0.01)
      out.note =
          "the best shape on this side lies at its edge, l4 = 1: the objective grows toward the other side, and this side has no maximum of its own";
    else if (found.mu_b < 2 * least_searched_mu_b)
      out.note = "the best shape lies at the lightest beam searched, mu_b = " + format_significant(found.mu_b, 2) +
          ": the objective still grows toward a beam of no mass";
  }
  return out;
}

}  // namespace

std::vector<Optimum> optimize(const OptimizeRequest& request) {
  if (request.machine == MachineKind::whipper) throw Error(ErrorKind::usage, whipper_not_designed);
  use_gsl_return_codes();
  check_shot_settings(request.settings);
  check_material(request.material);
  check_capacity_size(request.capacity.R, request.projectile_mass.value_or(request.capacity.T), !request.projectile_mass, request.material);
  // L3 = F L1 cos(theta_i) - L2 > 0 needs l > 1/(F cos theta_i); the paper's engines, formal
  // ones of appendix B included, have l < 60.
  check_ordinary(request.F, 1e-6, 1e6, "F", "", "counterweight arm fraction (L2 + L3)/H");
  const double l_min = 1 / (request.F * std::cos(radians(request.theta_i_deg)));
  if (!(request.F > 0 && request.theta_i_deg > 0 && request.theta_i_deg < 90) || !(l_min < max_beam_ratio))
    throw Error(ErrorKind::out_of_range,
                "theta_i = " + format_significant(request.theta_i_deg, 4) + " deg with F = " + format_significant(request.F, 4) +
                    " leaves room for the counterweight arm (L2 + L3 = F L1 cos(theta_i) > L2) "
                    "only for a beam ratio l = L1/L2 above " +
                    format_significant(l_min, 3) + ", beyond any engine of the paper (l < " + format_number(max_beam_ratio) +
                    "); lower theta_i or raise F (the paper's are 30 or 40 deg and 1, 2/3 or 1/2)");
  std::vector<Optimum> optima;
  std::string reasons;
  bool all_numerical = true;
  for (const Start& start : starts_for(request)) {
    try {
      optima.push_back(search_from(request, start));
      // Its figures are those of the engine it gives, shot in SI: the search's own shot, of the
      // scaled design, differs in the last digits, and the record must read back as its shot.
      optima.back().fit.verification = verify_engine(optima.back().fit.engine, request.settings);
    } catch (const Error& e) {
      reasons += (reasons.empty() ? "" : "; ") + e.named_message();
      all_numerical = all_numerical && e.kind() == ErrorKind::numerical;
    }
  }
  if (optima.empty()) throw Error(all_numerical ? ErrorKind::numerical : ErrorKind::out_of_range, reasons);
  return optima;
}

Optimum best_optimum(const std::vector<Optimum>& optima) {
  const Optimum* best = &optima.front();
  for (const Optimum& o : optima)
    if (o.objective > best->objective) best = &o;
  return *best;
}

}  // namespace trebuchet
