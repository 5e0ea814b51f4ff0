#include "options.hpp"

#include <algorithm>
#include <thread>

#include "flags.hpp"
#include "option_groups.hpp"
#include "program.hpp"

namespace trebuchet::verify {

Subcommands declare_subcommands(CLI::App& app, Options& o) {
  o.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  Subcommands s;
  s.shot = app.add_subcommand("shot",
                              "range, energy, efficiency, forces and quality at the best release of a design "
                              "(a JSON file, - for stdin, or flags), checked against a predicted capacity");
  s.fit = app.add_subcommand("fit", "keep a design's shape (l, l4, mu_b, theta_i, F); fit mu and the size to --R and --T, then shoot");
  s.optimize = app.add_subcommand("optimize", "the ab-initio optimum for --R and --T (or --R and --m) at --theta and --F (section 5)");
  s.derive_table = app.add_subcommand("derive-table",
                                      "re-derive tab:CPNC for --theta and --F: optimise along --X and fit eq:f_ZX "
                                      "(JSON for the calculator's --table)");
  s.merge = app.add_subcommand("merge", "join the parts written by derive-table --shard into one table");
  s.complete = app.add_subcommand("complete",
                                  "complete an engine from what a source attests (any of --Lb --L1 --L2 --H --l --L4 --M --m --mb --D "
                                  "--theta --F): keep those, choose the rest for the highest Q (or --quality range)");

  for (CLI::App* sub : {s.shot, s.fit}) {
    const bool shot = sub == s.shot;
    engine_options(sub, o, shot);
    if (shot) input_options(sub, o, op_shot, {FieldGroup::release, FieldGroup::part}, true);
    target_level_option(sub, o, shot);
    threads_option(sub, o, "threads for an array of designs (default: the cores); the output is the same on any number");
    release_options(sub, o);
    integrator_options(sub, o);
    format_option(sub, o, true);
    material_options(sub, o, "the design", !shot);
  }
  air_and_sampling_options(s.shot, o);
  air_options(s.fit, o);

  s.calibrate = app.add_subcommand("calibrate",
                                   "fit an engine's friction to the range it was measured to throw (--measured 34.4m±1.5m), "
                                   "report the losses, and predict other projectiles (--predict-m) or counterweights (--predict-M)");
  {
    CLI::App* c = s.calibrate;
    engine_options(c, o, false);
    input_options(c, o, op_shot, {FieldGroup::release, FieldGroup::part}, false);
    measured_options(c, o);
    target_level_option(c, o, false);
    release_options(c, o);
    integrator_options(c, o);
    format_option(c, o, false);
    material_options(c, o, "the design", false);
    air_options(c, o);
  }

  s.compare = app.add_subcommand("compare",
                                 "one engine's parts built as each machine, hinged, fixed, floating-arm and whipper, side by side: range, eps, "
                                 "the release, the pin to bend and the peak loads");
  {
    CLI::App* c = s.compare;
    c->add_option("input", o.input, "JSON file with a design, or CSV with one row (docs/csv.md); - for stdin");
    input_options(c, o, op_shot, {FieldGroup::engine, FieldGroup::alternative, FieldGroup::release, FieldGroup::part}, false);
    target_level_option(c, o, false);
    release_options(c, o);
    integrator_options(c, o);
    format_option(c, o, true);
    material_options(c, o, "the design", false);
    air_options(c, o);
  }

  s.contest = app.add_subcommand("contest",
                                 "the best engine of a --machine for a projectile --m within a contest's limits (--max-width, --max-height, "
                                 "--max-M, --max-axle-load, --max-acceleration), with the pin to bend, and the Pareto front of range "
                                 "against the axle's load (--pareto)");
  {
    CLI::App* c = s.contest;
    machine_option(c, o);
    for (auto member : {&DesignValues::m, &DesignValues::D, &DesignValues::box_width, &DesignValues::box_height}) {
      const InputField& field = field_of(member);
      parsed_option(
          c, field.flag,
          [&o, name = std::string(field.flag), member = member, dimension = field.dimension](const std::string& text) {
            o.design.*member = parse_positive(text, dimension, name);
          },
          member == &DesignValues::m ? "the contest's projectile mass [" + unit_list(field.dimension) + "]"
              : member == &DesignValues::D
              ? "the beam's diameter, of the wood (--wood-density): its mass per metre [" + unit_list(field.dimension) + "]"
              : std::string(field.help) + " [" + unit_list(field.dimension) + "]");
    }
    parsed_option(
        c, "--min-clearance", [&o](const std::string& text) { o.min_clearance = parse_value(text, UnitDimension::length, "--min-clearance"); },
        "the least clearance of the counterweight (its box's bottom, --box-height) above the ground, hanging straight down and in the shot "
        "[" +
            unit_list(UnitDimension::length) + "] (default 0: it may not strike the ground)");
    parsed_option(
        c, "--mb-per-m", [&o](const std::string& text) { o.beam_per_m = parse_value(text, UnitDimension::dimensionless, "--mb-per-m"); },
        "the beam's mass per metre of its length [kg/m], instead of --D");
    const InputField& theta = field_of(&DesignValues::theta_i_deg);
    parsed_option(
        c, theta.flag, [&o](const std::string& text) { o.design.theta_i_deg = parse_value(text, UnitDimension::angle, "--theta"); },
        option_help(theta));
    const std::pair<const char*, UnitDimension> limits[contest_limit_count] = {{"--max-width", UnitDimension::length},
                                                                               {"--max-height", UnitDimension::length},
                                                                               {"--max-M", UnitDimension::mass},
                                                                               {"--max-axle-load", UnitDimension::force},
                                                                               {"--max-acceleration", UnitDimension::acceleration}};
    const char* const words[contest_limit_count] = {"the width of the box the engine must keep within from rest through the release",
                                                    "its height above the base", "the largest counterweight", "the largest peak load on the axle",
                                                    "the largest peak acceleration of the projectile"};
    for (int k = 0; k < contest_limit_count; ++k)
      parsed_option(
          c, limits[k].first,
          [&o, k, name = std::string(limits[k].first), dimension = limits[k].second](const std::string& text) {
            o.limits[k] = parse_positive(text, dimension, name);
          },
          std::string(words[k]) + " [" + unit_list(limits[k].second) + "]");
    parsed_option(
        c, "--objective",
        [&o](const std::string& text) {
          if (text != "range" && text != "eps") throw Error(ErrorKind::usage, "--objective: '" + text + "' is not an objective; use range or eps");
          o.efficiency = text == "eps";
        },
        "what to maximise: range (released where the range peaks) or eps (released where eps peaks) (default range)");
    integer_option(c, "--pareto", o.pareto, 2, 200, "2 to 200", "also the Pareto front of this many optima, range against the axle's load");
    c->add_option("--plot", o.plot, "with --pareto, draw the front into this folder (pareto.svg, needs gnuplot)");
    target_level_option(c, o, false);
    integrator_options(c, o);
    format_option(c, o, false);
    material_options(c, o, "the beam", false);
    air_options(c, o);
  }

  s.sweep = app.add_subcommand("sweep",
                               "what if one value changes? the shot of one design (a file or flags) as --vary runs one of its values "
                               "over a range, the rest held: R, eps, Q, the release, the peak loads and the beam's margin at each point");
  {
    CLI::App* w = s.sweep;
    w->add_option("input", o.input, "JSON file with one design, or CSV with one row (docs/csv.md); - for stdin");
    input_options(w, o, op_shot, {FieldGroup::engine, FieldGroup::alternative, FieldGroup::release, FieldGroup::part}, false);
    machine_option(w, o);
    parsed_option(
        w, "--vary", [&o](const std::string& text) { o.what_if = parse_what_if(text, 21, "--vary"); },
        "the value to vary and its range, KEY=low..high with units, e.g. L4=2m..5m, M=10t..20t, pin_angle=30..50 (required)");
    integer_option(w, "--points", o.what_if_points, 2, max_what_if_points, "2 to " + std::to_string(max_what_if_points),
                   "shots from low to high, both ends included (default 21)");
    target_level_option(w, o, false);
    threads_option(w, o, "threads (default: the cores); the output is the same on any number");
    release_options(w, o);
    integrator_options(w, o);
    format_option(w, o, true);
    material_options(w, o, "the design", false);
    air_options(w, o);
  }

  CLI::App* c = s.complete;
  air_and_sampling_options(c, o);
  input_options(c, o, op_complete, {FieldGroup::engine, FieldGroup::alternative, FieldGroup::part}, true);
  target_level_option(c, o, true);
  threads_option(c, o, "threads for a Monte Carlo run (default: the cores)");
  c->add_option("--plot", o.plot, "with ranges or spreads: write the histogram of R and T into this folder (needs gnuplot)");
  material_options(c, o, "the beam", true);
  release_options(c, o);
  integrator_options(c, o);
  format_option(c, o, false);

  CLI::App* opt = s.optimize;
  // The capacity to design for, and a beam ratio to hold; each positive.
  for (auto member : {&DesignValues::R, &DesignValues::T, &DesignValues::m, &DesignValues::l}) {
    const InputField& field = field_of(member);
    parsed_option(
        opt, field.flag,
        [&o, name = std::string(field.flag), member = member, dimension = field.dimension](const std::string& text) {
          o.design.*member = parse_positive(text, dimension, name);
        },
        option_help(field));
  }
  for (CLI::App* sub : {s.optimize, s.derive_table}) {
    block_options(sub, o);
    material_options(sub, o, "the engines", true);
    release_options(sub, o);
  }
  integrator_options(opt, o);
  format_option(opt, o, false);
  air_options(opt, o);
  machine_option(opt, o);

  CLI::App* derive = s.derive_table;
  machine_option(derive, o);
  sweep_options(derive, o);
  threads_option(derive, o, "threads (default: the cores)");
  s.merge->add_option("parts", o.parts, "the files written by derive-table --shard k/N")->required();
  return s;
}

ShotSettings settings_of(const Options& o) {
  if (o.series_dt_s > 0 && o.series.empty())
    throw Error(ErrorKind::usage, "--series-dt samples the series; add --series FILE to write it, or leave --series-dt out");
  return shot_settings(o.settings);
}

MonteCarloRequest monte_carlo_request(const Options& o, bool completes) { return {o.design, o.settings, o.material, o.spreads, completes, ""}; }

}  // namespace trebuchet::verify
