#include "trebuchet/app/records/shot_record.hpp"

#include <cmath>

#include "trebuchet/air.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/app/input/csv.hpp"
#include "trebuchet/app/input/names.hpp"

namespace trebuchet {

nlohmann::ordered_json settings_json(const ShotSettings& settings, const Engine* engine) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  if (settings.air) {
    const Air& air = *settings.air;
    out["air"] = {{"density", air.density},
                  {"drag_coefficient", air.drag_coefficient ? nlohmann::ordered_json(*air.drag_coefficient) : nlohmann::ordered_json("Cd(Re)")},
                  {"projectile_density", air.projectile_density}};
    if (engine) out["air"]["projectile_diameter"] = sphere_diameter(engine->m, air.projectile_density);
    out["air"]["wind"] = air.wind;
    if (settings.drag_in_sling) out["air"]["drag_in_sling"] = true;  // the air acts before the release too
  } else {
    out["air"] = "vacuum";
  }
  out["range_from"] = settings.range_from_release ? "release" : "pivot";
  if (engine) {
    out["g"] = engine->material.g;
    out["theta_i_deg"] = engine->theta_i_deg;
    out["F"] = arm_fraction(*engine);
  }
  out["release"] = release_name(settings.criterion.release);
  if (const auto& at = settings.release_at)  // given: the release is there, and "release" names what Q is
    out["release_at"] = {{"by", release_by_name(at->by)}, {"value", at->value}, {"unit", at->by == ReleaseBy::time ? "s" : "deg"}};
  out["n"] = settings.criterion.n;
  out["target_level"] = settings.target_level;
  // The integrator, where it is not the default, so that the record reads back as the same shot.
  const IntegratorSettings standard;
  if (settings.integrator.stepper != standard.stepper) out["stepper"] = stepper_name(settings.integrator.stepper);
  if (settings.integrator.rtol != standard.rtol) out["rtol"] = settings.integrator.rtol;
  if (settings.integrator.atol != standard.atol) out["atol"] = settings.integrator.atol;
  return out;
}

nlohmann::ordered_json assumptions_json(const Engine& engine, const ShotSettings& given) {
  return settings_json(settings_for(engine, given), &engine);  // a ball of given size sets the projectile's density
}

