#include "trebuchet/capacity_fit.hpp"

#include <cmath>
#include <optional>

#include "solve_1d.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {

void check_capacity_size(double R, double target, bool energy, const Material& material) {
  check_ordinary(R, 1e-6, 1e6, "R", "m", "range");
  const double m = energy ? 2 * target / (material.g * R) : target;  // T ~ m g R / 2 (section 4)
  if (!(m >= 1e-9 && m <= 1e12))
    throw Error(ErrorKind::bad_number,
                (energy ? "{{T}} = " + format_significant(target, 4) + " J at {{R}} = " + format_significant(R, 4) +
                         " m asks a stone of about m = 2T/(gR), " + (std::isfinite(m) ? format_significant(m, 3) + " kg, " : std::string())
                        : "the stone {{m}} = " + format_significant(target, 4) + " kg is ") +
                    "outside the ordinary masses 1e-09 to 1e+12 kg; give a capacity of ordinary size");
}

namespace {

// What the fit matches besides R: the energy T [J] (section 5) or the projectile's mass m [kg].
enum class Matched { energy, mass };

// One fit of a shape to R and the energy or the mass, a root search in log mu: each trial a shot
// of the shape at mu, sized to land at R.
class ShapeFit {
 public:
  ShapeFit(const ScaledDesign& shape, double R, Matched matched, double target, const Material& material, const ShotSettings& settings, double rtol)
      : shape_(shape),
        R_(R),
        matched_(matched),
        target_(target),
        material_(material),
        settings_(settings),
        rtol_(rtol),
        design_(shape),
        // In vacuum to level 0 from the pivot the range scales with the size: L2 = R/rho.
        scales_(!settings.air && !settings.range_from_release && settings.target_level == 0),
        // A release that maximises Q or eps asks nothing of the flight's end (its air, level or
        // where it is measured from), and with the air acting in flight only the scaled motion
        // before the release is the same at every size: the shot at mu, and its release, then
        // serve every size, whose flight alone is computed anew (as the vacuum's fit takes its
        // figures from the scaled shot, not from the engine in SI shot again).
        same_release_(settings.criterion.release != Release::range && !settings.drag_in_sling && shape.machine != MachineKind::whipper) {}
  CapacityFit run();

 private:
  // One shot of the design with ratio mu gives the L2 that lands at R; eq:ExtraScalings then
  // gives M there, so the T delivered and the m thrown.
  struct Trial {
    ShotResult shot;
    double L2, value;  // [m]; T [J] or m [kg]
    std::optional<Verification> measured;  // the shot in SI, where the range is measured in air, to a target level or from the release
  };
  Verification measured_at(const ShotResult& shot_at_mu, double L2, bool find_loads);
  double size_for_range(const ShotResult& shot_at_mu, double L2_guess);
  Trial trial(double mu, bool find_loads = false);
  double log_error(double log_mu);
  double error_or_nan(double log_mu);
  std::optional<std::pair<double, double>> bracket(double log_mu_guess, bool warm);
  void check_found(const Trial& found) const;

