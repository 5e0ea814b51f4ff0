#include "trebuchet/app/output/report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "trebuchet/error.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/app/input/units.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/quality.hpp"

namespace trebuchet {
namespace {

// The series is computed: a number that is not finite means the integration failed.
double finite_or_error(double value) {
  if (!std::isfinite(value)) throw Error(ErrorKind::numerical, "the result in the series is not finite; tighten {{rtol}}");
  return value;
}

std::string cell(const std::string& label, const std::string& value) {
  std::string text = label + " = " + value;
  return text + std::string(text.size() < 18 ? 18 - text.size() : 1, ' ');
}

}  // namespace

std::string pin_to_bend_text(const Verification& v, double pin_friction, bool releases) {
  const std::string bend = format_significant(v.pin_to_bend_deg, 4) + " deg";
  if (!releases) return "none makes it (a pin bent to " + bend + " does not, see the note)";
  if (!(pin_friction > 0)) return bend;
  return bend + " for its friction " + format_significant(pin_friction, 3) + " (" + format_significant(v.pin_angle_deg, 4) + " deg frictionless)";
}

std::string describe_given_release(const SetRelease& release) {
  switch (release.by) {
    case ReleaseBy::time: return "the time " + format_significant(release.value, 6) + " s";
    case ReleaseBy::velocity_angle: return "the velocity angle " + format_significant(release.value, 6) + " deg";
    case ReleaseBy::pin_angle: return "the pin angle " + format_significant(release.value, 6) + " deg";
  }
  return "";
}

std::string describe_target(const ShotSettings& settings) {
  return settings.range_from_release ? std::string("range from the release point to where the flight dips below the release height (Denny's)")
                                     : "target level " + format_significant(settings.target_level, 4) + " m";
}

std::string describe_release(const ShotSettings& settings) {
  const ReleaseCriterion& c = settings.criterion;
  const std::string rule = settings.release_at ? "at " + describe_given_release(*settings.release_at) + " (given)"
      : c.release == Release::quality    ? (c.n == 1 ? "where Q peaks (eq:Q)" : "where Q_n peaks (eq:Q_n, n = " + format_significant(c.n, 3) + ")")
      : c.release == Release::efficiency ? "where eps peaks (Q_eps, appendix B)"
                                         : "where the range peaks (Denny's criterion)";
  return "release " + rule + ", " + describe_target(settings);
}

std::string describe_assumptions(const Engine& engine, const ShotSettings& settings) {
  const std::optional<Air>& air = settings_for(engine, settings).air;  // a ball of given size sets the projectile's density
  return (air ? describe_air(*air, engine.m) : std::string("vacuum (no air drag)")) + ", g = " + format_significant(engine.material.g, 4) +
      " m/s2, " + describe_release(settings);
}

namespace {

// A correlation with its sign: "+0.98", "-0.31".
std::string signed_correlation(double rho) { return (rho >= 0 ? "+" : "") + format_significant(rho, 2); }

}  // namespace

std::vector<std::size_t> strongest_first(const std::vector<RankCorrelation>& correlations) {
  std::vector<std::size_t> order(correlations.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return std::abs(correlations[a].rho) > std::abs(correlations[b].rho); });
  return order;
}

std::string moves_most_text(const std::string& subject, const std::string& against, const std::vector<std::string>& names,
                            const std::vector<RankCorrelation>& correlations, std::size_t samples) {
  std::vector<std::string> resolved, not_resolved;
  for (std::size_t k : strongest_first(correlations)) {
    const RankCorrelation& c = correlations[k];
    (c.resolved() ? resolved : not_resolved)
        .push_back(names[k] + " " + signed_correlation(c.rho) + " (" + signed_correlation(c.low) + " to " + signed_correlation(c.high) + ")");
  }
  std::string out = "what moves " + subject + " most (Spearman's rank correlation with " + against + ", its 95 % interval): ";
  const std::string at = " at " + std::to_string(samples) + " samples";
  if (resolved.empty()) return out + "none resolved" + at + ": " + join(not_resolved, ", ");
  out += join(resolved, ", ");
  return not_resolved.empty() ? out : out + "; not resolved" + at + ": " + join(not_resolved, ", ");
}

