#include "trebuchet/app/records/design_record.hpp"

#include <cstdint>
#include <cstring>

#include "trebuchet/format.hpp"
#include "trebuchet/app/input/csv.hpp"
#include "trebuchet/app/input/names.hpp"

namespace trebuchet {
namespace {

std::vector<Field> design_fields(const OptimalEngine& d) {
  std::vector<Field> fields = {{"R", d.capacity.R, "m"}, {"T", d.capacity.T, "J"}, {"X", d.coordinates.X}, {"Y", d.coordinates.Y}};
  for (const Field& field : engine_fields(d.engine)) fields.push_back(field);
  fields.push_back({"amplification", d.amplification});
  return fields;
}

}  // namespace

void require_finite(const OptimalEngine& design) { require_finite(design_fields(design)); }

nlohmann::ordered_json design_json(const OptimalEngine& design) {
  const std::vector<Field> fields = design_fields(design);
  require_finite(fields);
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const Field& field : fields) out[field.key] = field.value;
  if (design.engine.machine != MachineKind::hinged) out[machine_key] = machine_name(design.engine.machine);
  out["branch"] = branch_name(design.branch);
  out["air"] = "vacuum";  // R and T: the paper's, in vacuum
  if (design.scaled_from)
    out["scaled_from"] = {{"factor", design.scaled_from->factor}, {"R", design.scaled_from->full_size.R}, {"T", design.scaled_from->full_size.T}};
  if (design.branch_steps) {
    nlohmann::ordered_json steps = nlohmann::ordered_json::object();
    for (Param param : all_params) steps[std::string(param_name(param))] = (*design.branch_steps)[index(param)];
    out["branch_steps"] = steps;
  }
  out["warnings"] = design.warnings;
  out[version_key] = project_version();
  return out;
}

std::vector<std::string> design_csv_header(MachineKind machine) {
  std::vector<std::string> header;
  for (const Field& field : design_fields(OptimalEngine{})) header.push_back(csv_column(field));
  header.insert(header.end(), {"branch", "warnings", "air"});
  if (machine != MachineKind::hinged) header.push_back(machine_key);
  return header;
}

std::vector<std::string> design_output_names() {
  std::vector<std::string> names = design_csv_header();
  for (const Field& field : design_fields(OptimalEngine{})) names.push_back(field.key);
  names.insert(names.end(), {"scaled_from", "branch_steps", "line", "error", "exit_code", machine_key});
  return names;
}

std::string design_csv_text(const OptimalEngine& design, int digits) {
  const std::vector<Field> fields = design_fields(design);
  require_finite(fields);
  std::string text;
  text.reserve(16 * fields.size() + 64);
  // A batch's rows share their material, angle and arm fraction: a value the same, bit for bit,
  // as the previous row's in its column is copied from that row's text, not formatted again
  // (formatting the numbers is most of a row's time).
  struct Written {
    std::uint64_t bits = 0;
    int digits = 0;
    std::string text;
  };
  thread_local std::vector<Written> previous;
  previous.resize(fields.size());
  for (std::size_t k = 0; k < fields.size(); ++k) {
    Written& last = previous[k];
    std::uint64_t bits = 0;  // std::bit_cast, which Emscripten's library lacks
    std::memcpy(&bits, &fields[k].value, sizeof bits);
    if (last.digits != digits || last.bits != bits) {
      last.text.clear();
      append_csv_number(last.text, fields[k].value, digits);
      last.bits = bits, last.digits = digits;
    }
    text += last.text;
    text += ',';
  }
  append_csv_cell(text, branch_name(design.branch));
  text += ',';
  append_csv_cell(text, join(design.warnings, "; "));
  text += ",vacuum";
  if (design.engine.machine != MachineKind::hinged) text += "," + machine_name(design.engine.machine);
  return text;
}

}  // namespace trebuchet
