#include "trebuchet/app/report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "trebuchet/error.hpp"
#include "trebuchet/app/units.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/quality.hpp"

namespace trebuchet {
namespace {

std::string with_unit(double value, const char* unit) { return format_significant(value, 4) + " " + unit; }

std::string mass_text(double kg) { return kg >= 1000 ? with_unit(kg / 1000, "t") : with_unit(kg, "kg"); }

std::string energy_text(double joules) {
  if (joules >= 1e6) return with_unit(joules / 1e6, "MJ");
  if (joules >= 1e3) return with_unit(joules / 1e3, "kJ");
  return with_unit(joules, "J");
}

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

std::string design_table(const OptimalEngine& design) {
  require_finite(design);
  const Engine& e = design.engine;
  const ScaledDesign s = scaled_design(e);
  std::string t;
  t += "Optimal engine from tab:CPNC: theta_i = " + format_number(e.theta_i_deg) + " deg, F = " +
       format_fraction(design.F) + ", beta2 = " + format_fraction(e.material.beta2) + ", " +
       (design.branch == Branch::none ? std::string("segment") : std::string(branch_name(design.branch)) + " branch") +
       " X in [" + format_number(design.segment_X_min) + ", " + format_number(design.segment_X_max) + "]\n";
  if (design.scaled_from)
    t += "A MODEL at " + format_significant(design.scaled_from->factor, 4) + " of the size of the optimal engine for R = " +
         with_unit(design.scaled_from->full_size.R, "m") + ", T = " + energy_text(design.scaled_from->full_size.T) +
         " (eq:ExtraScalings); the capacity below is the model's\n";
  t += "  capacity       " + cell("R", with_unit(design.capacity.R, "m")) + cell("T", energy_text(design.capacity.T)) +
       cell("X", format_significant(design.coordinates.X, 3)) + cell("Y", format_significant(design.coordinates.Y, 3)) + "\n";
  t += "                 in vacuum, from the pivot to the base's level (trebuchet-verify shot --air flies it through air)\n";
  t += "  beam           " + cell("L1", with_unit(e.L1, "m")) + cell("L2", with_unit(e.L2, "m")) +
       cell("Lb", with_unit(beam_length(e), "m")) + cell("H", with_unit(pivot_height(e), "m")) + "\n";
  t += "                 " + cell("D", with_unit(e.D, "m")) + cell("mb", mass_text(e.mb)) + "\n";
  t += "  counterweight  " + cell("M", mass_text(e.M)) + cell("L3", with_unit(e.L3, "m")) + "\n";
  t += "  sling          " + cell("L4", with_unit(e.L4, "m")) + "\n";
  t += "  projectile     " + cell("m", mass_text(e.m)) + "\n";
  t += "  scaled         " + cell("l", format_significant(s.l, 4)) + cell("l4", format_significant(s.l4, 4)) +
       cell("L", format_significant(e.L3 / e.L2, 4)) + "\n";
  t += "                 " + cell("mu", format_significant(s.mu, 4)) + cell("mu_b", format_significant(s.mu_b, 4)) +
       cell("K", format_significant(s.K(), 4)) + "\n";
  t += "  stored energy  " + cell("DeltaU", energy_text(potential_energy_drop(e))) + "(eq:DU)\n";
  const Material& material = e.material;
  if (material.g != Material{}.g || material.wood_density != Material{}.wood_density ||
      material.youngs_modulus != Material{}.youngs_modulus)
    t += "  material       " + cell("E", with_unit(material.youngs_modulus / 1e9, "GPa")) +
         cell("rho_d", with_unit(material.wood_density, "kg/m3")) + cell("g", with_unit(material.g, "m/s2")) + "\n";
  for (const std::string& w : design.warnings) t += "warning: " + w + "\n";
  return t;
}

std::string verification_table(const Engine& engine, const ShotSettings& settings, const Verification& v,
                               const std::optional<CapacityCheck>& check) {
  require_finite(v);
  auto sig = [](double x, int digits = 5) { return format_significant(x, digits); };
  const double g = engine.material.g, mg_kN = engine.m * g / 1e3, Mg_kN = engine.M * g / 1e3;
  const ReleaseCriterion& c = settings.criterion;
  const std::string rule = c.release == Release::quality ? (c.n == 1 ? "where Q peaks (eq:Q)" : "where Q_n peaks (eq:Q_n, n = " + sig(c.n, 3) + ")")
                           : c.release == Release::efficiency ? "where eps peaks (Q_eps, appendix B)"
                                                              : "where the range peaks (Denny's criterion)";
  std::ostringstream out;
  out << "engine simulated:\n" << engine_table(engine) << "  theta_i = " << sig(engine.theta_i_deg, 4)
      << " deg, arm fraction (L2 + L3)/H = " << sig(arm_fraction(engine), 4)
      << (engine.psi_i_deg != 0 ? ", counterweight propped at psi_i = " + sig(engine.psi_i_deg, 4) + " deg" : std::string()) << "\n"
      << "assumptions: " << (settings.air ? describe_air(*settings.air, engine.m) : std::string("vacuum (no air drag)")) << ", g = " << sig(g, 4)
      << " m/s2, release " << rule << ", "
      << (settings.range_from_release ? std::string("range from the release point to where the flight dips below the release height (Denny's)")
                                      : "target level " + sig(settings.target_level, 4) + " m")
      << "\n"
      << "R = " << sig(v.capacity.R) << " m   T = " << sig(v.capacity.T / 1e3) << " kJ   "
      << (settings.range_from_release ? "back at the release height" : "at the target level")
      << (settings.air || settings.range_from_release ? "; the paper's range, in vacuum from the pivot: " + sig(v.R_vacuum) + " m" : std::string()) << "\n"
      << "eps = " << sig(100 * v.eps, 4) << " %   Q = " << sig(100 * v.Q, 4) << " %   force factor = " << sig(v.force_factor, 4) << " (eq:F)\n"
      << "release: v = " << sig(v.v, 4) << " m/s, h = " << sig(v.h, 4) << " m, x = " << sig(v.x, 4)
      << " m (behind the pivot if > 0), A = " << sig(v.A_deg, 4) << " deg\n"
      << "times: lift-off " << sig(v.t_liftoff, 4) << " s, release " << sig(v.t_release, 4) << " s\n"
      << "forces: F_S_perp = " << sig(v.FS_perp_mg * mg_kN, 4) << " kN (" << sig(v.FS_perp_mg, 4) << " × m·g), F_R = " << sig(v.FR_Mg * Mg_kN, 4)
      << " kN (" << sig(v.FR_Mg, 4) << " × M·g), dF_Rh = " << sig(v.dFRh_Mg * Mg_kN, 4) << " kN (" << sig(v.dFRh_Mg, 4) << " × M·g)\n"
      << "energy drift: " << sig(v.energy_drift, 2) << " of Delta U\n";
  for (const std::string& w : v.warnings) out << "warning: " << w << "\n";
  if (check) {
    out << "predicted: R = " << sig(check->predicted.R) << " m (" << (check->deviation_R >= 0 ? "+" : "") << sig(100 * check->deviation_R, 3)
        << " %), T = " << sig(check->predicted.T / 1e3) << " kJ (" << (check->deviation_T >= 0 ? "+" : "") << sig(100 * check->deviation_T, 3)
        << " %): " << (check->pass ? "pass" : "FAIL") << " at tolerance " << sig(100 * check->tolerance, 3) << " %\n";
  }
  return out.str();
}

std::string optimum_table(const Optimum& optimum, const ShotSettings& settings) {
  return "optimum from the " + optimum.start + " start (" + std::to_string(optimum.simulations) + " shots, " +
         std::to_string(optimum.iterations) + " simplex iterations):\n" + verification_table(optimum.fit.engine, settings, optimum.fit.verification);
}

namespace {

// The engine's quantities that a completion keeps or chooses, with their values.
std::vector<std::pair<std::string, double>> completed_values(const Engine& e) {
  return {{"Lb", beam_length(e)}, {"L1", e.L1}, {"L2", e.L2}, {"H", pivot_height(e)}, {"L3", e.L3}, {"L4", e.L4},
          {"M", e.M}, {"m", e.m}, {"mb", e.mb}, {"D", e.D}};
}

bool listed(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::string completion_table(const Completion& c, const ShotSettings& settings) {
  auto listing = [](const std::vector<std::string>& names) { return names.empty() ? std::string("none") : join(names, ", "); };
  const ReleaseCriterion& criterion = settings.criterion;
  const std::string goal = criterion.release == Release::range ? "the longest range" : criterion.release == Release::efficiency ? "the highest eps" : "the highest Q";
  std::ostringstream out;
  out << "completed engine (" << c.simulations << " shots):\n"
      << "  attested: " << listing(c.attested) << "\n"
      << "  implied:  " << listing(c.implied) << "\n"
      << "  chosen for " << goal << ": " << listing(c.chosen) << "\n";
  out << verification_table(c.engine, settings, c.verification);
  if (c.calculator) {
    const OptimalEngine& o = *c.calculator;
    out << "the calculator's optimum for this engine's capacity in vacuum (R = " << format_significant(o.capacity.R, 4) << " m, T = "
        << format_significant(o.capacity.T / 1e3, 4) << " kJ), and how far this engine's values lie from it:\n ";
    const auto ours = completed_values(c.engine), optimum = completed_values(o.engine);
    for (std::size_t k = 0; k < ours.size(); ++k) {
      const std::string& name = ours[k].first;
      if (name == "D" && !(c.engine.D > 0)) continue;
      const double deviation = ours[k].second / optimum[k].second - 1;
      const bool mass = name == "M" || name == "m" || name == "mb";
      out << (k ? "," : "") << " " << name << " " << format_significant(optimum[k].second, 4) << (mass ? " kg" : " m") << " ("
          << (deviation >= 0 ? "+" : "") << format_significant(100 * deviation, 3) << " %"
          << (listed(c.attested, name) ? ", attested" : listed(c.chosen, name) ? ", chosen" : "") << ")";
    }
    out << "\n";
  } else {
    out << "no calculator optimum for this engine's capacity: " << c.calculator_note << "\n";
  }
  return out.str();
}

std::string engine_table(const Engine& e) {
  auto sig = [](double x) { return format_significant(x, 4); };
  auto mass = [&](double kg) { return kg >= 1000 ? sig(kg / 1000) + " t" : sig(kg) + " kg"; };
  std::ostringstream out;
  out << "  Lb = " << sig(beam_length(e)) << " m, H = " << sig(pivot_height(e)) << " m, L1 = " << sig(e.L1) << " m, L2 = " << sig(e.L2)
      << " m, L3 = " << sig(e.L3) << " m, L4 = " << sig(e.L4) << " m\n"
      << "  M = " << mass(e.M) << ", m = " << mass(e.m) << ", mb = " << mass(e.mb)
      << (e.D > 0 ? ", D = " + format_significant(e.D, 3) + " m" : std::string(", D not given")) << "\n";
  return out.str();
}

std::string trace_csv(const std::vector<TracePoint>& trace, const Engine& engine) {
  const ScaledDesign scaled = scaled_design(engine);
  const double g = engine.material.g;
  const double time_unit = std::sqrt(engine.L2 / g);           // section 3 [s]
  const double energy_unit = engine.M * g * engine.L2;         // [J]
  const double drop = scaled.energy_drop();
  double energy0 = trace.empty() ? 0 : trace.front().snapshot.energy;
  bool released = false;
  std::ostringstream out;
  out << "phase,t_s,theta_deg,psi_deg,phi_deg,theta_dot_rad_s,psi_dot_rad_s,phi_dot_rad_s,"
         "FS_perp_mg,FR_Mg,FRh_Mg,FRv_Mg,FH_Mg,normal_mg,energy_J,energy_drift,"
         "counterweight_x_m,counterweight_y_m,tip_x_m,tip_y_m,projectile_x_m,projectile_y_m,"
         "E_counterweight_J,E_beam_J,E_projectile_kinetic_J,E_projectile_potential_J\n";
  for (const TracePoint& p : trace) {
    const Snapshot& s = p.snapshot;
    if (p.phase == Phase::released && !released) {  // without the projectile, energy is conserved anew
      released = true;
      energy0 = s.energy;
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
                          s.pivot_reaction.x,
                          s.pivot_reaction.y,
                          std::hypot(s.hinge_force.x, s.hinge_force.y),
                          s.normal_force / scaled.mu,
                          s.energy * energy_unit,
                          (s.energy - energy0) / drop,
                          cw.x, cw.y, tip.x, tip.y,
                          gone ? none : pr.x, gone ? none : pr.y,
                          s.energies.counterweight * energy_unit,
                          s.energies.beam * energy_unit,
                          s.energies.projectile_kinetic * energy_unit,
                          s.energies.projectile_potential * energy_unit};
    out << (p.phase == Phase::trough ? "I" : p.phase == Phase::lifted ? "II" : "III");
    for (double x : row) out << "," << (std::isnan(x) ? std::string() : format_number(finite_or_error(x)));
    out << "\n";
  }
  return out.str();
}

SitePoint site_point(Vec2 scaled, const Engine& engine) {
  return {-scaled.x * engine.L2, scaled.y * engine.L2 + pivot_height(engine)};
}

}  // namespace trebuchet
