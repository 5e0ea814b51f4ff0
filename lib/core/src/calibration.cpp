#include "trebuchet/calibration.hpp"

#include <algorithm>
#include <cmath>

#include "solve_1d.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {

namespace {

// The friction coefficients check_engine allows reach 2: the fit searches up to there.
constexpr double largest_coefficient = 2;

double largest_value(const Engine& e, FrictionFit fitted) {
  if (fitted == FrictionFit::pin_coefficient) return largest_coefficient;
  const EngineParts& p = e.parts;
  return largest_coefficient / std::max({p.axle.friction, p.hinge.friction, p.trough_friction});
}

}  // namespace

Engine with_friction(const Engine& engine, FrictionFit fitted, double value) {
  Engine e = engine;
  EngineParts& p = e.parts;
  if (fitted == FrictionFit::pin_coefficient) {  // at each pin given a radius that the engine has (the fixed counterweight has no hinge)
    if (p.axle.radius > 0) p.axle.friction = value;
    if (p.hinge.radius > 0 && engine.machine != MachineKind::fixed) p.hinge.friction = value;
  } else {
    p.axle.friction *= value, p.hinge.friction *= value, p.trough_friction *= value;
  }
  return e;
}

FrictionFit friction_fit_of(const Engine& engine) {
  const EngineParts& p = engine.parts;
  const bool has_friction = p.axle.friction > 0 || p.hinge.friction > 0 || p.trough_friction > 0;
  // A pin of radius 0 has no friction's torque: one pin's radius is enough, the other's 0. The
  // fixed machine's counterweight has no hinge to rub.
  const bool hinge_rubs = p.hinge.radius > 0 && engine.machine != MachineKind::fixed;
  if (!has_friction && !hinge_rubs && !(p.axle.radius > 0) && p.hinge.radius > 0)
    throw Error(ErrorKind::usage,
                "the fixed machine's counterweight has no hinge, so {{hinge_radius}} gives calibrate no pin to rub; give the axle's radius "
                "{{axle_radius}}");
  if (!has_friction && !hinge_rubs && !(p.axle.radius > 0))
    throw Error(ErrorKind::usage,
                "calibrate fits the engine's friction: give its coefficients ({{axle_friction}}, {{hinge_friction}}, "
                "{{trough_friction}}), whose common scale it fits, or a pin's radius ({{axle_radius}}, {{hinge_radius}} or both), "
                "and it fits one coefficient at the pins");
  return has_friction ? FrictionFit::scale : FrictionFit::pin_coefficient;
}

double fit_friction(const Engine& engine, double range, const ShotSettings& given) {
  const FrictionFit fitted = friction_fit_of(engine);
  ShotSettings settings = given;
  settings.loads = false;  // the range alone
  // The range at a friction; an engine that jams or sticks there throws nothing, which keeps the
  // range falling with the friction, as the bracket below needs.
  const auto range_at = [&](double value) {
    try {
      return verify_engine(with_friction(engine, fitted, value), settings).capacity.R;
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::numerical || value == 0) throw;
      return 0.0;
    }
  };
  const double R0 = range_at(0);
  if (!(range < R0))
    throw Error(ErrorKind::out_of_range,
                "no friction explains it: the engine throws " + format_significant(R0, 4) + " m without friction, no farther than the range " +
                    format_significant(range, 4) + " m");
  const double top = largest_value(engine, fitted), R_top = range_at(top);
  if (!(R_top < range))
    throw Error(ErrorKind::out_of_range,
                "friction alone does not explain it: the strongest friction allowed still throws " + format_significant(R_top, 4) +
                    " m, farther than the range " + format_significant(range, 4) + " m");
  return find_root([&](double value) { return range_at(value) - range; }, 0, top, 1e-5 * top, 0);
}

