#include "options.hpp"

#include <algorithm>
#include <thread>

#include "flags.hpp"
#include "option_groups.hpp"
#include "program.hpp"
#include "trebuchet/app/input/request.hpp"

namespace trebuchet::verify {

namespace {
const char* key_flag(std::optional<double> DesignValues::*member) { return field_of(member).flag; }
}  // namespace

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

  const std::string one_design = "JSON file with a design, or CSV with one row (docs/csv.md); - for stdin";
  using G = FieldGroup;
  for (CLI::App* sub : {s.shot, s.fit}) {
    const bool shot = sub == s.shot;
    sub->add_option("input", o.input, "JSON file with a design or an array of designs, or CSV with a design a row (docs/csv.md); - for stdin");
    if (shot)
      input_options(sub, o, op_shot, {G::engine, G::alternative, G::capacity, G::release, G::part}, true);
    else
      input_options(sub, o, op_shot, {G::engine, G::alternative, G::capacity}, false);
    material_options(sub, o, op_shot, !shot);  // fit sizes the beam anew
    setting_options(sub, o, shot ? cmd_shot : cmd_fit, shot);
  }

  s.calibrate = app.add_subcommand("calibrate",
                                   "fit an engine's friction to the range it was measured to throw (--measured 34.4m±1.5m), "
                                   "report the losses, and predict other projectiles (--predict-m) or counterweights (--predict-M)");
  s.calibrate->add_option("input", o.input, one_design);
  // What nobody measured may be a range or a spread: the calibration is then drawn over it.
  input_options(s.calibrate, o, op_shot, {G::engine, G::alternative, G::capacity, G::release, G::part}, true);
  material_options(s.calibrate, o, op_shot, false);
  setting_options(s.calibrate, o, cmd_calibrate, true);

  s.compare = app.add_subcommand("compare",
                                 "one engine's parts built as each machine, hinged, fixed, floating-arm and whipper, side by side: range, eps, "
                                 "the release, the pin to bend and the peak loads");
  s.sweep = app.add_subcommand("sweep",
                               "what if one value changes? the shot of one design (a file or flags) as --vary runs one of its values "
                               "over a range, the rest held: R, eps, Q, the release, the peak loads and the beam's margin at each point");
  for (CLI::App* sub : {s.compare, s.sweep}) {
    sub->add_option("input", o.input, one_design);
    input_options(sub, o, op_shot, {G::engine, G::alternative, G::release, G::part}, false);
    material_options(sub, o, op_shot, false);
    setting_options(sub, o, sub == s.compare ? cmd_compare : cmd_sweep, false);
  }

  s.contest = app.add_subcommand("contest",
                                 "the best engine of a --machine for a projectile --m within a contest's limits (--max-width, --max-height, "
                                 "--max-M, --max-axle-load, --max-acceleration), with the pin to bend, and the Pareto front of range "
                                 "against the axle's load (--pareto)");
  // The contest's projectile (its mass, and its size for the air), beam and box, each positive, the beam's angle at rest, and the
  // sling's parts (0 or more: the contest checks them as the shot does).
  for (auto member : {&DesignValues::m, &DesignValues::D, &DesignValues::box_width, &DesignValues::box_height, &DesignValues::theta_i_deg,
                      &DesignValues::rope_mass, &DesignValues::pouch_mass, &DesignValues::pin_friction, &DesignValues::projectile_diameter})
    parsed_option(
        s.contest, field_of(member).flag,
        [&o, member](const std::string& text) {
          const InputField& field = field_of(member);
          const bool positive = member != &DesignValues::theta_i_deg && field.group != FieldGroup::part;
          o.design.*member = positive ? parse_positive(text, field.dimension, field.flag) : parse_value(text, field.dimension, field.flag);
        },
        member == &DesignValues::D
            ? "the beam's diameter, of the wood (--wood-density): its mass per metre [" + unit_list(UnitDimension::length) + "]"
            : option_help(field_of(member)));
  material_options(s.contest, o, op_shot, false);
  setting_options(s.contest, o, cmd_contest, false);

  CLI::App* c = s.complete;
  input_options(c, o, op_complete, {G::engine, G::alternative, G::part}, true);
  material_options(c, o, op_complete, true);
  setting_options(c, o, cmd_complete, true);

  // optimize's capacity to design for and a beam ratio to hold, each positive; its and
  // derive-table's block of the table (theta_i and F).
  for (auto member : {&DesignValues::R, &DesignValues::T, &DesignValues::m, &DesignValues::l})
    parsed_option(
        s.optimize, field_of(member).flag,
        [&o, member](const std::string& text) { o.design.*member = parse_positive(text, field_of(member).dimension, field_of(member).flag); },
        option_help(field_of(member)));
  for (CLI::App* sub : {s.optimize, s.derive_table}) {
    parsed_option(
        sub, key_flag(&DesignValues::theta_i_deg), [&o](const std::string& text) { o.design.theta_i_deg = parse_theta(text, "--theta"); },
        "initial beam angle theta_i [deg] (default 30)");
    parsed_option(
        sub, key_flag(&DesignValues::F), [&o](const std::string& text) { o.design.F = parse_positive(text, UnitDimension::dimensionless, "--F"); },
        "counterweight arm fraction (L2+L3)/H (default 2/3)");
    material_options(sub, o, op_optimize, true);
    setting_options(sub, o, sub == s.optimize ? cmd_optimize : cmd_derive_table, false);
  }
  s.merge->add_option("parts", o.parts, "the files written by derive-table --shard k/N")->required();
  return s;
}

ShotSettings settings_of(const Options& o, bool over_designs) {
  if (o.series_dt_s > 0 && o.series.empty())
    throw Error(ErrorKind::usage, "--series-dt samples the series; add --series FILE to write it, or leave --series-dt out");
  return over_designs ? shot_settings_over_designs(o.settings) : shot_settings(o.settings);
}

MonteCarloRequest monte_carlo_request(const Options& o, bool completes) { return {o.design, o.settings, o.spreads, completes, "", {}}; }

}  // namespace trebuchet::verify
