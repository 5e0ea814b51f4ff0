// contest: the best engine of a machine within a contest's limits, and the Pareto front of range
// against the axle's load (contest.hpp, docs/machines.md).
#include <cmath>
#include <iostream>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/app/output/contest_record.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/input/text_input.hpp"

namespace trebuchet::verify {

int run_contest(const Options& o) {
  ContestRequest request = contest_request(o.design, settings_of(o), o.beam_per_m, o.efficiency);
  request.limits = o.limits;
  request.min_clearance = o.min_clearance.value_or(0);
  if (!o.plot.empty() && o.pareto == 0) throw Error(ErrorKind::usage, "--plot draws the Pareto front; give --pareto 20 (its points) too");
  if (o.all_machines) {  // each machine's best, side by side: the whipper is not designed by search (docs/machines.md)
    if (!o.plot.empty() || o.pareto > 0)
      throw Error(ErrorKind::usage, "--machine all sets the machines' best side by side; drop --pareto and --plot, or name one machine");
    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    int refused = 0, code = exit_success;
    for (const MachineBest& each : contest_each_machine(request)) {
      request.machine = each.machine;
      const std::string heading = "== " + machine_name(each.machine) + "\n";
      if (each.best) {
        if (o.format == Format::json)
          all.push_back(contest_json(*each.best, request, {}));
        else
          std::cout << heading << contest_table(*each.best, request, {}, o.units) << "\n";
        continue;
      }
      ++refused, code = std::max(code, exit_code(Program::verify, each.refusal->kind()));
      const std::string message = each.refusal->message(option_word);
      std::cerr << "trebuchet-verify: " << machine_name(each.machine) << ": " << message << "\n";
      if (o.format == Format::json)
        all.push_back({{machine_key, machine_name(each.machine)}, {"error", message}});
      else
        std::cout << heading << message << "\n\n";
    }
    if (o.format == Format::json) std::cout << pretty_json(all);
    return refused == static_cast<int>(std::size(searched_machines)) ? code : exit_success;
  }
  const auto [best, front] = contest_with_front(request, o.pareto);
  if (!o.plot.empty()) write_picture_folder(o.plot, pareto_pictures(front, request), {"pareto.gp"});
  if (o.format == Format::json)
    std::cout << pretty_json(contest_json(best, request, front));
  else
    std::cout << contest_table(best, request, front, o.units);
  return exit_success;
}

}  // namespace trebuchet::verify