std::string design_table(const OptimalEngine& design, UnitSystem units) {
  require_finite(design);
  const Engine& e = design.engine;
  const ScaledDesign s = scaled_design(e);
  auto length = [&](double m) { return quantity_text(m, UnitDimension::length, units); };
  auto mass = [&](double kg) { return quantity_text(kg, UnitDimension::mass, units); };
  auto energy = [&](double J) { return quantity_text(J, UnitDimension::energy, units); };
  std::string t;
  t += (e.machine == MachineKind::hinged
            ? "Optimal engine from tab:CPNC: theta_i = " + format_number(e.theta_i_deg) + " deg, F = " + format_fraction(design.F)
            : "Optimal " + machine_words(e.machine) + " from its scaling table (data/cpnc-" + machine_name(e.machine) +
                ".json, docs/machines.md), its counterweight at the short arm's end: theta_i = " + format_number(e.theta_i_deg) + " deg") +
      ", beta2 = " + format_fraction(e.material.beta2) + ", " +
      (design.branch == Branch::none ? std::string("segment") : std::string(branch_name(design.branch)) + " branch") + " X in [" +
      format_number(design.segment_X_min) + ", " + format_number(design.segment_X_max) + "]\n";
  if (design.scaled_from)
    t += "A MODEL at " + format_significant(design.scaled_from->factor, 4) +
        " of the size of the optimal engine for R = " + length(design.scaled_from->full_size.R) + ", T = " + energy(design.scaled_from->full_size.T) +
        " (eq:ExtraScalings); the capacity below is the model's\n";
  t += "  capacity       " + cell("R", length(design.capacity.R)) + cell("T", energy(design.capacity.T)) +
      cell("X", format_significant(design.coordinates.X, 3)) + cell("Y", format_significant(design.coordinates.Y, 3)) + "\n";
  t += std::string("                 in vacuum, from ") + (e.machine == MachineKind::floating_arm ? "the guide's line" : "the pivot") +
      " to the base's level (trebuchet-verify shot --air flies it through air)\n";
  using V = DesignValues;  // the engine's values under their keys (fields.hpp)
  t += "  beam           " + cell(key_of(&V::L1), length(e.L1)) + cell(key_of(&V::L2), length(e.L2)) + cell(key_of(&V::Lb), length(beam_length(e))) +
      cell(key_of(&V::H), length(pivot_height(e))) + "\n";
  t += "                 " + cell(key_of(&V::D), length(e.D)) + cell(key_of(&V::mb), mass(e.mb)) + "\n";
  t += "  counterweight  " + cell(key_of(&V::M), mass(e.M)) + cell(key_of(&V::L3), length(e.L3)) + "\n";
  t += "  sling          " + cell(key_of(&V::L4), length(e.L4)) + "\n";
  t += "  projectile     " + cell(key_of(&V::m), mass(e.m)) + "\n";
  t += "  scaled         " + cell("l", format_significant(s.l, 4)) + cell("l4", format_significant(s.l4, 4)) +
      cell("L", format_significant(e.L3 / e.L2, 4)) + "\n";
  t += "                 " + cell("mu", format_significant(s.mu, 4)) + cell("mu_b", format_significant(s.mu_b, 4)) +
      cell("K", format_significant(s.K(), 4)) + "\n";
  t += "  stored energy  " + cell("DeltaU", energy(potential_energy_drop(e))) + "(eq:DU)\n";
  const Material& material = e.material;
  if (material.g != Material{}.g || material.wood_density != Material{}.wood_density || material.youngs_modulus != Material{}.youngs_modulus)
    t += "  material       " + cell("E", quantity_text(material.youngs_modulus, UnitDimension::pressure, units)) +
        cell("rho_d", quantity_text(material.wood_density, UnitDimension::density, units)) +
        cell("g", quantity_text(material.g, UnitDimension::acceleration, units)) + "\n";
  for (const std::string& w : design.warnings) t += "warning: " + w + "\n";
  t += "the optimum of the fitted table; trebuchet-verify optimize finds the ab-initio optimum for the same capacity, within the flat top of Q "
       "(docs/calculator.md, \"Two optima\")\n";
  return t;
}