namespace {

// The pin angle at the release (verification.hpp), apart from the input pin_angle_deg that sets one.
constexpr const char* pin_angle_column = "pin_angle_at_release_deg";
// The pin to bend for the release (Verification::pin_to_bend_deg) and Siano's range efficiency
// (Verification::range_efficiency): in JSON beside the release's angles and eps and Q, in CSV last.
constexpr const char* pin_to_bend_key = "pin_to_bend_deg";
constexpr const char* range_efficiency_keys[2] = {"range_efficiency", "range_efficiency_counterweight"};
// The whipper's own time, in its JSON record beside t_liftoff (when its projectile leaves the arm) [s].
constexpr const char* counterweight_free_key = "t_counterweight_free";

// The inputs that set a release (FieldGroup::release), in the table's order.
std::vector<const InputField*> release_fields() {
  std::vector<const InputField*> fields;
  for (const InputField& field : input_fields())
    if (field.group == FieldGroup::release) fields.push_back(&field);
  return fields;
}

// The figures of a shot, in the order of the JSON and CSV records. Throws Error(numerical) for
// one that is not finite.
std::vector<Field> verification_fields(const Verification& v) {
  std::vector<Field> fields = {{"R", v.capacity.R, "m"},
                               {"T", v.capacity.T, "J"},
                               {"R_vacuum", v.R_vacuum, "m"},
                               {"T_vacuum", v.T_vacuum, "J"},
                               {"eps", v.eps},
                               {"Q", v.Q},
                               {"force_factor", v.force_factor},
                               {"v", v.v, "m_s"},
                               {"h", v.h, "m"},
                               {"x", v.x, "m"},
                               {"A_deg", v.A_deg},
                               {"t_release", v.t_release, "s"},
                               {"t_liftoff", v.t_liftoff, "s"},
                               {"FS_perp_mg", v.FS_perp_mg},
                               {"FR_Mg", v.FR_Mg},
                               {"dFRh_Mg", v.dFRh_Mg},
                               {"FS_perp", v.FS_perp, "N"},
                               {"FR", v.FR, "N"},
                               {"dFRh", v.dFRh, "N"}};
  // The builder's loads (verification.hpp), each with its time; the beam's strength, 0 without a beam.
  const char* load_names[load_count][2] = {
      {"sling_tension", "t_sling_tension"}, {"hinge_force", "t_hinge_force"}, {"pivot_force", "t_pivot_force"}, {"beam_moment", "t_beam_moment"}};
  for (int k = 0; k < load_count; ++k) {
    fields.push_back({load_names[k][0], v.loads[k].value, k == beam_moment_load ? "N_m" : "N"});
    fields.push_back({load_names[k][1], v.loads[k].t, "s"});
  }
  const BeamStrength beam = v.beam.value_or(BeamStrength{});
  fields.insert(fields.end(),
                {{"beam_D", beam.D, "m"},
                 {"beta2_implied", beam.beta2},
                 {"strain_at_rest", beam.strain_at_rest},
                 {"strain_peak", beam.strain_peak},
                 {"stress_at_rest", beam.stress_at_rest, "Pa"},
                 {"stress_peak", beam.stress_peak, "Pa"},
                 {"rupture_margin", beam.margin},
                 {"energy_drift", v.energy_drift}});
  for (const Field& field : fields)
    if (!std::isfinite(field.value)) throw Error(ErrorKind::numerical, std::string("the result ") + field.key + " is not finite; tighten {{rtol}}");
  return fields;
}

// Where Delta U went by the release (Verification::EnergyBudget), and the air in flight: the
// last CSV columns, so that the columns before them keep their places; in JSON, "energy".
std::vector<Field> energy_fields(const Verification& v) {
  const Verification::EnergyBudget& e = v.energy;
  std::vector<Field> fields = {{"energy_projectile", e.projectile, "J"},          {"energy_engine", e.engine, "J"},
                               {"loss_axle", e.losses[axle_loss], "J"},           {"loss_hinge", e.losses[hinge_loss], "J"},
                               {"loss_trough", e.losses[trough_loss], "J"},       {"loss_sling_drag", e.losses[projectile_drag_loss], "J"},
                               {"loss_rope_drag", e.losses[rope_drag_loss], "J"}, {"loss_flight_drag", e.flight_drag, "J"}};
  for (const Field& field : fields)
    if (!std::isfinite(field.value)) throw Error(ErrorKind::numerical, std::string("the result ") + field.key + " is not finite; tighten {{rtol}}");
  return fields;
}

// The check against a predicted capacity, as CSV fields (empty when there is none).
std::vector<Field> check_fields(const std::optional<CapacityCheck>& check) {
  const CapacityCheck c = check.value_or(CapacityCheck{});
  return {{"predicted_R", c.predicted.R, "m"}, {"predicted_T", c.predicted.T, "J"}, {"deviation_R", c.deviation_R}, {"deviation_T", c.deviation_T}};
}

}  // namespace

std::vector<std::string> verification_csv_header() {
  std::vector<std::string> header;
  const Verification v{};
  for (const auto& fields : {engine_fields(Engine{}), verification_fields(v), check_fields(std::nullopt)})
    for (const Field& field : fields) header.push_back(csv_column(field));
  header.insert(header.end(), {"pass", "air", "release", "n", "target_level_m", "warnings", "notes"});
  for (const Field& field : energy_fields(v)) header.push_back(csv_column(field));
  for (const std::string& column : part_columns()) header.push_back(column);
  header.push_back("psi_i_deg");
  header.push_back(pin_angle_column);  // after the earlier columns, so that they keep their places
  for (const InputField* field : release_fields()) header.push_back(csv_column_of(*field));  // a given release, which reads back
  header.push_back(machine_key);
  header.insert(header.end(), {"clearance_geometric_m", "clearance_in_shot_m"});  // Verification::Clearance: the columns before keep their places
  header.insert(header.end(), {range_efficiency_keys[0], range_efficiency_keys[1], pin_to_bend_key, "energy_sling_J"});  // issue 48
  // Issue 50, last: with release, n and target_level_m, the settings a CSV reads back with; and
  // the beam's wood's strength, an input beside the material's others.
  header.push_back("range_from");
  header.push_back(csv_column_of(field_of(&DesignValues::modulus_of_rupture)));
  return header;
}

