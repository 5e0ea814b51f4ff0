#include "trebuchet/app/records/schema.hpp"

#include <cmath>

#include "trebuchet/app/input/csv.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/error.hpp"

namespace trebuchet {

const char* project_version() { return TREBUCHET_PROJECT_VERSION; }

// A written number must be finite: JSON has no inf or nan, and neither has a spreadsheet. The
// calculator rejects extreme inputs before this; an engine read back is checked here once more.
void require_finite(const std::vector<Field>& fields) {
  for (const Field& field : fields)
    if (!std::isfinite(field.value))
      throw Error(ErrorKind::bad_number,
                  std::string("the engine's ") + field.key + " is beyond the range of numbers (about 1e-308 to 1e308); give values of ordinary size");
}

// The parts as built (FieldGroup::part), each in SI: the last CSV columns of the verifier, so
// that its CSV reads back.
std::vector<const InputField*> part_fields() {
  std::vector<const InputField*> parts;
  for (const InputField& field : input_fields())
    if (field.group == FieldGroup::part) parts.push_back(&field);
  return parts;
}

std::vector<std::string> part_columns() {
  std::vector<std::string> columns;
  for (const InputField* part : part_fields()) columns.push_back(csv_column_of(*part));
  return columns;
}

namespace {

// A field of an engine's record under its input's key and unit.
Field input(std::optional<double> DesignValues::*member, double value) {
  const InputField& field = field_of(member);
  return {field.key, value, field.unit};
}

}  // namespace

std::vector<Field> engine_fields(const Engine& e) {
  using V = DesignValues;
  const ScaledDesign s = scaled_design(e);
  return {input(&V::theta_i_deg, e.theta_i_deg),
          input(&V::F, s.F),
          input(&V::beta2, e.material.beta2),
          input(&V::L1, e.L1),
          input(&V::L2, e.L2),
          input(&V::L3, e.L3),
          input(&V::L4, e.L4),
          input(&V::D, e.D),
          input(&V::M, e.M),
          input(&V::m, e.m),
          input(&V::mb, e.mb),
          input(&V::Lb, beam_length(e)),
          input(&V::H, pivot_height(e)),
          input(&V::l, s.l),
          {"l4", s.l4},
          {"L", e.L3 / e.L2},
          {"mu", s.mu},
          {"mu_b", s.mu_b},
          {"K", s.K()},
          {"DeltaU", potential_energy_drop(e), "J"},
          input(&V::youngs_modulus, e.material.youngs_modulus),
          input(&V::wood_density, e.material.wood_density),
          input(&V::g, e.material.g)};
}

void write_engine(nlohmann::ordered_json& out, const Engine& engine) {
  const std::vector<Field> fields = engine_fields(engine);
  require_finite(fields);
  for (const Field& field : fields) out[field.key] = field.value;
  if (engine.psi_i_deg != 0) out[key_of(&DesignValues::psi_i_deg)] = engine.psi_i_deg;  // only a propped engine carries it
  if (engine.machine != MachineKind::hinged) out[machine_key] = machine_name(engine.machine);  // the paper's engine is the one without
  // The parts as built, as given, so that the engine reads back the same.
  using V = DesignValues;
  const EngineParts& p = engine.parts;
  const auto put = [&](std::optional<double> V::*member, double value) { out[key_of(member)] = value; };
  if (p.beam_cm) put(&V::beam_cm, *p.beam_cm);
  if (p.beam_inertia) put(&V::beam_inertia, *p.beam_inertia);
  if (p.beam_gyration) put(&V::beam_gyration, *p.beam_gyration);
  if (p.D_tip) put(&V::D_hinge, *p.D_hinge), put(&V::D_tip, *p.D_tip);
  if (p.box_width && p.box_height)
    put(&V::box_width, *p.box_width), put(&V::box_height, *p.box_height);  // the box, which gives the inertia
  else if (p.counterweight_inertia > 0)
    put(&V::counterweight_inertia, p.counterweight_inertia);
  if (p.axle.friction > 0 || p.axle.radius > 0) put(&V::axle_friction, p.axle.friction), put(&V::axle_radius, p.axle.radius);
  if (p.hinge.friction > 0 || p.hinge.radius > 0) put(&V::hinge_friction, p.hinge.friction), put(&V::hinge_radius, p.hinge.radius);
  if (p.trough_friction > 0) put(&V::trough_friction, p.trough_friction);
  if (p.rope_diameter > 0) put(&V::rope_diameter, p.rope_diameter), put(&V::rope_cd, p.rope_cd);
  if (p.rope_mass > 0) put(&V::rope_mass, p.rope_mass);
  if (p.pouch_mass > 0) put(&V::pouch_mass, p.pouch_mass);
  if (p.pin_friction > 0) put(&V::pin_friction, p.pin_friction);
  if (engine.material.modulus_of_rupture != Material{}.modulus_of_rupture) put(&V::modulus_of_rupture, engine.material.modulus_of_rupture);
  if (engine.machine == MachineKind::whipper) put(&V::rope_angle_deg, engine.whipper.rope_angle_deg);  // its start besides theta_i and H
  if (engine.projectile_diameter) put(&V::projectile_diameter, *engine.projectile_diameter);
}

// The parts as built, as write_engine gives them (empty where the engine has no such part).
std::vector<std::string> part_cells(const Engine& engine, int digits) {
  nlohmann::ordered_json written;
  write_engine(written, engine);
  std::vector<std::string> cells;
  for (const InputField* part : part_fields())
    cells.push_back(written.contains(part->key) ? csv_number(written[part->key].get<double>(), digits) : "");
  return cells;
}

std::string csv_column(const Field& field) { return *field.unit ? std::string(field.key) + "_" + field.unit : field.key; }

std::string csv_line(const std::vector<std::string>& cells) {
  std::string line;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (k) line += ',';
    append_csv_cell(line, cells[k]);
  }
  line += '\n';
  return line;
}

void require_finite_json(const nlohmann::ordered_json& json, const std::string& what) {
  if (json.is_number_float() && !std::isfinite(json.get<double>()))
    throw Error(ErrorKind::data_file, what + " holds a number that is not finite; nothing was written");
  if (json.is_structured())
    for (auto it = json.begin(); it != json.end(); ++it)
      require_finite_json(*it, what + (json.is_object() ? "." + it.key() : "[" + std::to_string(std::distance(json.begin(), it)) + "]"));
}

}  // namespace trebuchet