namespace {

// The machine after "engine simulated", none for the paper's.
std::string machine_title(MachineKind machine) {
  switch (machine) {
    case MachineKind::fixed: return " (fixed counterweight, its centre L3 beyond the short arm's end)";
    case MachineKind::floating_arm: return " (floating arm, its counterweight L3 below its pin; lengths along the ground from the guide's line)";
    case MachineKind::whipper: return " (whipper: started with its long arm forward and up, the counterweight and the projectile resting on it)";
    case MachineKind::hinged: break;
  }
  return "";
}

// The whipper's start in words, after its theta_i; empty for the others.
std::string whipper_start(const Engine& engine, UnitSystem units) {
  if (engine.machine != MachineKind::whipper) return "";
  const Engine::WhipperStart& w = engine.whipper;
  return " (the long arm " + format_significant(-90 - engine.theta_i_deg, 4) + " deg above the horizontal, forward; the rope " +
      format_significant(w.rope_angle_deg, 4) + " deg off it" +
      (engine.projectile_diameter ? "; the ball " + quantity_text(*engine.projectile_diameter, UnitDimension::length, units, 4) + " across"
                                  : std::string()) +
      ")";
}

// The parts of an engine as built, a line of the report; empty for the paper's ideal engine. The
// release pin's friction, which does not change the motion (EngineParts::any leaves it out), is
// one of them: a pin greased alone was left off the line (a fresh builder's test).
std::string describe_parts(const Engine& engine, UnitSystem units) {
  const EngineParts& p = engine.parts;
  if (!p.any() && p.pin_friction == 0) return "";
  auto q = [&](double si, UnitDimension dimension) { return quantity_text(si, dimension, units, 4); };
  std::vector<std::string> parts;
  if (p.D_tip) {
    parts.push_back("a tapered beam, D " + q(*p.D_hinge, UnitDimension::length) + " at the hinge to " + q(*p.D_tip, UnitDimension::length) +
                    " at the tip");
  } else if (p.beam_cm) {
    parts.push_back("a beam with its centre of mass " + q(*p.beam_cm, UnitDimension::length) + " from the pivot and " +
                    q(*given_beam_inertia(engine), UnitDimension::inertia) + " about it");
  }
  if (p.counterweight_inertia > 0) parts.push_back("a counterweight of " + q(p.counterweight_inertia, UnitDimension::inertia) + " about its centre");
  const auto pin = [&](const Pin& pin, const char* what) {
    if (pin.friction > 0)
      parts.push_back(std::string(what) + " friction " + format_significant(pin.friction, 3) + " on a radius of " +
                      q(pin.radius, UnitDimension::length));
  };
  pin(p.axle, "axle");
  pin(p.hinge, "hinge pin");
  if (p.trough_friction > 0) parts.push_back("trough friction " + format_significant(p.trough_friction, 3));
  if (p.rope_diameter > 0)
    parts.push_back("a rope of " + q(p.rope_diameter, UnitDimension::length) + " (Cd " + format_significant(p.rope_cd, 3) + ")");
  if (p.pin_friction > 0) parts.push_back("release pin friction " + format_significant(p.pin_friction, 3));
  if (p.rope_mass > 0 || p.pouch_mass > 0)
    parts.push_back("a sling of " + q(p.rope_mass, UnitDimension::mass) + " rope and " + q(p.pouch_mass, UnitDimension::mass) + " pouch");
  return "  as built: " + join(parts, ", ") + "\n";
}

// Where Delta U went by the release (Verification::EnergyBudget), a line of the report.
std::string energy_budget_text(const Verification& v, UnitSystem units) {
  const Verification::EnergyBudget& e = v.energy;
  auto share = [&](double joules) {
    return quantity_text(joules, UnitDimension::energy, units, 4) + " (" + format_significant(100 * joules / e.delta_U, 3) + " %)";
  };
  std::string text = "where Delta U = " + quantity_text(e.delta_U, UnitDimension::energy, units, 4) + " went by the release: the projectile " +
      share(e.projectile) + ", the beam and the counterweight " + share(e.engine) + (e.sling != 0 ? ", the sling " + share(e.sling) : "");
  const char* names[loss_count] = {"axle friction", "hinge friction", "trough friction", "air on the projectile", "air on the rope"};
  for (int k = 0; k < loss_count; ++k)
    if (e.losses[k] != 0) text += ", " + std::string(names[k]) + " " + share(e.losses[k]);
  text += "\n";
  // A tailwind can give the projectile more than the drag takes.
  if (e.flight_drag > 0) text += "in flight the air took " + quantity_text(e.flight_drag, UnitDimension::energy, units, 4) + " more\n";
  if (e.flight_drag < 0)
    text += "in flight the wind gave " + quantity_text(-e.flight_drag, UnitDimension::energy, units, 4) + " more than the drag took\n";
  return text;
}

}  // namespace