  const ScaledDesign& shape_;
  const double R_;  // [m]
  const Matched matched_;
  const double target_;  // T [J] or m [kg]
  const Material& material_;
  const ShotSettings& settings_;
  const double rtol_;
  CapacityFit fit_;
  ScaledDesign design_;
  const bool scales_, same_release_;
  // The mu tried whose value came nearest the target: the fit's answer where the root search's
  // estimate misses the tolerance because the release's own round-off (about 1e-9 in T near a
  // kink of the objective) makes the value jump at the finest steps in mu.
  double nearest_log_mu_ = 0, nearest_error_ = INFINITY;
  bool any_shot_ = false;  // a shot on the walk ran
  std::optional<Error> numerical_failure_;  // the last shot whose integration failed
};

Verification ShapeFit::measured_at(const ShotResult& shot_at_mu, double L2, bool find_loads) {
  const Engine engine = engine_of(design_, L2, material_);
  if (same_release_) {
    check_engine(engine);
    return verification_of(engine, shot_at_mu, settings_.target_level, settings_.air, settings_.range_from_release);
  }
  ShotSettings at = settings_;
  at.loads = find_loads;
  ++fit_.simulations;
  return verify_engine(engine, at);
}

// Through air, to another level or from the release point the range does not scale with the
// size: the size is solved for, by the secant method on log R against log L2 from the estimate
// (R grows about as L2), to 0.1 rtol of R, each step a shot measured as verify_engine measures it.
double ShapeFit::size_for_range(const ShotResult& shot_at_mu, double L2_guess) {
  double log_L2 = std::log(L2_guess), log_R = std::log(measured_at(shot_at_mu, L2_guess, false).capacity.R), slope = 1;  // R about proportional to L2
  for (int step = 0; step < 30 && !(std::abs(log_R - std::log(R_)) <= 0.1 * rtol_); ++step) {
    const double next = log_L2 + (std::log(R_) - log_R) / slope;
    const double log_R_next = std::log(measured_at(shot_at_mu, std::exp(next), false).capacity.R);
    // The slope from steps too short to rise above the shot's round-off (1e-11) is not taken.
    if (std::abs(next - log_L2) > 1e-7) slope = (log_R_next - log_R) / (next - log_L2);
    log_L2 = next, log_R = log_R_next;
    if (!(slope > 0.05))
      throw Error(ErrorKind::out_of_range,
                  "the range " + std::string(settings_.air ? "through the air " : "") +
                      "does not grow with the engine's size here; no size of this shape reaches " + format_significant(R_, 4) + " m");
  }
  return std::exp(log_L2);
}

ShapeFit::Trial ShapeFit::trial(double mu, bool find_loads) {
  design_.mu = mu;
  Trial out{simulate_shot(design_, settings_.criterion, settings_.integrator, nullptr, 0, nullptr, find_loads && (scales_ || same_release_)), 0, 0,
            std::nullopt};
  ++fit_.simulations;
  out.L2 = R_ / out.shot.release.range;
  if (!scales_) {
    out.L2 = size_for_range(out.shot, out.L2);
    out.measured = measured_at(out.shot, out.L2, find_loads);
  }
  const ExtraScalings sizes = extra_scalings(design_.K(), out.L2, material_);  // eq:ExtraScalings
  out.value = matched_ == Matched::mass ? mu * sizes.M
      : out.measured                    ? out.measured->capacity.T
                                        : sizes.energy_unit * out.shot.release.energy_at_target;
  return out;
}

double ShapeFit::log_error(double log_mu) {
  const double error = std::log(trial(std::exp(log_mu)).value / target_);
  if (std::abs(error) < nearest_error_) nearest_error_ = std::abs(error), nearest_log_mu_ = log_mu;
  return error;
}

// The error at log mu, or NaN where mu lies beyond (1e-6, 1] or its shot fails.
double ShapeFit::error_or_nan(double log_mu) {
  if (log_mu < std::log(1e-6) || log_mu > 0) return std::nan("");
  try {
    const double error = log_error(log_mu);
    any_shot_ = true;
    return error;
  } catch (const Error& e) {
    if (integration_failed(e)) numerical_failure_ = e;
    return std::nan("");
  }
}

// T and m grow with mu where the fit has worked (a heavier stone needs a larger engine for the
// same R), so the walk goes first the way the error at the guess points, then the other way:
// outward in steps that double from 1 % (warm) or 5 % in mu, up to a factor 20, to the first
// sign change of the error; shots that fail on the way are stepped over.
std::optional<std::pair<double, double>> ShapeFit::bracket(double log_mu_guess, bool warm) {
  const double first_step = warm ? 0.01 : 0.05, reach = 3.0;
  const double at_guess = error_or_nan(log_mu_guess);
  const double first_side = at_guess > 0 ? -1 : 1;
  for (const double side : {first_side, -first_side}) {
    double previous = at_guess, inner = 0;
    for (double step = first_step; inner < reach; inner += step, step *= 2) {
      const double from = log_mu_guess + side * inner, to = log_mu_guess + side * (inner + step);
      const double value = error_or_nan(to);
      if (std::isfinite(value) && std::isfinite(previous) && (value > 0) != (previous > 0)) return std::pair{std::min(from, to), std::max(from, to)};
      previous = value;
    }
  }
  return std::nullopt;
}

// The fitted engine is an engine, conserves energy, and meets the request to rtol.
void ShapeFit::check_found(const Trial& found) const {
  try {
    check_engine(fit_.engine);
  } catch (const Error& e) {
    throw Error(e.kind(), "the fitted engine: " + e.named_message());
  }
  if (!(fit_.verification.eps <= 1))
    throw Error(
        ErrorKind::numerical,
        "the fitted engine has eps = " + format_significant(fit_.verification.eps, 4) + " > 1: energy is not conserved (eq:Aux); tighten {{rtol}}");
  if (!(std::abs(found.value / target_ - 1) <= rtol_) || !(std::abs(fit_.verification.capacity.R / R_ - 1) <= rtol_))
    throw Error(
        ErrorKind::numerical,
        "the fit reached R = " + format_significant(fit_.verification.capacity.R, 8) + " m with " +
            (matched_ == Matched::energy ? "T = " + format_significant(found.value, 8) + " J" : "m = " + format_significant(found.value, 8) + " kg") +
            ", not within " + format_significant(rtol_, 2) +
            " of the request: it jumps with mu here, as the "
            "release moves from one maximum of the objective to another");
}

CapacityFit ShapeFit::run() {
  check_shot_settings(settings_);
  check_material(material_);
  // The guess: the given mu (a warm start), or one without a shot: T ~ m g R / 2 ties m and T
  // (section 4), and T ~ 0.9 Delta U with Delta U = M g L2 (Delta U/(M g L2)) (eq:DU) and
  // M g L2 ~ L2^5 (eq:ExtraScalings) gives L2 and M.
  const double T_guess = matched_ == Matched::energy ? target_ : target_ * material_.g * R_ / 2;
  const double m_guess = 2 * T_guess / (material_.g * R_);
  check_capacity_size(R_, target_, matched_ == Matched::energy, material_);
  const double drop_per_L2_5 = extra_scalings(shape_.K(), 1.0, material_).energy_unit * shape_.energy_drop();  // Delta U at L2 = 1 m [J]
  const double L2_guess = std::pow(T_guess / (0.9 * drop_per_L2_5), 0.2);
  const bool warm = shape_.mu > 0;
  const double log_mu_guess = warm ? std::log(shape_.mu) : std::log(m_guess / extra_scalings(shape_.K(), L2_guess, material_).M);
  const auto bracketed = bracket(log_mu_guess, warm);
  const std::string goal = matched_ == Matched::energy
      ? "deliver " + format_significant(target_ / 1e3, 4) + " kJ at " + format_significant(R_, 4) + " m"
      : "throw " + format_significant(target_, 4) + " kg to " + format_significant(R_, 4) + " m";
  // Every shot's integration failed: the integrator is at fault, not the capacity.
  if (!bracketed && !any_shot_ && numerical_failure_)
    throw Error(ErrorKind::numerical, "every shot of the fit failed: " + numerical_failure_->named_message());
  if (!bracketed)
    throw Error(ErrorKind::out_of_range,
                "no projectile mass within a factor 20 of " +
                    (warm ? "the starting m/M = " + format_significant(shape_.mu, 3) : "m = 2T/(gR) = " + format_significant(m_guess, 3) + " kg") +
                    " lets this shape " + goal + "; change the shape (l, l4, mu_b) or the capacity");
  Trial found = trial(std::exp(find_root([&](double log_mu) { return log_error(log_mu); }, bracketed->first, bracketed->second, 0.1 * rtol_, 0)),
                      settings_.loads);
  if (!(std::abs(found.value / target_ - 1) <= rtol_) && nearest_error_ < std::abs(std::log(found.value / target_)))
    found = trial(std::exp(nearest_log_mu_), settings_.loads);
  fit_.design = design_;
  fit_.engine = engine_of(design_, found.L2, material_);  // the one conversion to SI
  fit_.verification = found.measured ? *found.measured : verification_of(fit_.engine, found.shot, 0);
  check_found(found);
  return fit_;
}

CapacityFit fit_shape(const ScaledDesign& shape, double R, Matched matched, double target, const Material& material, const ShotSettings& settings,
                      double rtol) {
  return ShapeFit(shape, R, matched, target, material, settings, rtol).run();
}

}  // namespace

CapacityFit fit_capacity(const ScaledDesign& shape, const Capacity& capacity, const Material& material, const ShotSettings& settings, double rtol) {
  return fit_shape(shape, capacity.R, Matched::energy, capacity.T, material, settings, rtol);
}

CapacityFit fit_range_and_mass(const ScaledDesign& shape, double R, double m, const Material& material, const ShotSettings& settings, double rtol) {
  return fit_shape(shape, R, Matched::mass, m, material, settings, rtol);
}

}  // namespace trebuchet
