#include "option_groups.hpp"

#include <algorithm>
#include <iterator>
#include <cstdio>
#include <thread>

#include "flags.hpp"
#include "program.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/app/names.hpp"
#include "trebuchet/app/request.hpp"
#include "trebuchet/app/table_json.hpp"
#include "trebuchet/app/units.hpp"

namespace trebuchet::verify {
namespace {

// Where a value of a flag goes: a value of the design (--L1, --theta, ...) or a setting (--wind, ...).
struct Slot {
  std::optional<double> DesignValues::*value = nullptr;
  std::optional<double> SettingsValues::*setting = nullptr;
};
std::optional<double>& slot_in(Options& o, const Slot& slot) { return slot.value ? o.design.*slot.value : o.settings.*slot.setting; }

// The order in which uncertain values are drawn and listed, whatever the order they were given
// in: the same command draws the same numbers. A shot's values in the table's order, the other
// options, then what a completion alone takes (Lb, H, l).
int draw_rank(const std::string& name) {
  static const std::vector<std::string> order = [] {
    std::vector<std::string> names;
    for (const InputField& field : input_fields())
      if (field.operations & op_shot) names.emplace_back(field.flag);
    names.insert(names.end(), {"--target-level", "--wind", "--air-density"});
    for (const InputField& field : input_fields())
      if (!(field.operations & op_shot)) names.emplace_back(field.flag);
    return names;
  }();
  return static_cast<int>(std::find(order.begin(), order.end(), name) - order.begin());
}

// A value with a unit into `slot` (strictly positive with `positive`). With `spreads`, it may be a
// range or a spread (uncertainty.hpp): the slot then holds its first number, and the spread is
// kept for the Monte Carlo run.
CLI::Option* value_option(CLI::App* app, Options& o, const std::string& name, Slot slot, UnitDimension dimension, const std::string& help,
                          bool spreads = false, bool positive = false) {
  return parsed_option(
      app, name,
      [&o, name, slot, dimension, spreads, positive](const std::string& text) {
        const auto spread = parse_spread(text, dimension, name);
        if (spread && !spreads)
          throw Error(ErrorKind::usage,
                      name + ": '" + text +
                          "' is a range or a spread; give one value (ranges and spreads are for the "
                          "engine's values, --theta, --psi-i, --target-level and the air, in shot and complete)");
        slot_in(o, slot) = spread ? spread->a : positive ? parse_positive(text, dimension, name) : parse_value(text, dimension, name);
        if (!spread) return;
        const auto after = std::find_if(o.spreads.begin(), o.spreads.end(),
                                        [&](const SpreadInput& u) { return draw_rank(u.input.name) > draw_rank(name); });
        o.spreads.insert(after, {{name, dimension, *spread}, slot.value, slot.setting});
      },
      help);
}

}  // namespace

// The option of a row of the table; a capacity is never a spread.
static void input_option(CLI::App* app, Options& o, const InputField& field, bool spreads) {
  value_option(app, o, field.flag, Slot{field.member, nullptr}, field.dimension, option_help(field), spreads && field.group != FieldGroup::capacity);
}

// The table's inputs that `operation` takes, of the groups given (the material has options of
// its own, material_options).
void input_options(CLI::App* app, Options& o, unsigned operation, std::initializer_list<FieldGroup> groups, bool spreads) {
  for (const InputField& field : input_fields())
    if ((field.operations & operation) && std::find(groups.begin(), groups.end(), field.group) != groups.end()) input_option(app, o, field, spreads);
}

void engine_options(CLI::App* app, Options& o, bool spreads) {
  app->add_option("input", o.input, "JSON file with a design or an array of designs, or CSV with a design a row (docs/csv.md); - for stdin");
  input_options(app, o, op_shot, {FieldGroup::engine, FieldGroup::alternative, FieldGroup::capacity}, spreads);
  positive_option(app, "--tol", o.tolerance, UnitDimension::dimensionless, "relative tolerance on the predicted R and T (default 0.02)");
  app->add_option("--series", o.series, "write the time series of the shot (angles, forces, positions, energies) to this CSV file");
  positive_option(app, "--series-dt", o.series_dt_s, UnitDimension::time,
                  "sample the series every this many seconds (e.g. 5ms) instead of at the integrator's steps");
  app->add_option("--plot", o.plot, "draw the shot into this folder: SVG pictures, an animated GIF and index.html (needs gnuplot)");
  machine_option(app, o);
}

void machine_option(CLI::App* app, Options& o) {
  parsed_option(
      app, "--machine", [&o](const std::string& text) { o.design.machine = parse_machine(text, "--machine"); },
      "the machine: hinged (the paper's counterweight on its arm L3), fixed (bolted to the short arm, its centre L3 beyond the arm's "
      "end), floating-arm (the axle rolling on a rail, the counterweight L3 below its pin in a vertical guide) or whipper (the "
      "paper's, started with its arm forward and up on a frame --H, the counterweight and the ball resting on it) (default hinged; "
      "docs/machines.md)");
}

void target_level_option(CLI::App* app, Options& o, bool spreads) {
  value_option(app, o, "--target-level", Slot{nullptr, &SettingsValues::target_level}, UnitDimension::length,
               "target height relative to the engine's base, e.g. -54m (default 0) [" + unit_list(UnitDimension::length) + "]", spreads);
}

void release_options(CLI::App* app, Options& o) {
  parsed_option(
      app, "--quality",
      [&o](const std::string& text) {
        o.settings.base.criterion.release = parse_release(text, "--quality");
        o.release_given = true;
      },
      "what the release maximises: Q (eq:Q, eq:Q_n), eps (appendix B) or range (Denny) (default Q)");
  parsed_option(
      app, "--n",
      [&o](const std::string& text) {
        o.settings.base.criterion.n = parse_value(text, UnitDimension::dimensionless, "--n");
        o.release_given = true;  // Q_n: the release where it peaks
        if (!(o.settings.base.criterion.n >= 0)) throw Error(ErrorKind::bad_number, "--n: '" + text + "' must be 0 or more (eq:Q_n)");
      },
      "exponent of eps in eq:Q_n (default 1)");
}

void integrator_options(CLI::App* app, Options& o) {
  parsed_option(
      app, "--stepper", [&o](const std::string& text) { o.settings.base.integrator.stepper = parse_stepper(text, "--stepper"); },
      "GSL odeiv2 stepper: " + stepper_names() + " (default " + stepper_name(IntegratorSettings{}.stepper) + ")");
  positive_option(app, "--rtol", o.settings.base.integrator.rtol, UnitDimension::dimensionless, "relative tolerance per step (default 1e-11)");
  positive_option(app, "--atol", o.settings.base.integrator.atol, UnitDimension::dimensionless,
                  "absolute tolerance per step, scaled units (default 1e-11)");
}

void format_option(CLI::App* app, Options& o, bool csv_too) {
  parsed_option(
      app, "--units", [&o](const std::string& text) { o.units = parse_unit_system(text, "--units"); },
      "si or imperial: how tables print values (imperial: ft, lb, lbf, ft·lbf, psi, with SI beside; JSON and CSV stay SI)");
  parsed_option(
      app, "--format",
      [&o, csv_too](const std::string& text) {
        if (text == "table")
          o.format = Format::table;
        else if (text == "json")
          o.format = Format::json;
        else if (text == "csv" && csv_too)
          o.format = Format::csv;
        else
          throw Error(ErrorKind::usage, "--format: '" + text + "' is not a format; use table" + (csv_too ? ", json or csv" : " or json"));
      },
      csv_too ? "table, json or csv (default table)" : "table or json (default table)");
  if (csv_too)
    parsed_option(
        app, "--digits", [&o](const std::string& text) { o.digits = parse_digits(text, "--digits"); },
        "significant digits of CSV numbers (default " + std::to_string(default_csv_digits) + "; 17: exact)");
}

void material_options(CLI::App* app, Options& o, const std::string& what, bool beta2) {
  using V = DesignValues;
  using O = MaterialOverrides;
  const std::pair<std::optional<double> V::*, std::optional<double> O::*> material[] = {
      {&V::g, &O::g}, {&V::youngs_modulus, &O::youngs_modulus}, {&V::wood_density, &O::wood_density}, {&V::beta2, &O::beta2}};
  for (const auto& [row, member] : material) {
    const InputField& field = field_of(row);
    if (row == &V::beta2 && !beta2) continue;
    const std::string name = field.flag;
    const std::string units = field.dimension == UnitDimension::dimensionless ? "" : " [" + unit_list(field.dimension) + "]";
    const std::string help = row == &V::beta2 ? "allowed beam bending u2/L2 that sizes " + what + " (default: its own, else 1/300)"
                                              : std::string(field.help) + " (default: the design's, else " + field.fallback + ")" + units;
    parsed_option(
        app, name,
        [&o, name, member = member, dimension = field.dimension](const std::string& text) {
          o.material.*member = parse_positive(text, dimension, name);
        },
        help);
  }
  parsed_option(
      app, "--rupture", [&o](const std::string& text) { o.material.modulus_of_rupture = parse_positive(text, UnitDimension::pressure, "--rupture"); },
      "modulus of rupture of the beam's wood, the stress it breaks at (default 120MPa, 1 % of 12GPa, section 4)");
}

void block_options(CLI::App* app, Options& o) {
  parsed_option(
      app, "--theta", [&o](const std::string& text) { o.design.theta_i_deg = parse_theta(text, "--theta"); },
      "initial beam angle theta_i [deg] (default 30)");
  parsed_option(
      app, "--F", [&o](const std::string& text) { o.design.F = parse_positive(text, UnitDimension::dimensionless, "--F"); },
      "counterweight arm fraction (L2+L3)/H (default 2/3)");
}

void threads_option(CLI::App* app, Options& o, const std::string& help) {
  integer_option(app, "--threads", o.threads, 1, 1 << 16, "1 or more (at most 65536)", help);
}

// The air: shot's, complete's and calibrate's.
void air_options(CLI::App* app, Options& o) {
  app->add_flag("--air", o.settings.air,
                "fly through air (quadratic drag on a sphere) instead of vacuum; with --quality range the release maximises the range in air");
  app->add_flag("--drag-in-sling", o.settings.drag_in_sling,
                "with --air: the air acts before the release too, on the projectile in the trough and the sling and on the rope (--rope-diameter)");
  value_option(app, o, "--air-density", Slot{nullptr, &SettingsValues::air_density}, UnitDimension::density,
               "density of the air (default 1.2kg/m3) [" + unit_list(UnitDimension::density) + "]", true, true);
  parsed_option(
      app, "--cd",
      [&o](const std::string& text) {
        if (text == "Re")
          o.settings.drag_of_reynolds = true;
        else if (text.find_first_of("0123456789") == std::string::npos)
          throw Error(ErrorKind::usage, "--cd: '" + text + "' is not a drag coefficient; give a number, e.g. 0.47, or Re for Cd(Re)");
        else
          o.settings.drag_coefficient = parse_positive(text, UnitDimension::dimensionless, "--cd");
      },
      "drag coefficient of the sphere (default 0.47), or Re for Cd(Re) of a smooth sphere");
  parsed_option(
      app, "--projectile", [&o](const std::string& text) { o.settings.projectile_density = parse_projectile_density(text, "--projectile"); },
      "stone (2500kg/m3, the default), iron (7870kg/m3), lead (11340kg/m3), clay (fired, about 1800kg/m3) or a density: "
      "gives the sphere's size");
  value_option(app, o, "--wind", Slot{nullptr, &SettingsValues::wind}, UnitDimension::speed,
               "horizontal wind toward the target, e.g. 5m/s or -20km/h (against) [" + unit_list(UnitDimension::speed) + "]", true);
  parsed_option(
      app, "--range-from", [&o](const std::string& text) { o.settings.base.range_from_release = parse_range_from(text, "--range-from"); },
      "pivot (the paper's: to the target level, the default) or release (Denny's: from the release point back to its height)");
}

// The air, and Monte Carlo: shot's and complete's.
void air_and_sampling_options(CLI::App* app, Options& o) {
  // The run's work is checked against its budget once the shots of a sample are known (check_monte_carlo_work).
  integer_option(app, "--samples", o.samples, 1, static_cast<int>(max_run_shots), "1 to " + std::to_string(max_run_shots),
                 "Monte Carlo samples, when a value is a range (2.5t..3.5t) or a spread (3.5m±0.2m) (default " +
                     std::to_string(default_shot_samples) + " for a shot, " + std::to_string(default_completion_samples) + " for complete)");
  integer_option(app, "--seed", o.seed, std::uint64_t{0}, std::uint64_t{0}, "0 or more",
                 "seed of the Monte Carlo draws: the same seed, the same result (default 1)");
  parsed_option(
      app, "--claim",
      [&o](const std::string& text) {
        o.claim = parse_positive(text, UnitDimension::length, "--claim");
        check_ordinary(*o.claim, 1e-6, 1e6, "claim", "m", "claimed range");
      },
      "with ranges or spreads: a claimed range, e.g. 300m; report how many samples reach it and which inputs matter [" +
          unit_list(UnitDimension::length) + "]");
  app->add_option("--draws", o.draws, "with ranges or spreads: write every sample's drawn inputs and its R, T, eps and v to this CSV file");
  air_options(app, o);
}

}  // namespace trebuchet::verify