std::string calibration_table(const Calibration& c, const MeasuredRange& measured, const std::vector<Prediction>& predictions,
                              const ShotSettings& settings, UnitSystem units) {
  auto q = [&](double si, UnitDimension dimension, int digits = 4) { return quantity_text(si, dimension, units, digits); };
  auto sig = [](double x, int digits = 3) { return format_significant(x, digits); };
  const Engine& e = c.engine;
  const EngineParts& p = e.parts;
  std::ostringstream out;
  out << "measured: R = " << q(measured.range, UnitDimension::length)
      << (measured.uncertainty > 0 ? " ± " + q(measured.uncertainty, UnitDimension::length) : std::string()) << "\n"
      << "without friction the engine throws " << q(c.frictionless.capacity.R, UnitDimension::length) << " (" << describe_assumptions(e, settings)
      << ")\n"
      << "the range, step by step:\n";
  for (const CalibrationStep& step : c.steps) {
    std::string figure = q(step.R, UnitDimension::length);
    figure.resize(std::max<std::size_t>(figure.size(), 10), ' ');
    out << "  " << figure << "  " << step.what << "\n";
  }
  const std::string band = measured.uncertainty > 0 ? " (" + sig(c.value_low) + " to " + sig(c.value_high) + " for the range's ± 1 sigma" +
          (c.band_clipped ? "; the short end is clipped at the strongest friction the engine runs with" : "") + ")"
                                                    : "";
  if (c.fitted == FrictionFit::pin_coefficient)
    out << "fitted: one friction coefficient at both pins, mu = " << sig(c.value) << band << ", on the axle's radius "
        << q(p.axle.radius, UnitDimension::length) << " and the hinge pin's " << q(p.hinge.radius, UnitDimension::length) << "\n";
  else
    out << "fitted: the given friction coefficients times " << sig(c.value) << band << ": axle " << sig(p.axle.friction) << ", hinge pin "
        << sig(p.hinge.friction) << ", trough " << sig(p.trough_friction) << "\n";
  const double lost = c.frictionless.capacity.R - c.shot.capacity.R;
  out << "friction costs " << q(lost, UnitDimension::length) << " (" << sig(100 * lost / c.frictionless.capacity.R) << " % of the range); "
      << energy_budget_text(c.shot, units);
  if (!predictions.empty()) {
    out << "predicted with the calibrated friction (band: the fit's band):\n";
    for (const Prediction& pr : predictions) {
      const auto end = [&](const std::optional<double>& R) { return R ? q(*R, UnitDimension::length) : std::string("refused"); };
      out << "  " << pr.changed << ": R = " << q(pr.R, UnitDimension::length) << " (" << end(pr.R_low) << " to " << end(pr.R_high)
          << "), T = " << q(pr.shot.capacity.T, UnitDimension::energy) << "\n";
      if (!pr.band_end_refused.empty()) out << "    refused at an end of the band: " << pr.band_end_refused << "\n";
    }
  }
  out << "(" << c.simulations << " shots)\n";
  return out.str();
}