std::vector<std::string> verification_csv_row(const Engine& engine, const ShotSettings& settings, const Verification& v,
                                              const std::optional<CapacityCheck>& check, int digits) {
  std::vector<Field> engine_part = engine_fields(engine);
  require_finite(engine_part);
  std::vector<std::string> row;
  for (const auto& fields : {engine_part, verification_fields(v)})
    for (const Field& field : fields) row.push_back(csv_number(field.value, digits));
  for (const Field& field : check_fields(check)) row.push_back(check ? csv_number(field.value, digits) : "");
  const nlohmann::ordered_json assumed = assumptions_json(engine, settings);
  const std::optional<Air>& as_shot = settings_for(engine, settings).air;  // a ball of given size sets its density
  const std::string air = as_shot ? describe_air(*as_shot, engine.m) : "vacuum";
  row.insert(row.end(),
             {check ? (check->pass ? "yes" : "no") : "", air, assumed["release"].get<std::string>(), csv_number(settings.criterion.n, digits),
              csv_number(settings.target_level, digits), join(v.warnings, "; "), join(v.notes, "; ")});
  for (const Field& field : energy_fields(v)) row.push_back(csv_number(field.value, digits));
  for (const std::string& cell : part_cells(engine, digits)) row.push_back(cell);
  row.push_back(csv_number(engine.psi_i_deg, digits));
  row.push_back(csv_number(v.pin_angle_deg, digits));
  for (const InputField* field : release_fields()) {
    const bool given = settings.release_at && &release_field(settings.release_at->by) == field;
    row.push_back(given ? csv_number(settings.release_at->value, digits) : "");
  }
  row.push_back(machine_name(engine.machine));
  row.push_back(csv_number(v.clearance.geometric, digits));
  row.push_back(v.clearance.in_shot ? csv_number(*v.clearance.in_shot, digits) : "");
  for (const double value : {v.range_efficiency, v.range_efficiency_counterweight, v.pin_to_bend_deg, v.energy.sling})
    row.push_back(csv_number(value, digits));
  row.push_back(assumed["range_from"].get<std::string>());
  row.push_back(csv_number(engine.material.modulus_of_rupture, digits));
  return row;
}

std::vector<std::string> verification_output_names() {
  std::vector<std::string> names = verification_csv_header();
  for (const Field& field : verification_fields(Verification{})) names.push_back(field.key);
  names.push_back(pin_angle_column);
  names.push_back(counterweight_free_key);
  names.insert(names.end(), {"predicted", "deviation", "tolerance", "against", "engine", "assumptions", "error", "exit_code", "energy", "clearance"});
  return names;
}

void require_finite(const Verification& v) {
  verification_fields(v);
  energy_fields(v);
}

nlohmann::ordered_json verification_json(const Verification& v, const std::optional<CapacityCheck>& check) {
  nlohmann::ordered_json out;
  for (const Field& field : verification_fields(v)) {
    out[field.key] = field.value;
    if (field.key == std::string("A_deg"))
      out[pin_angle_column] = v.pin_angle_deg, out[pin_to_bend_key] = v.pin_to_bend_deg;  // the release's angles together
    if (field.key == std::string("Q"))  // beside eps and Q
      out[range_efficiency_keys[0]] = v.range_efficiency, out[range_efficiency_keys[1]] = v.range_efficiency_counterweight;
    if (field.key == std::string("t_liftoff") && v.t_counterweight_free) out[counterweight_free_key] = *v.t_counterweight_free;  // the whipper's
  }
  const Verification::EnergyBudget& e = v.energy;
  out["energy"] = {{"delta_U", e.delta_U},
                   {"projectile", e.projectile},
                   {"engine", e.engine},
                   {"sling", e.sling},
                   {"losses",
                    {{"axle", e.losses[axle_loss]},
                     {"hinge", e.losses[hinge_loss]},
                     {"trough", e.losses[trough_loss]},
                     {"sling_drag", e.losses[projectile_drag_loss]},
                     {"rope_drag", e.losses[rope_drag_loss]}}},
                   {"flight_drag", e.flight_drag}};
  out["clearance"] = {{"geometric", v.clearance.geometric},
                      {"in_shot", v.clearance.in_shot ? nlohmann::ordered_json(*v.clearance.in_shot) : nlohmann::ordered_json()},
                      {"buildable", v.clearance.buildable()}};
  out["warnings"] = v.warnings;
  out["notes"] = v.notes;
  if (check) {
    out["predicted"] = {{"R", check->predicted.R}, {"T", check->predicted.T}};
    out["deviation"] = {{"R", check->deviation_R}, {"T", check->deviation_T}};
    out["tolerance"] = check->tolerance;
    out["against"] = check->as_measured ? "measured" : "vacuum";  // fit's requested capacity, or the calculator's in vacuum
    out["pass"] = check->pass;
  }
  out[version_key] = project_version();
  return out;
}

}  // namespace trebuchet
