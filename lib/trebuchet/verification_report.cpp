#include "trebuchet/verification_report.hpp"

#include <cmath>
#include <sstream>

#include "trebuchet/dynamics.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {
namespace {

double checked(double value, const char* key) {
  if (!std::isfinite(value)) throw Error(ErrorKind::numerical, std::string("the result ") + key + " is not finite; tighten --rtol");
  return value;
}

double degrees(double radians) { return radians * 180 / M_PI; }

}  // namespace

CapacityCheck check_capacity(const Verification& v, double R, double T, double tolerance) {
  CapacityCheck c;
  c.R = R, c.T = T, c.tolerance = tolerance;
  c.deviation_R = v.R / R - 1;
  c.deviation_T = v.T / T - 1;
  c.pass = std::abs(c.deviation_R) <= tolerance && std::abs(c.deviation_T) <= tolerance;
  return c;
}

nlohmann::ordered_json verification_json(const Verification& v, const std::optional<CapacityCheck>& check) {
  nlohmann::ordered_json out;
  const std::pair<const char*, double> fields[] = {
      {"R", v.R}, {"T", v.T}, {"eps", v.eps}, {"Q", v.Q}, {"force_factor", v.force_factor}, {"v", v.v}, {"h", v.h},
      {"x", v.x}, {"A_deg", v.A_deg}, {"t_release", v.t_release}, {"t_liftoff", v.t_liftoff}, {"FS_perp_mg", v.FS_perp_mg},
      {"FR_Mg", v.FR_Mg}, {"dFRh_Mg", v.dFRh_Mg}, {"energy_drift", v.energy_drift}};
  for (const auto& [key, value] : fields) out[key] = checked(value, key);
  if (check) {
    out["predicted"] = {{"R", check->R}, {"T", check->T}};
    out["deviation"] = {{"R", check->deviation_R}, {"T", check->deviation_T}};
    out["tolerance"] = check->tolerance;
    out["pass"] = check->pass;
  }
  return out;
}

std::string verification_table(const Verification& v, const std::optional<CapacityCheck>& check) {
  verification_json(v, check);  // the same finiteness check as JSON
  auto sig = [](double x, int digits = 5) { return format_significant(x, digits); };
  std::ostringstream out;
  out << "R = " << sig(v.R) << " m   T = " << sig(v.T / 1e3) << " kJ   at the target level\n"
      << "eps = " << sig(100 * v.eps, 4) << " %   Q = " << sig(100 * v.Q, 4) << " %   F = " << sig(v.force_factor, 4) << "\n"
      << "release: v = " << sig(v.v, 4) << " m/s, h = " << sig(v.h, 4) << " m, x = " << sig(v.x, 4)
      << " m (behind the pivot if > 0), A = " << sig(v.A_deg, 4) << " deg\n"
      << "times: lift-off " << sig(v.t_liftoff, 4) << " s, release " << sig(v.t_release, 4) << " s\n"
      << "forces: F_S_perp = " << sig(v.FS_perp_mg, 4) << " mg, F_R = " << sig(v.FR_Mg, 4) << " Mg, dF_Rh = " << sig(v.dFRh_Mg, 4)
      << " Mg\n"
      << "energy drift: " << sig(v.energy_drift, 2) << " of Delta U\n";
  if (check) {
    out << "predicted: R = " << sig(check->R) << " m (" << (check->deviation_R >= 0 ? "+" : "") << sig(100 * check->deviation_R, 3)
        << " %), T = " << sig(check->T / 1e3) << " kJ (" << (check->deviation_T >= 0 ? "+" : "") << sig(100 * check->deviation_T, 3)
        << " %): " << (check->pass ? "pass" : "FAIL") << " at tolerance " << sig(100 * check->tolerance, 3) << " %\n";
  }
  return out.str();
}

nlohmann::ordered_json engine_json(const Engine& e) {
  nlohmann::ordered_json out;
  out["theta_i_deg"] = e.theta_i_deg;
  out["F"] = arm_fraction(e);
  out["L1"] = e.L1;
  out["L2"] = e.L2;
  out["L3"] = e.L3;
  out["L4"] = e.L4;
  out["D"] = e.D;
  out["M"] = e.M;
  out["m"] = e.m;
  out["mb"] = e.mb;
  return out;
}

std::string engine_table(const Engine& e) {
  auto sig = [](double x) { return format_significant(x, 4); };
  std::ostringstream out;
  out << "  Lb = " << sig(beam_length(e)) << " m, H = " << sig(pivot_height(e)) << " m, L1 = " << sig(e.L1) << " m, L2 = " << sig(e.L2)
      << " m, L3 = " << sig(e.L3) << " m, L4 = " << sig(e.L4) << " m\n"
      << "  M = " << sig(e.M) << " kg, m = " << sig(e.m) << " kg, mb = " << sig(e.mb) << " kg, D = " << format_significant(e.D, 3) << " m\n";
  return out.str();
}

std::string trace_csv(const std::vector<TracePoint>& trace, const Engine& engine, double g) {
  const ScaledEngine scaled = ScaledEngine::from(engine);
  const double time_unit = std::sqrt(engine.L2 / g);           // section 3 [s]
  const double energy_unit = engine.M * g * engine.L2;         // [J]
  const double drop = scaled.energy_drop();
  double energy0 = trace.empty() ? 0 : trace.front().snapshot.energy;
  bool released = false;
  std::ostringstream out;
  out << "phase,t_s,theta_deg,psi_deg,phi_deg,theta_dot_rad_s,psi_dot_rad_s,phi_dot_rad_s,"
         "FS_perp_mg,FR_Mg,FRh_Mg,FRv_Mg,FH_Mg,normal_mg,energy_J,energy_drift\n";
  for (const TracePoint& p : trace) {
    const Snapshot& s = p.snapshot;
    if (p.phase == Phase::released && !released) {  // without the projectile, energy is conserved anew
      released = true;
      energy0 = s.energy;
    }
    const double row[] = {p.t * time_unit,
                          degrees(p.state.theta),
                          degrees(p.state.psi),
                          degrees(p.state.phi),
                          p.state.theta_dot / time_unit,
                          p.state.psi_dot / time_unit,
                          p.state.phi_dot / time_unit,
                          s.sling_perpendicular / scaled.mu,
                          std::hypot(s.pivot_reaction.x, s.pivot_reaction.y),
                          s.pivot_reaction.x,
                          s.pivot_reaction.y,
                          std::hypot(s.hinge_force.x, s.hinge_force.y),
                          s.normal_force / scaled.mu,
                          s.energy * energy_unit,
                          (s.energy - energy0) / drop};
    out << (p.phase == Phase::trough ? "I" : p.phase == Phase::lifted ? "II" : "III");
    for (double x : row) out << "," << format_number(checked(x, "in the series"));
    out << "\n";
  }
  return out.str();
}

}  // namespace trebuchet