std::string verification_table(const Engine& engine, const ShotSettings& settings, const Verification& v, const std::optional<CapacityCheck>& check,
                               UnitSystem units) {
  require_finite(v);
  auto sig = [](double x, int digits = 5) { return format_significant(x, digits); };
  auto q = [&](double si, UnitDimension dimension, int digits = 4) { return quantity_text(si, dimension, units, digits); };
  const double g = engine.material.g, mg = engine.m * g, Mg = engine.M * g;
  std::ostringstream out;
  const bool floating = engine.machine == MachineKind::floating_arm;
  const char* origin = floating ? " the guide's line" : " the pivot";  // where lengths along the ground start
  out << "engine simulated" << machine_title(engine.machine) << ":\n"
      << engine_table(engine, units) << "  theta_i = " << sig(engine.theta_i_deg, 4) << " deg" << whipper_start(engine, units)
      << ", arm fraction (L2 + L3)/H = " << sig(arm_fraction(engine), 4)
      << (engine.psi_i_deg != 0 ? ", counterweight propped at psi_i = " + sig(engine.psi_i_deg, 4) + " deg" : std::string()) << "\n"
      << describe_parts(engine, units) << "assumptions: " << describe_assumptions(engine, settings) << "\n"
      << "R = " << q(v.capacity.R, UnitDimension::length, 5) << "   T = " << q(v.capacity.T, UnitDimension::energy, 5) << "   "
      << (settings.range_from_release ? "back at the release height" : "at the target level")
      << (settings.air || settings.range_from_release
              ? "; the paper's range, in vacuum from" + std::string(origin) + ": " + q(v.R_vacuum, UnitDimension::length, 5)
              : std::string())
      << "\n"
      << "eps = " << sig(100 * v.eps, 4) << " %   Q = " << sig(100 * v.Q, 4) << " %   force factor = " << sig(v.force_factor, 4)
      << " (eq:F)"
      // In air T is at the flight's end, eps (eq:Aux) the energy at the release over Delta U: two different things beside each other.
      << (settings.air ? "; eps is the energy at the release over Delta U (eq:Aux), before the air's loss in flight" : "") << "\n"
      << "range efficiency (Siano) = " << sig(100 * v.range_efficiency, 4) << " % of the black box's 2 Delta U/(m g), "
      << sig(100 * v.range_efficiency_counterweight, 4) << " % of 2 M h/m with h the counterweight's fall alone\n"
      << "release: v = " << q(v.v, UnitDimension::speed) << ", h = " << q(v.h, UnitDimension::length) << ", "
      << q(std::abs(v.x), UnitDimension::length) << (v.x < 0 ? " behind" : " ahead of") << origin << " (x = " << sig(v.x, 4)
      << " m), A = " << sig(v.A_deg, 4) << " deg, pin angle " << sig(v.pin_angle_deg, 4) << " deg\n"
      << "times: "
      << (v.t_counterweight_free ? "the counterweight leaves the arm " + sig(*v.t_counterweight_free, 4) + " s, the projectile "
                                 : std::string("lift-off "))
      << sig(v.t_liftoff, 4) << " s, release " << sig(v.t_release, 4) << " s\n"
      << "forces of eq:F: F_S_perp = " << q(v.FS_perp, UnitDimension::force) << " = " << sig(v.FS_perp_mg, 4)
      << " m·g, F_R = " << q(v.FR, UnitDimension::force) << " = " << sig(v.FR_Mg, 4) << " M·g, dF_Rh = " << q(v.dFRh, UnitDimension::force) << " = "
      << sig(v.dFRh_Mg, 4) << " M·g\n";
  if (settings.loads) {
    const char* names[load_count] = {"sling tension (rope)      ",
                                     engine.machine == MachineKind::fixed ? "counterweight's mounting  " : "counterweight hinge pin   ",
                                     floating ? "frame (rail and guide)    " : "pivot axle                ", "beam, bending at the pivot"};
    const double weight[load_count] = {mg, Mg, Mg, Mg * engine.L2};
    out << "largest loads up to the release, to size the parts:\n";
    const bool moment_known = scaled_design(engine).short_section().has_value();
    for (int k = 0; k < (moment_known ? load_count : beam_moment_load); ++k)
      out << "  " << names[k] << " " << q(v.loads[k].value, k == beam_moment_load ? UnitDimension::moment : UnitDimension::force) << " = "
          << sig(v.loads[k].value / weight[k], 4)
          << (k == sling_tension_load     ? " m·g"
                  : k == beam_moment_load ? " M·g·L2"
                                          : " M·g")
          << " at t = " << sig(v.loads[k].t, 4) << " s\n";
    if (!moment_known)
      out << "  the beam's bending at the pivot needs its short section's mass: give the beam tapered (--D-hinge, --D-tip) instead of "
             "its centre of mass and inertia\n";
    if (const auto& b = v.beam) {
      const double rupture = engine.material.modulus_of_rupture;
      out << "beam: D = " << q(b->D, UnitDimension::length, 3) << (engine.D > 0 ? "" : " (from mb and the wood, eq:BeamMass)")
          << ", bent by the counterweight at rest beta2 = u2/L2 = " << sig(100 * b->beta2, 3)
          << " % (eq:bend_L2; the paper sizes for 1/300 = 0.33 %)\n"
          << "  strain at the pivot: level under the counterweight " << sig(b->strain_at_rest, 3) << " = 1/"
          << quantity_text(1 / b->strain_at_rest, UnitDimension::dimensionless, units, 3) << " (eq:Strain), in the shot " << sig(b->strain_peak, 3)
          << " = 1/" << quantity_text(1 / b->strain_peak, UnitDimension::dimensionless, units, 3) << "\n"
          << "  stress: level " << q(b->stress_at_rest, UnitDimension::pressure, 3) << ", in the shot "
          << q(b->stress_peak, UnitDimension::pressure, 3) << ", against a modulus of rupture of " << q(rupture, UnitDimension::pressure, 3) << ": "
          << (b->margin >= 1 ? "margin " + sig(b->margin, 3) + " (the modulus of rupture over the larger stress)"
                             : "the beam BREAKS (margin " + sig(b->margin, 3) + " < 1: the larger stress exceeds the modulus of rupture)")
          << "\n";
    }
  }
  out << energy_budget_text(v, units);
  {  // Verification::Clearance
    const auto& c = v.clearance;
    out << "counterweight above the ground" << (engine.parts.box_height ? " (its box's bottom)" : "") << ": at least "
        << q(c.geometric, UnitDimension::length, 4) << " hanging straight down";
    if (c.in_shot) out << ", lowest in the shot " << q(*c.in_shot, UnitDimension::length, 4);
    out << (c.buildable() ? "" : ": NOT BUILDABLE") << "\n";
  }
  out << "energy drift: " << sig(v.energy_drift, 2) << " of Delta U"
      << (shot_design(engine, settings).parts.dissipates() ? ", with the work of the losses" : "") << "\n";
  for (const std::string& w : v.warnings) out << "warning: " << w << "\n";
  for (const std::string& n : v.notes) out << "note: " << n << "\n";
  if (check && check->as_measured) {
    out << "requested: R = " << q(check->predicted.R, UnitDimension::length, 5) << " (" << (check->deviation_R >= 0 ? "+" : "")
        << sig(100 * check->deviation_R, 3) << " %), T = " << q(check->predicted.T, UnitDimension::energy, 5) << " ("
        << (check->deviation_T >= 0 ? "+" : "") << sig(100 * check->deviation_T, 3) << " %): " << (check->pass ? "pass" : "FAIL") << " at tolerance "
        << sig(100 * check->tolerance, 3) << " %, against this shot as it measures them\n";
  } else if (check) {
    out << "predicted, in vacuum: R = " << q(check->predicted.R, UnitDimension::length, 5) << " (" << (check->deviation_R >= 0 ? "+" : "")
        << sig(100 * check->deviation_R, 3) << " %), T = " << q(check->predicted.T, UnitDimension::energy, 5) << " ("
        << (check->deviation_T >= 0 ? "+" : "") << sig(100 * check->deviation_T, 3) << " %): " << (check->pass ? "pass" : "FAIL") << " at tolerance "
        << sig(100 * check->tolerance, 3) << " %"
        << (settings.air || settings.range_from_release ? ", against this shot in vacuum from the pivot (R = " +
                    q(v.R_vacuum, UnitDimension::length, 5) + ", T = " + q(v.T_vacuum, UnitDimension::energy, 5) + ")"
                                                        : std::string())
        << "\n";
    if (!check->pass)
      out << "  the calculator interpolates the fitted table (tab:CPNC) for optimal engines; an engine away from that optimum, or at "
             "another theta_i, F or beta2, need not throw what it predicts\n";
  }
  return out.str();
}

