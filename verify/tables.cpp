// optimize, derive-table and merge: the ab-initio optimum for a capacity, and tab:CPNC derived
// from optima along X, whole or in shards that merge joins.
#include <chrono>
#include <iostream>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/parallel.hpp"
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/records/table_json.hpp"
#include "trebuchet/app/input/text_input.hpp"

namespace trebuchet::verify {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Prints a table or sweep part; each X without an optimum is named on stderr and gives exit 3.
int print_derived(const nlohmann::ordered_json& json, const std::vector<double>& failed) {
  require_finite_json(json, "the table");
  std::cout << pretty_json(json);
  for (double X : failed)
    std::cerr << "trebuchet-verify: no optimum at X = " << format_number(X) << "; its reason is in the output, the fit used the other points\n";
  return failed.empty() ? exit_success : exit_code(Program::verify, ErrorKind::numerical);
}

}  // namespace

int run_optimize(const Options& o) {
  const OptimizeRequest request = optimize_request(o.design, settings_of(o));
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Optimum> optima = optimize(request);
  const double seconds = seconds_since(start);
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const Optimum& optimum : optima) {
    all.push_back(optimum_json(optimum, request.settings, seconds));
    if (o.format == Format::table) std::cout << optimum_table(optimum, request.settings, o.units) << "\n";
  }
  if (o.format == Format::json)
    std::cout << pretty_json(all);
  else
    std::cout << "wall time " << format_significant(seconds, 3) << " s\n";
  return exit_success;
}

int run_derive_table(const Options& o) {
  SweepPart part;
  part.origin = "the sweep";
  SweepSpec& spec = part.spec;
  spec = o.sweep;
  spec.theta_i_deg = o.design.theta_i_deg.value_or(standard_theta_i_deg);
  spec.F = o.design.F.value_or(standard_F);
  spec.machine = o.design.machine.value_or(MachineKind::hinged);
  if (spec.machine != MachineKind::hinged && o.design.F)
    throw Error(ErrorKind::usage,
                "{{F}}: the fixed counterweight's and the floating arm's tables hold the counterweight at the short arm's end; leave out {{F}}");
  spec.material = material_of(o.design, Material{});
  spec.criterion = settings_of(o).criterion;
  if (o.shard) part.shard = *o.shard;
  // The work, decided before the run: the shard's X points at about 1100 shots each (an optimum).
  const long points = (static_cast<long>(sweep_grid(spec).size()) - part.shard.k + part.shard.n) / part.shard.n;
  if (points * shots_per_sweep_point > max_run_shots)
    throw Error(ErrorKind::usage,
                "--X gives " + std::to_string(points) + " X points to this run, about " + std::to_string(points * shots_per_sweep_point) +
                    " shots, more than the " + std::to_string(max_run_shots) + " a run may take (about 30 s on two cores); give at most " +
                    std::to_string(max_run_shots / shots_per_sweep_point) +
                    " points a run: a coarser --X, or --shard k/N over several runs (docs/table_derivation.md)");
  const auto start = std::chrono::steady_clock::now();
  part.points = run_sweep(spec, part.shard, o.threads, progress_bar("X points"));
  int shots = 0;
  std::vector<double> failed;
  for (const SweepPoint& p : part.points) {
    shots += p.simulations;
    if (!p.error.empty()) failed.push_back(p.X);
  }
  std::cerr << "trebuchet-verify: " << part.points.size() << " X points, " << shots << " shots, " << format_significant(seconds_since(start), 3)
            << " s on " << thread_count(o.threads, part.points.size()) << " threads\n";
  if (o.shard) return print_derived(sweep_part_json(part), failed);
  const DerivedTable table = derive_table({part});
  return print_derived(derived_table_json(table), failed_points(table));
}

int run_merge(const Options& o) {
  std::vector<SweepPart> parts;
  for (const std::string& path : o.parts) {
    const std::string expected = "a part written by derive-table --shard k/N";
    parts.push_back(read_sweep_part(parse_json(read_text(path, expected), source_name(path), expected), "'" + path + "'"));
  }
  const DerivedTable table = derive_table(parts);
  return print_derived(derived_table_json(table), failed_points(table));
}

}  // namespace trebuchet::verify
