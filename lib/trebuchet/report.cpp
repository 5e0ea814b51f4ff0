#include "trebuchet/report.hpp"

#include <cmath>
#include <functional>
#include <vector>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {
namespace {

struct Column {
  const char* name;
  std::function<double(const OptimalEngine&)> value;
};

// The numeric columns shared by JSON and CSV, in print order.
const std::vector<Column>& numeric_columns() {
  static const std::vector<Column> columns = {
      {"R", [](const OptimalEngine& d) { return d.R; }},
      {"T", [](const OptimalEngine& d) { return d.T; }},
      {"X", [](const OptimalEngine& d) { return d.X; }},
      {"Y", [](const OptimalEngine& d) { return d.Y; }},
      {"theta_i_deg", [](const OptimalEngine& d) { return d.engine.theta_i_deg; }},
      {"F", [](const OptimalEngine& d) { return d.F; }},
      {"beta2", [](const OptimalEngine& d) { return d.material.beta2; }},
      {"L1", [](const OptimalEngine& d) { return d.engine.L1; }},
      {"L2", [](const OptimalEngine& d) { return d.engine.L2; }},
      {"L3", [](const OptimalEngine& d) { return d.engine.L3; }},
      {"L4", [](const OptimalEngine& d) { return d.engine.L4; }},
      {"D", [](const OptimalEngine& d) { return d.engine.D; }},
      {"M", [](const OptimalEngine& d) { return d.engine.M; }},
      {"m", [](const OptimalEngine& d) { return d.engine.m; }},
      {"mb", [](const OptimalEngine& d) { return d.engine.mb; }},
      {"Lb", [](const OptimalEngine& d) { return beam_length(d.engine); }},
      {"H", [](const OptimalEngine& d) { return pivot_height(d.engine); }},
      {"l", [](const OptimalEngine& d) { return scaled_design(d.engine).l; }},
      {"l4", [](const OptimalEngine& d) { return scaled_design(d.engine).l4; }},
      {"L", [](const OptimalEngine& d) { return scaled_design(d.engine).L; }},
      {"mu", [](const OptimalEngine& d) { return scaled_design(d.engine).mu; }},
      {"mu_b", [](const OptimalEngine& d) { return scaled_design(d.engine).mu_b; }},
      {"K", [](const OptimalEngine& d) { return scaled_design(d.engine).K; }},
      {"DeltaU", [](const OptimalEngine& d) { return potential_energy_drop(d.engine, d.material.g); }},
      {"youngs_modulus_Pa", [](const OptimalEngine& d) { return d.material.youngs_modulus; }},
      {"wood_density_kg_m3", [](const OptimalEngine& d) { return d.material.wood_density; }},
      {"g", [](const OptimalEngine& d) { return d.material.g; }},
      {"amplification", [](const OptimalEngine& d) { return d.amplification; }},
  };
  return columns;
}

std::string joined_warnings(const OptimalEngine& design) {
  std::string text;
  for (const std::string& w : design.warnings) text += (text.empty() ? "" : "; ") + w;
  return text;
}

std::string csv_quoted(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string with_unit(double value, const char* unit) { return format_significant(value, 4) + " " + unit; }

std::string mass_text(double kg) { return kg >= 1000 ? with_unit(kg / 1000, "t") : with_unit(kg, "kg"); }

std::string energy_text(double joules) {
  if (joules >= 1e6) return with_unit(joules / 1e6, "MJ");
  if (joules >= 1e3) return with_unit(joules / 1e3, "kJ");
  return with_unit(joules, "J");
}

std::string cell(const std::string& label, const std::string& value) {
  std::string text = label + " = " + value;
  return text + std::string(text.size() < 18 ? 18 - text.size() : 1, ' ');
}

}  // namespace

void require_finite(const OptimalEngine& design) {
  for (const Column& column : numeric_columns())
    if (!std::isfinite(column.value(design)))
      throw Error(ErrorKind::numerical, std::string("internal error: ") + column.name +
                                            " is not finite; please report the command that caused it");
}

nlohmann::ordered_json design_json(const OptimalEngine& design) {
  require_finite(design);
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const Column& column : numeric_columns()) out[column.name] = column.value(design);
  out["branch"] = branch_name(design.branch);
  if (design.branch_steps) {
    nlohmann::ordered_json steps = nlohmann::ordered_json::object();
    for (Param param : all_params) steps[std::string(param_name(param))] = (*design.branch_steps)[index(param)];
    out["branch_steps"] = steps;
  }
  out["warnings"] = design.warnings;
  return out;
}

std::string design_csv_header() {
  std::string header;
  for (const Column& column : numeric_columns()) header += std::string(column.name) + ",";
  return header + "branch,warnings";
}

std::string design_csv_row(const OptimalEngine& design) {
  require_finite(design);
  std::string row;
  for (const Column& column : numeric_columns()) row += format_number(column.value(design)) + ",";
  return row + std::string(branch_name(design.branch)) + "," + (design.warnings.empty() ? "" : csv_quoted(joined_warnings(design)));
}

std::string design_table(const OptimalEngine& design) {
  require_finite(design);
  const Engine& e = design.engine;
  const ScaledDesign s = scaled_design(e);
  std::string t;
  t += "Optimal engine from tab:CPNC: theta_i = " + format_number(e.theta_i_deg) + " deg, F = " +
       format_fraction(design.F) + ", beta2 = " + format_fraction(design.material.beta2) + ", " +
       (design.branch == Branch::none ? std::string("segment") : std::string(branch_name(design.branch)) + " branch") +
       " X in [" + format_number(design.segment_X_min) + ", " + format_number(design.segment_X_max) + "]\n";
  t += "  capacity       " + cell("R", with_unit(design.R, "m")) + cell("T", energy_text(design.T)) +
       cell("X", format_significant(design.X, 3)) + cell("Y", format_significant(design.Y, 3)) + "\n";
  t += "  beam           " + cell("L1", with_unit(e.L1, "m")) + cell("L2", with_unit(e.L2, "m")) +
       cell("Lb", with_unit(beam_length(e), "m")) + cell("H", with_unit(pivot_height(e), "m")) + "\n";
  t += "                 " + cell("D", with_unit(e.D, "m")) + cell("mb", mass_text(e.mb)) + "\n";
  t += "  counterweight  " + cell("M", mass_text(e.M)) + cell("L3", with_unit(e.L3, "m")) + "\n";
  t += "  sling          " + cell("L4", with_unit(e.L4, "m")) + "\n";
  t += "  projectile     " + cell("m", mass_text(e.m)) + "\n";
  t += "  scaled         " + cell("l", format_significant(s.l, 4)) + cell("l4", format_significant(s.l4, 4)) +
       cell("L", format_significant(s.L, 4)) + "\n";
  t += "                 " + cell("mu", format_significant(s.mu, 4)) + cell("mu_b", format_significant(s.mu_b, 4)) +
       cell("K", format_significant(s.K, 4)) + "\n";
  t += "  stored energy  " + cell("DeltaU", energy_text(potential_energy_drop(e, design.material.g))) + "(eq:DU)\n";
  if (design.material.g != Material{}.g || design.material.wood_density != Material{}.wood_density ||
      design.material.youngs_modulus != Material{}.youngs_modulus)
    t += "  material       " + cell("E", with_unit(design.material.youngs_modulus / 1e9, "GPa")) +
         cell("rho_d", with_unit(design.material.wood_density, "kg/m3")) + cell("g", with_unit(design.material.g, "m/s2")) + "\n";
  for (const std::string& w : design.warnings) t += "warning: " + w + "\n";
  return t;
}

}  // namespace trebuchet