std::string optimum_table(const Optimum& optimum, const ShotSettings& settings, UnitSystem units) {
  const ScaledDesign& from = optimum.start_design;
  const ScaledDesign to = scaled_design(optimum.fit.engine);
  auto shape = [](const ScaledDesign& d) {
    return "l = " + format_significant(d.l, 4) + ", l4 = " + format_significant(d.l4, 4) + ", mu_b = " + format_significant(d.mu_b, 4);
  };
  std::string text = "optimum from the " + optimum.start + " start (" + std::to_string(optimum.simulations) + " shots, " +
      std::to_string(optimum.iterations) + " simplex iterations):\n" +
      verification_table(optimum.fit.engine, settings, optimum.fit.verification, std::nullopt, units);
  text += "the search started from " + shape(from) + " and ended at " + shape(to) + ".";
  if (!optimum.note.empty()) text += " Note: " + optimum.note + ".";
  if (optimum.start.rfind("calculator", 0) == 0)
    text +=
        " trebuchet-calc gives the start's engine: the optimum of the table fitted to the paper's optima (tab:CPNC); this one is "
        "the ab-initio optimum for the same capacity. Q is flat near its top, so the two can differ by several % in length at a "
        "Q that differs by little (docs/calculator.md, \"Two optima\").";
  return text + "\n";
}