Calibration calibrate(const Engine& engine, const MeasuredRange& measured, const ShotSettings& settings) {
  check_engine(engine);
  check_shot_settings(settings);
  if (!(measured.range > 0))
    throw Error(ErrorKind::bad_number,
                "{{measured}} = " + format_significant(measured.range, 6) + " m: give the measured range, e.g. {{measured}} 34.4m±1.5m");
  if (!(measured.uncertainty >= 0 && measured.uncertainty < measured.range))
    throw Error(ErrorKind::bad_number,
                "the measured range's uncertainty " + format_significant(measured.uncertainty, 6) +
                    " m must lie from 0 to the range itself; give it as {{measured}} 34.4m±1.5m");
  Calibration out;
  out.fitted = friction_fit_of(engine);
  // The gap explained in a fixed order (issue 35): the ideal engine at its optimum in vacuum,
  // measured as the settings measure it; then the release given; then the air given.
  {
    ShotSettings ideal = settings;
    ideal.release_at.reset(), ideal.air.reset(), ideal.drag_in_sling = false;
    const Engine frictionless = with_friction(engine, out.fitted, 0);
    out.steps.push_back({"the engine without friction, released at its optimum, in vacuum", verify_engine(frictionless, ideal).capacity.R});
    ++out.simulations;
    if (settings.release_at) {
      ideal.release_at = settings.release_at;
      out.steps.push_back({"released as given", verify_engine(frictionless, ideal).capacity.R});
      ++out.simulations;
    }
  }
  auto range_at = [&](double value) {
    ++out.simulations;
    return verify_engine(with_friction(engine, out.fitted, value), settings).capacity.R;
  };
  out.frictionless = verify_engine(with_friction(engine, out.fitted, 0), settings);
  ++out.simulations;
  if (settings.air)
    out.steps.push_back({settings.drag_in_sling ? "through the given air, in the sling too" : "through the given air", out.frictionless.capacity.R});
  const double R0 = out.frictionless.capacity.R;
  // The steps in words, for the refusals below: "42.83 m without friction ..., 40.1 m through the given air".
  const auto explained = [&] {
    std::string text;
    for (const CalibrationStep& step : out.steps) text += (text.empty() ? " (" : ", ") + format_significant(step.R, 4) + " m " + step.what;
    return text + ")";
  };
  if (!(measured.range < R0))
    throw Error(ErrorKind::out_of_range,
                "the measured range " + format_significant(measured.range, 4) + " m is not shorter than the engine's without friction, " +
                    format_significant(R0, 4) + " m" + explained() +
                    ": friction only shortens a shot; check the engine's values, the release, the air (--air) "
                    "and the target level");
  // The largest friction allowed, or, where the engine jams (or sticks) before it, the largest it
  // still runs with: bisected to 1e-6 of the allowed range between the last that ran and the first
  // that did not.
  double top = largest_value(engine, out.fitted), R_top = 0;
  try {
    R_top = range_at(top);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::numerical) throw;
    double runs = 0, fails = top;
    R_top = R0;
    while (fails - runs > 1e-6 * top) {
      const double middle = (runs + fails) / 2;
      try {
        R_top = range_at(middle), runs = middle;
      } catch (const Error& failure) {
        if (failure.kind() != ErrorKind::numerical) throw;
        fails = middle;
      }
    }
    top = runs;
    out.jams_at = fails;
  }
  auto value_for = [&](double range) {
    if (range >= R0) return 0.0;
    if (range <= R_top) {
      out.band_clipped = true;
      return top;
    }
    return find_root([&](double value) { return range_at(value) - range; }, 0, top, 0, 1e-9);
  };
  if (!(measured.range > R_top))
    throw Error(ErrorKind::out_of_range,
                (out.jams_at ? "the strongest friction the engine runs with (" + format_significant(top, 4) +
                         (out.fitted == FrictionFit::scale ? " times the coefficients" : " at both pins") + "; more jams it) throws "
                             : "even friction coefficients of " + format_significant(largest_coefficient, 2) + " throw ") +
                    format_significant(R_top, 4) + " m, farther than the measured " + format_significant(measured.range, 4) + " m" + explained() +
                    ": friction alone does not explain the shortfall; check the engine's values, the release ({{release_time}}, "
                    "{{release_angle}} or {{pin_angle}}) and the air");
  out.value = value_for(measured.range);
  out.value_low = value_for(measured.range + measured.uncertainty);
  out.value_high = value_for(measured.range - measured.uncertainty);
  out.engine = with_friction(engine, out.fitted, out.value);
  out.shot = verify_engine(out.engine, settings);
  ++out.simulations;
  out.steps.push_back({"with the friction fitted", out.shot.capacity.R});
  return out;
}

Prediction predict(const Calibration& c, const Engine& changed, const std::string& what, const ShotSettings& settings) {
  // `changed` is the calibrated engine with another projectile or counterweight: it carries the
  // fitted friction; the band's ends carry the friction fitted to the range's ends.
  Prediction out;
  out.changed = what;
  out.engine = changed;
  out.shot = verify_engine(changed, settings);
  out.R = out.shot.capacity.R;
  // At a band's end the changed engine may stop being one the model shoots (friction that jams
  // the beam, or sticks the counterweight to it): that end is left empty, with why, rather than
  // losing the fit.
  const auto range_with = [&](double value) -> std::optional<double> {
    const Engine e = c.fitted == FrictionFit::pin_coefficient ? with_friction(changed, c.fitted, value)
                                                              : with_friction(changed, FrictionFit::scale, value / c.value);
    try {
      return verify_engine(e, settings).capacity.R;
    } catch (const Error& error) {
      // Its words without its advice: the friction there is the band's, not one the user gave.
      const std::string why = with_words(error.named_message(), [](std::string_view key) { return std::string(key); });
      out.band_end_refused = why.substr(0, why.find("; give"));
      return std::nullopt;
    }
  };
  out.R_low = range_with(c.value_high);
  out.R_high = range_with(c.value_low);
  return out;
}

}  // namespace trebuchet
