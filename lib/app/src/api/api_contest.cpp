// The contest's request (api.hpp): its own room, which the page's build leaves out with the
// contest and NLopt (lib/CMakeLists.txt).
#include <algorithm>
#include <cmath>
#include <tuple>

#include "api_input.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/app/api/api.hpp"
#include "trebuchet/app/output/contest_record.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/run/requests.hpp"

namespace trebuchet::api {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

namespace {

// machine "all": each machine's best by its name, or the error object of its refusal
// (error_json); a refusal that every machine gives alike (bad input) is thrown.
ordered_json each_machine_json(ContestRequest request) {
  const std::vector<MachineBest> each = contest_each_machine(request);
  const bool alike = std::all_of(each.begin(), each.end(), [&](const MachineBest& b) {
    return b.refusal && each.front().refusal->named_message() == b.refusal->named_message();
  });
  if (alike) throw *each.front().refusal;
  ordered_json answer = ordered_json::object();
  for (const MachineBest& b : each) {
    request.machine = b.machine;
    answer[machine_name(b.machine)] = b.best ? contest_json(*b.best, request, {}) : error_json(*b.refusal);
  }
  return answer;
}

}  // namespace

ordered_json contest(const json& request) {
  std::vector<std::string> known = keys_of(req_contest, op_optimize);
  for (const char* key :
       {"m", "D", "theta_i_deg", "theta", "box_width", "box_height", "rope_mass", "pouch_mass", "pin_friction", "projectile_diameter"})
    known.emplace_back(key);
  require_keys(request, known, "contest");
  DesignValues v = material_of_request(request, op_optimize);
  for (const auto& [member, key, dimension] : {std::tuple{&DesignValues::m, "m", UnitDimension::mass},
                                               {&DesignValues::D, "D", UnitDimension::length},
                                               {&DesignValues::box_width, "box_width", UnitDimension::length},
                                               {&DesignValues::box_height, "box_height", UnitDimension::length},
                                               {&DesignValues::projectile_diameter, "projectile_diameter", UnitDimension::length}})
    v.*member = positive_value(request, key, dimension);
  for (const auto& [member, key, dimension] : {std::tuple{&DesignValues::rope_mass, "rope_mass", UnitDimension::mass},
                                               {&DesignValues::pouch_mass, "pouch_mass", UnitDimension::mass},
                                               {&DesignValues::pin_friction, "pin_friction", UnitDimension::dimensionless}})
    v.*member = positive_value(request, key, dimension, true);
  v.theta_i_deg = read_value(request, request.contains("theta") ? "theta" : "theta_i_deg", UnitDimension::angle, "");
  const bool all_machines = request.contains(machine_key) && text_of(request[machine_key], machine_key) == "all";
  if (request.contains(machine_key) && !all_machines) v.machine = parse_machine(text_of(request[machine_key], machine_key), "{{machine}}");
  bool efficiency = false;
  if (request.contains("objective")) {
    efficiency = parse_efficiency_objective(text_of(request["objective"], "objective"), "{{objective}}");
  }
  ContestRequest r = contest_request(v, settings_of(request, req_contest), positive_value(request, "mb_per_m", UnitDimension::dimensionless),
                                     efficiency);
  for (std::size_t k = 0; k < contest_limit_count; ++k) {
    const char* key = contest_limit_key(static_cast<ContestLimit>(k));
    r.limits[k] = positive_value(request, key, setting_row(find_setting(key, req_contest)->id).dimension);
  }
  r.min_clearance = read_value(request, "min_clearance", UnitDimension::length, "").value_or(0);
  const double pareto = read_value(request, "pareto", UnitDimension::dimensionless, "").value_or(0);
  if (pareto != 0 && (!(pareto >= 2 && pareto <= 200) || pareto != std::floor(pareto)))
    throw Error(ErrorKind::bad_number, "{{pareto}} = " + format_significant(pareto, 6) + " must be a whole number from 2 to 200");
  if (all_machines) {
    if (pareto != 0)
      throw Error(ErrorKind::usage, "{{machine}} \"all\" sets the machines' best side by side; leave out {{pareto}}, or name one machine");
    return each_machine_json(r);
  }
  const auto [best, front] = contest_with_front(r, static_cast<int>(pareto));
  return contest_json(best, r, front);
}

}  // namespace trebuchet::api