namespace {

// The engine's quantities that a completion keeps or chooses, with their values.
std::vector<std::pair<std::string, double>> completed_values(const Engine& e) {
  using V = DesignValues;
  return {{key_of(&V::Lb), beam_length(e)}, {key_of(&V::L1), e.L1}, {key_of(&V::L2), e.L2}, {key_of(&V::H), pivot_height(e)}, {key_of(&V::L3), e.L3},
          {key_of(&V::L4), e.L4},           {key_of(&V::M), e.M},   {key_of(&V::m), e.m},   {key_of(&V::mb), e.mb},           {key_of(&V::D), e.D}};
}

bool listed(const std::vector<std::string>& names, const std::string& name) { return std::find(names.begin(), names.end(), name) != names.end(); }

}  // namespace

std::string completion_table(const Completion& c, const ShotSettings& settings, UnitSystem units, const Completion* longest,
                             const std::string& longest_note) {
  auto listing = [](const std::vector<std::string>& names) { return names.empty() ? std::string("none") : join(names, ", "); };
  const ReleaseCriterion& criterion = settings.criterion;
  const std::string goal = criterion.release == Release::range ? "the longest range"
      : criterion.release == Release::efficiency               ? "the highest eps"
                                                               : "the highest Q";
  std::ostringstream out;
  out << "completed engine (" << c.simulations << " shots):\n"
      << "  attested: " << listing(c.attested) << "\n"
      << "  implied:  " << listing(c.implied) << "\n"
      << "  chosen for " << goal << ": " << listing(c.chosen) << "\n";
  out << verification_table(c.engine, settings, c.verification, std::nullopt, units);
  if (c.calculator) {
    const OptimalEngine& o = *c.calculator;
    out << "the calculator's optimum for this engine's capacity as the paper measures it (in vacuum, to the base's level, released where Q "
           "peaks: R = "
        << quantity_text(o.capacity.R, UnitDimension::length, units, 4) << ", T = " << quantity_text(o.capacity.T, UnitDimension::energy, units, 4)
        << "; the shot above, under its own settings, may differ), and how far this engine's values lie from it:\n ";
    const auto ours = completed_values(c.engine), optimum = completed_values(o.engine);
    for (std::size_t k = 0; k < ours.size(); ++k) {
      const std::string& name = ours[k].first;
      if (name == "D" && !(c.engine.D > 0)) continue;
      const double deviation = ours[k].second / optimum[k].second - 1;
      const bool mass = name == "M" || name == "m" || name == "mb";
      out << (k ? "," : "") << " " << name << " " << quantity_text(optimum[k].second, mass ? UnitDimension::mass : UnitDimension::length, units, 4)
          << " (" << (deviation >= 0 ? "+" : "") << format_significant(100 * deviation, 3) << " %"
          << (listed(c.attested, name)     ? ", attested"
                  : listed(c.chosen, name) ? ", chosen"
                                           : "")
          << ")";
    }
    out << "\n";
  } else {
    out << "no calculator optimum for this engine's capacity: " << c.calculator_note << "\n";
  }
  if (longest) {
    const double gain = longest->verification.capacity.R / c.verification.capacity.R - 1;
    out << "\nthe longest range with the same attested values (--quality range): R = "
        << quantity_text(longest->verification.capacity.R, UnitDimension::length, units, 4) << ", " << (gain >= 0 ? "+" : "")
        << format_significant(100 * gain, 3) << " % against the engine of " << goal.substr(4)
        << " above, at Q = " << format_significant(100 * longest->verification.Q, 3) << " % (against "
        << format_significant(100 * c.verification.Q, 3) << " %), eps = " << format_significant(100 * longest->verification.eps, 3)
        << " %; it chooses:\n"
        << engine_table(longest->engine, units)
        << (criterion.release == Release::quality ? "the engine of highest Q balances range against the forces on the frame (eq:Q); " : "")
        << "the longest range is the farthest the search found with these values, in this model (the paper's ideal engine, no friction)"
        << (gain < 0 ? "; here it found no engine throwing further than the one of " + goal.substr(4) : std::string()) << "\n";
  } else if (!longest_note.empty()) {
    out << "\nno longest range for comparison: " << longest_note << "\n";
  }
  return out.str();
}

std::string engine_table(const Engine& e, UnitSystem units) {
  auto length = [&](double m) { return quantity_text(m, UnitDimension::length, units); };
  auto mass = [&](double kg) { return quantity_text(kg, UnitDimension::mass, units); };
  std::ostringstream out;
  out << "  Lb = " << length(beam_length(e)) << ", H = " << length(pivot_height(e)) << ", L1 = " << length(e.L1) << ", L2 = " << length(e.L2)
      << ", L3 = " << length(e.L3) << ", L4 = " << length(e.L4) << "\n"
      << "  M = " << mass(e.M) << ", m = " << mass(e.m) << ", mb = " << mass(e.mb)
      << (e.D > 0 ? ", D = " + quantity_text(e.D, UnitDimension::length, units, 3) : std::string(", D not given")) << "\n";
  return out.str();
}

std::string trace_csv(const std::vector<TracePoint>& trace, const Engine& engine) {
  const ScaledDesign scaled = scaled_design(engine);
  const double g = engine.material.g;
  const double time_unit = std::sqrt(engine.L2 / g);  // section 3 [s]
  const double energy_unit = engine.M * g * engine.L2;  // [J]
  const double drop = scaled.energy_drop();
  // The bodies' energy with the work the losses took so far: what is conserved.
  const auto balance = [](const TracePoint& p) {
    double lost = 0;
    for (double w : p.work) lost += w;
    return p.snapshot.energy + lost;
  };
  double energy0 = trace.empty() ? 0 : balance(trace.front());
  bool released = false;
  std::ostringstream out;
  out << "phase,t_s,theta_deg,psi_deg,phi_deg,theta_dot_rad_s,psi_dot_rad_s,phi_dot_rad_s,"
         "FS_perp_mg,FR_Mg,FRh_Mg,FRv_Mg,FH_Mg,normal_mg,energy_J,energy_drift,"
         "counterweight_x_m,counterweight_y_m,tip_x_m,tip_y_m,projectile_x_m,projectile_y_m,"
         "E_counterweight_J,E_beam_J,E_projectile_kinetic_J,E_projectile_potential_J,sling_tension_mg,beam_moment_MgL2,"
         "W_axle_J,W_hinge_J,W_trough_J,W_sling_drag_J,W_rope_drag_J,pivot_x_m\n";
  for (const TracePoint& p : trace) {
    const Snapshot& s = p.snapshot;
    if (p.phase == Phase::released && !released) {  // without the projectile, energy is conserved anew
      released = true;
      energy0 = balance(p);
    }
    const SitePoint cw = site_point(s.counterweight, engine), tip = site_point(s.tip, engine), pr = site_point(s.projectile, engine);
    // After the release the sling and projectile are gone: phi, its rate and their positions are left empty.
    const double none = std::nan("");
    const bool gone = p.phase == Phase::released;
    const double row[] = {p.t * time_unit,
                          degrees(p.state.theta),
                          degrees(p.state.psi),
                          gone ? none : degrees(p.state.phi),
                          p.state.theta_dot / time_unit,
                          p.state.psi_dot / time_unit,
                          gone ? none : p.state.phi_dot / time_unit,
                          s.sling_perpendicular / scaled.mu,
                          force_values(s)[pivot_reaction],
                          force_values(s)[pivot_horizontal],
                          s.pivot_reaction.y,
                          std::hypot(s.hinge_force.x, s.hinge_force.y),
                          s.normal_force / scaled.mu,
                          s.energy * energy_unit,
                          (balance(p) - energy0) / drop,
                          cw.x,
                          cw.y,
                          tip.x,
                          tip.y,
                          gone ? none : pr.x,
                          gone ? none : pr.y,
                          s.energies.counterweight * energy_unit,
                          s.energies.beam * energy_unit,
                          s.energies.projectile_kinetic * energy_unit,
                          s.energies.projectile_potential * energy_unit,
                          gone ? none : s.sling_tension / scaled.mu,
                          s.beam_moment,
                          p.work[axle_loss] * energy_unit,
                          p.work[hinge_loss] * energy_unit,
                          p.work[trough_loss] * energy_unit,
                          p.work[projectile_drag_loss] * energy_unit,
                          p.work[rope_drag_loss] * energy_unit,
                          site_point(s.pivot, engine).x};
    out << phase_numeral(p.phase);
    for (double x : row) out << "," << (std::isnan(x) ? std::string() : format_number(finite_or_error(x)));
    out << "\n";
  }
  return out.str();
}

SitePoint site_point(Vec2 scaled, const Engine& engine) { return {-scaled.x * engine.L2, scaled.y * engine.L2 + pivot_height(engine)}; }

}  // namespace trebuchet
