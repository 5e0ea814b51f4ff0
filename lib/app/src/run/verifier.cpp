#include "trebuchet/app/run/verifier.hpp"

#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "trebuchet/capacity_fit.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/app/output/pictures.hpp"
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/input/csv.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/app/output/output_files.hpp"
#include "trebuchet/app/input/text_input.hpp"

namespace trebuchet {

DesignInputs read_design_inputs(const std::string& text, const std::string& path) {
  DesignInputs in;
  const std::string expected = "a design object like {\"L1\": \"6.13m\", ...}, an array of them, or CSV with a header (docs/csv.md)";
  const std::size_t start = text.find_first_not_of(" \t\r\n", text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0);
  const bool named_json = path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
  const bool csv = !named_json && start != std::string::npos && text[start] != '{' && text[start] != '[' && !nlohmann::json::accept(text);
  if (csv) {
    std::istringstream stream(text);
    DesignRows rows = read_design_rows(stream, source_name(path));
    // A column passed through must not take the name of one the verifier writes (in CSV or JSON).
    const std::vector<std::string> written = verification_output_names();
    for (const std::string& column : rows.passed_columns)
      if (std::find(written.begin(), written.end(), column) != written.end())
        throw Error(ErrorKind::usage,
                    source_name(path) + ": the column '" + column + "' would pass through, but the output has a column '" + column +
                        "' of its own; rename it, e.g. '" + column + "_input'");
    in.passed_columns = std::move(rows.passed_columns);
    in.rows = std::move(rows.rows);
    for (const auto& row : in.rows) in.where.push_back("line " + std::to_string(row.line));
    in.single = false;
    return in;
  }
  // An array nesting too deep in some member: the others are answered, each deep one refused by
  // its index, as any other bad member is.
  if (json_depth(text) > max_json_depth)
    if (const auto members = array_members(text)) {
      in.single = false;
      for (std::size_t i = 0; i < members->size(); ++i) {
        const std::string where = "design[" + std::to_string(i) + "]";
        DesignRows::Row row{0, nullptr, {}, "", ""};
        if (json_depth((*members)[i]) > max_json_depth - 1)
          row.error = where + " nests arrays or objects more than " + std::to_string(max_json_depth) + " levels deep; give " + expected;
        else
          row.design = parse_json(std::string((*members)[i]), source_name(path) + " " + where, expected);
        in.rows.push_back(std::move(row));
        in.where.push_back(where);
      }
      return in;
    }
  nlohmann::json json = parse_json(text, source_name(path), expected);
  if (!json.is_object() && !json.is_array())
    throw Error(ErrorKind::usage, source_name(path) + " holds " + brief_json(json) + ", not a design; give " + expected);
  // A sweep's record reads back as its points, each a shot's record.
  const bool sweep = json.is_object() && json.contains("vary") && json.contains("points") && json["points"].is_array();
  if (sweep) json = std::move(json["points"]);
  in.single = json.is_object();
  // Moved, not copied: a copy of deeply nested input would recurse as deep as it nests.
  for (std::size_t i = 0; i < (in.single ? 1 : json.size()); ++i) {
    in.rows.push_back({0, in.single ? std::move(json) : std::move(json[i]), {}, "", ""});
    in.where.push_back(in.single ? "design" : (sweep ? "point[" : "design[") + std::to_string(i) + "]");
    // A record of a failure (a sweep's point with its varied value, a machine compare refused)
    // fails again, as written: it holds an error and no engine, which needs both masses.
    const nlohmann::json& row = in.rows.back().design;
    if (row.is_object() && row.contains("error") && row["error"].is_string() && !row.contains("engine") && !(row.contains("M") && row.contains("m")))
      in.rows.back().error = in.where.back() + " failed where it was written: " + row["error"].get<std::string>();
  }
  return in;
}

void check_fixed_beam_ratio(double l, const std::string& name) {
  // Below l = 2 the long arm is hardly longer than the short one: no engine of the paper (l
  // from 3 to 59), and most shapes there leave no room for the counterweight arm at all.
  if (!(l >= 2))
    throw Error(ErrorKind::usage,
                name + " " + format_significant(l, 4) + " is below the beam ratios the fixed-l search covers (2 to " + format_number(max_beam_ratio) +
                    "; the paper's engines have 3 to 59); give a larger " + name);
  if (!(l < max_beam_ratio))
    throw Error(ErrorKind::usage,
                name + " " + format_significant(l, 4) + " is beyond the optimizer's beam ratios (below " + format_number(max_beam_ratio) +
                    ", appendix B's largest is 59); give a smaller " + name);
}

namespace {

// The run's settings over the design's own (a record's), the release the run gives over the
// design's; the tolerance of the capacity check, the record's where the caller gives none.
ShotSettings settings_of_check(const EngineRecord& record, const DesignCheck& check, double& tolerance) {
  ShotSettings settings = check.settings;  // the run's release over the design's own
  if (check.given) {  // the design's settings (a record's), under the caller's
    ShotSettings own = shot_settings(overlay(record.settings, *check.given));
    own.release_at = settings.release_at;
    own.loads = settings.loads;
    settings = own;
    if (record.settings.tol && !check.given->tol) tolerance = *record.settings.tol;
  }
  if (!settings.release_at) settings.release_at = record.release_at;
  return settings;
}

// fit: the engine sized to the record's capacity, with its shots, and its table.
struct FittedEngine {
  Engine engine;
  int simulations = 0;
  std::string table;
};

FittedEngine fit_for_check(const Engine& engine, const EngineRecord& record, const DesignCheck& check, const ShotSettings& settings) {
  if (settings.release_at)
    throw Error(ErrorKind::usage,
                "fit sizes the engine for a release at its optimum; a release the design sets ({{release_time}}, {{release_angle}}, "
                "{{pin_angle}}) is shot by shot; leave it out to fit");
  if (engine.parts.any())
    throw Error(ErrorKind::usage,
                "fit scales the paper's ideal engine to a capacity; an engine as built (friction, a beam or counterweight "
                "as built, a rope) is checked by shot, or fitted to a measured range by calibrate");
  if (!record.capacity) throw Error(ErrorKind::usage, "fit needs a capacity; give {{R}} and {{T}}, or \"R\" and \"T\" in the input");
  if (engine.projectile_diameter && engine.machine != MachineKind::whipper)
    throw Error(ErrorKind::usage,
                "fit sizes the projectile anew (its mass m), and a diameter held fixed would change its density with it; "
                "give its density ({{projectile}}) instead, or leave {{projectile_diameter}} out");
  const CapacityFit result = fit_capacity(scaled_design(engine), *record.capacity, engine.material, check.settings);
  return {result.engine, result.simulations,
          "fitted engine (" + std::to_string(result.simulations) + " shots):\n" + engine_table(result.engine, check.units)};
}

// The pin to bend for an optimum (none where no pin makes its release: check_design), and what a
// degree or two of error costs (read off the same shot); without friction on the pin, the bend
// for a greased and a dry one.
void add_pin_tolerance(DesignReport& out, const PinScan& tolerance_scan, const Verification& v, const Engine& engine, const DesignCheck& check) {
  nlohmann::ordered_json tolerance = nlohmann::ordered_json::array();
  std::vector<std::string> lost;
  const std::vector<PinShot>& shots = tolerance_scan.shots();
  for (std::size_t k = 1; k < shots.size(); ++k) {  // the first is the own pin (check_design)
    const PinShot& shot = shots[k];
    const double offset = shot.pin_angle_deg - v.pin_to_bend_deg;
    const std::string signed_offset = (offset > 0 ? "+" : "") + format_significant(offset, 2) + " deg: ";
    if (shot.R) {
      const double change = *shot.R - v.capacity.R;
      tolerance.push_back({{"pin_angle_deg", shot.pin_angle_deg}, {"R", *shot.R}, {"R_change", change}});
      lost.push_back(signed_offset + (change > 0 ? "+" : "") + quantity_text(change, UnitDimension::length, check.units, 3));
    } else {
      tolerance.push_back({{"pin_angle_deg", shot.pin_angle_deg}, {"R", nullptr}, {"R_change", nullptr}, {"refused", shot.refused}});
      lost.push_back(signed_offset + "refused");
    }
  }
  out.json["pin_tolerance"] = tolerance;
  // The loop leaves a pin of friction mu atan(mu) later (release_pin_angle): bend it that much more.
  const double mu = engine.parts.pin_friction;
  std::string pin = pin_to_bend_text(v, mu);
  if (!(mu > 0)) {
    nlohmann::ordered_json by_friction = nlohmann::ordered_json::array();
    for (const auto& [coefficient, what] : {std::pair{greased_pin_friction, "greased"}, {dry_pin_friction, "dry"}}) {
      const double bend = pin_to_bend_deg(v.pin_angle_deg, coefficient);
      by_friction.push_back({{"pin_friction", coefficient}, {"pin_to_bend_deg", bend}});
      pin += std::string(what == std::string("greased") ? " frictionless, " : ", ") + format_significant(bend, 4) + " deg " + what + " (mu " +
          format_significant(coefficient, 2) + ")";
    }
    out.json["pin_to_bend_by_friction"] = by_friction;
  }
  if (check.table)
    out.table += "pin to bend for this release: " +
        (out.pin_releases ? pin + "; R changes with the pin off by " + join(lost, ", ") : pin_to_bend_text(v, mu, false)) + "\n";
}

}  // namespace

namespace {

// A design as checked: its engine in the run's material (for fit, the fitted one, with its
// shots and table), the settings it is shot under, and the tolerance of its capacity check.
struct CheckedDesign {
  Engine engine;
  ShotSettings settings;
  double tolerance = 0;
  nlohmann::ordered_json simulated;
  std::string fitted_table;
};

CheckedDesign design_to_check(const EngineRecord& record, const DesignCheck& check) {
  CheckedDesign d;
  d.engine = record.engine;
  d.engine.material = material_of(check.material, d.engine.material);
  if (record.mb_from_D) d.engine.mb = wood_beam_mass(d.engine);  // in the wood of the run
  d.tolerance = check.tolerance;
  d.settings = settings_of_check(record, check, d.tolerance);
  if (check.fit) {
    FittedEngine fitted = fit_for_check(d.engine, record, check, d.settings);
    d.engine = fitted.engine;
    d.simulated["simulations"] = fitted.simulations;
    d.fitted_table = std::move(fitted.table);
  }
  return d;
}

// An error of the design's shot; a release the design itself sets named by its key, as the
// design gives it ("pin_angle_deg").
Error shot_error(const Error& e, const EngineRecord& record, const DesignCheck& check) {
  if (!record.release_at || check.settings.release_at) return e;
  return Error(e.kind(), e.message([](std::string_view key) {
    const InputField* field = find_field(key);
    return field && field->group == FieldGroup::release ? std::string(field->key) : "{{" + std::string(key) + "}}";
  }));
}

// The report of the design's shot `v`: its record, table and CSV cells, the capacity checked,
// the pin's tolerance where the shot read it (`tolerance_scan`), and whether a pin makes its release.
DesignReport design_report(const EngineRecord& record, const DesignCheck& check, const CheckedDesign& d, const Verification& v,
                           const PinScan* tolerance_scan, bool pin_releases) {
  const Engine& engine = d.engine;
  const ShotSettings& settings = d.settings;
  DesignReport out;
  std::optional<CapacityCheck> capacity;
  // fit designs for the capacity as the shot measures it (through its air, to its level, from where
  // it measures); a capacity to check is the calculator's, in vacuum. In vacuum to level 0 from
  // the pivot the two are the same.
  const bool measured = check.fit && (settings.air || settings.range_from_release || settings.target_level != 0);
  if (record.capacity) capacity = check_capacity(v, *record.capacity, d.tolerance, measured);
  out.json = verification_json(v, capacity);
  if (check.table) out.table = d.fitted_table + verification_table(engine, settings, v, capacity, check.units);
  if (check.csv) out.csv = verification_csv_row(engine, settings, v, capacity, check.csv_digits);
  // The engine simulated (for fit, the fitted one, with its shots) and what the shot assumed.
  nlohmann::ordered_json engine_json;
  write_engine(engine_json, engine);
  if (const auto& at = settings.release_at)  // the release its builder set, so that the record reads back
    engine_json[release_field(at->by).key] = at->value;
  if (check.fit) engine_json.update(d.simulated);
  out.json["engine"] = engine_json;
  out.json["assumptions"] = assumptions_json(engine, settings);
  out.pin_releases = pin_releases;
  if (tolerance_scan) add_pin_tolerance(out, *tolerance_scan, v, engine, check);
  if (!record.passed.empty()) {  // the design's keys no reader knows, as given
    out.json["passed"] = record.passed;
    std::vector<std::string> keys;
    for (const auto& [key, value] : record.passed.items()) keys.push_back(key);
    if (check.table) out.table += "passed through, not read: " + join(keys, ", ") + "\n";
  }
  out.outside_tolerance = capacity && !capacity->pass;
  out.engine = engine;
  out.settings = settings;
  out.verification = v;
  return out;
}

}  // namespace

DesignReport check_design(const EngineRecord& record, const DesignCheck& check) {
  const CheckedDesign d = design_to_check(record, check);
  std::vector<TracePoint> trace;
  // The pin to bend for an optimum, whether a pin bent so makes its release, and what a degree or
  // two of error costs: read off the same shot, the own pin first.
  PinScan tolerance_scan(d.engine, d.settings, [](double own_deg) {
    std::vector<double> pins{own_deg};
    for (double offset : pin_tolerance_offsets) pins.push_back(own_deg + offset);
    return pins;
  });
  PinScan* pins = d.settings.release_at ? nullptr : &tolerance_scan;
  Verification v = [&] {
    try {
      return verify_engine(d.engine, d.settings, check.series_path.empty() ? nullptr : &trace, check.series_dt_s, pins);
    } catch (const Error& e) {
      throw shot_error(e, record, check);
    }
  }();
  const std::optional<std::string> no_pin = pins && !pins->shots().empty() ? pin_release_note(v, pins->shots().front()) : std::nullopt;
  if (no_pin) v.notes.push_back(*no_pin);
  DesignReport out = design_report(record, check, d, v, pins, !no_pin);
  if (!check.plot_dir.empty())
    write_picture_folder(check.plot_dir, shot_pictures(d.engine, d.settings, v, out.json, check.units), picture_scripts(), check.inputs);
  if (!check.series_path.empty()) write_output_file(check.series_path, trace_csv(trace, d.engine), "series");
  return out;
}

std::vector<ReleasedDesign> check_released_designs(const std::vector<EngineRecord>& records, const DesignCheck& check) {
  if (check.fit || !check.series_path.empty() || !check.plot_dir.empty())
    throw Error(ErrorKind::usage, "designs checked at several releases are neither fitted nor drawn");
  std::vector<ReleasedDesign> out(records.size());
  std::vector<CheckedDesign> designs;
  std::vector<SetRelease> releases;
  std::vector<std::size_t> place;  // each design's place in `records`
  for (std::size_t i = 0; i < records.size(); ++i) {
    try {
      designs.push_back(design_to_check(records[i], check));
    } catch (const Error& e) {
      out[i].error = e;
      continue;
    }
    if (!designs.back().settings.release_at) throw Error(ErrorKind::usage, "a design checked at several releases needs its release given");
    releases.push_back(*designs.back().settings.release_at);
    place.push_back(i);
  }
  if (designs.empty()) return out;
  const std::vector<VerifiedRelease> shots = verify_releases(designs.front().engine, designs.front().settings, releases);
  for (std::size_t k = 0; k < shots.size(); ++k) {
    const EngineRecord& record = records[place[k]];
    if (shots[k].error) {
      out[place[k]].error = shot_error(*shots[k].error, record, check);
      continue;
    }
    try {
      out[place[k]].report = design_report(record, check, designs[k], *shots[k].verification, nullptr, true);
    } catch (const Error& e) {
      out[place[k]].error = e;  // a figure its record cannot hold, as check_design throws it
    }
  }
  return out;
}

std::vector<MachineComparison> compare_machines(const EngineRecord& record, const DesignCheck& check) {
  DesignCheck plain = check;
  plain.series_path.clear(), plain.plot_dir.clear();
  std::vector<MachineComparison> out;
  for (MachineKind machine : {MachineKind::hinged, MachineKind::fixed, MachineKind::floating_arm, MachineKind::whipper}) {
    MachineComparison one;
    one.machine = machine;
    EngineRecord built = record;
    built.engine.machine = machine;
    // A box counterweight, given as the machine it was read as, is given again as this one (give_box).
    if (const EngineParts& p = record.engine.parts; p.box_width && p.box_height) give_box(built.engine, *p.box_width, *p.box_height);
    if (machine == MachineKind::whipper) {  // pytrebuchet's start, on a frame as tall as the others' pivot stands
      built.engine.theta_i_deg = whipper_theta_i_deg;
      built.engine.whipper.H = pivot_height(record.engine);
    }
    try {
      // What one machine takes another may not (L3 = 0, a propped counterweight). A column that
      // hangs its counterweight on an arm, given none, is offered the paper's: F = 2/3 of the
      // pivot height (section 2), L3 = F H - L2.
      if (built.engine.L3 == 0 && (machine == MachineKind::hinged || machine == MachineKind::whipper)) {
        const double arm = standard_F * (machine == MachineKind::whipper ? built.engine.whipper.H : pivot_height(built.engine)) - built.engine.L2;
        throw Error(ErrorKind::usage,
                    "the " + machine_name(machine) + " machine hangs its counterweight on an arm, and {{L3}} is 0" +
                        (arm > 0 ? "; give one, e.g. {{L3}} " + format_significant(arm, 3) + "m (the paper's F = 2/3: L3 = 2/3 H - L2), to compare it"
                                 : "; give one to compare it"));
      }
      check_engine(built.engine);
      one.report = check_design(built, plain);
    } catch (const Error& e) {
      one.error = e;
    }
    one.limited = check.limits.any();
    if (one.report && one.limited) try {
        one.broken = broken_limits(one.report->engine, one.report->settings, check.limits);
      } catch (const Error& e) {
        one.unmeasured = e;
      }
    out.push_back(std::move(one));
  }
  return out;
}

namespace {

// What a column measures against the contest's limits: "met", "breaks 2" or "not measured".
std::string limits_cell(const MachineComparison& c) {
  if (c.unmeasured) return "not measured";
  return c.broken.empty() ? "met" : "breaks " + std::to_string(c.broken.size());
}

// The limits a column breaks, each with its measure and the limit: "{{max_axle_load}} 18 kN over 12 kN".
std::string broken_words(const std::vector<BrokenLimit>& broken, UnitSystem units) {
  std::string words;
  for (const BrokenLimit& b : broken) {
    const UnitDimension dimension = find_setting(b.key, req_contest)->dimension;
    words += (words.empty() ? "" : ", ") + std::string("{{") + b.key + "}} " + quantity_text(b.measured, dimension, units, 4) +
        (std::string(b.key) == "min_clearance" ? " under " : " over ") + quantity_text(b.limit, dimension, units, 4);
  }
  return words;
}

}  // namespace

std::string comparison_table(const std::vector<MachineComparison>& comparison, UnitSystem units,
                             const std::function<std::string(std::string_view)>& word) {
  const auto q = [&](double si, UnitDimension dimension) { return quantity_text(si, dimension, units, 4); };
  const auto sig = [](double x) { return format_significant(x, 4); };
  using Row = std::pair<const char*, std::function<std::string(const DesignReport&)>>;
  const std::vector<Row> rows = {
      // A shot that warns (the model stops holding: a slack sling, a weight through the ground) is
      // marked where its range is read, its warnings listed below.
      {"range R",
       [&](const DesignReport& r) { return q(r.verification.capacity.R, UnitDimension::length) + (r.verification.warnings.empty() ? "" : " !"); }},
      {"energy T", [&](const DesignReport& r) { return q(r.verification.capacity.T, UnitDimension::energy); }},
      {"efficiency eps", [&](const DesignReport& r) { return sig(100 * r.verification.eps) + " %"; }},
      {"quality Q", [&](const DesignReport& r) { return sig(100 * r.verification.Q) + " %"; }},
      {"release time", [&](const DesignReport& r) { return sig(r.verification.t_release) + " s"; }},
      {"release angle A", [&](const DesignReport& r) { return sig(r.verification.A_deg) + " deg"; }},
      {"pin angle to bend",
       [&](const DesignReport& r) { return r.pin_releases ? sig(r.verification.pin_to_bend_deg) + " deg" : std::string("none"); }},
      {"peak axle load", [&](const DesignReport& r) { return q(r.verification.loads[pivot_load].value, UnitDimension::force); }},
      {"peak sling tension", [&](const DesignReport& r) { return q(r.verification.loads[sling_tension_load].value, UnitDimension::force); }},
      {"peak counterweight pin", [&](const DesignReport& r) { return q(r.verification.loads[hinge_load].value, UnitDimension::force); }},
  };
  const int label = 24, width = 16;
  std::ostringstream out;
  const auto cell = [&](const std::string& text, int w) {
    out << text << std::string(text.size() < static_cast<std::size_t>(w) ? w - text.size() : 1, ' ');
  };
  // Every column shares the check's settings: the first report that stands says how they release.
  std::string release = "each released at its own optimum or at the release given";
  for (const MachineComparison& c : comparison)
    if (c.report) {
      release = describe_release(c.report->settings);
      break;
    }
  out << "the same parts built as each machine (docs/machines.md); " << release << ":\n";
  cell("", label);
  for (const MachineComparison& c : comparison) cell(machine_name(c.machine), width);
  out << "\n";
  // Under a contest's limits, a column that breaks one is marked where its range is read (x), never a peer of the others.
  const bool limited = std::any_of(comparison.begin(), comparison.end(), [](const MachineComparison& c) { return c.limited; });
  for (const auto& [name, value] : rows) {
    cell(name, label);
    for (const MachineComparison& c : comparison)
      cell(c.report ? value(*c.report) + (name == rows.front().first && !c.broken.empty() ? " x" : "") : "refused", width);
    out << "\n";
  }
  if (limited) {
    cell("the contest's limits", label);
    for (const MachineComparison& c : comparison) cell(c.report ? limits_cell(c) : "refused", width);
    out << "\n";
  }
  for (const MachineComparison& c : comparison) {
    if (c.error) out << machine_name(c.machine) << ": " << c.error->message(word) << "\n";
    if (!c.broken.empty())
      out << machine_name(c.machine)
          << " (x) breaks the contest's limits, not a peer of the others: " << with_words(broken_words(c.broken, units), word) << "\n";
    if (c.unmeasured) out << machine_name(c.machine) << ": not measured against the contest's limits: " << c.unmeasured->message(word) << "\n";
    if (c.report)
      for (const std::string& warning : c.report->verification.warnings)
        out << machine_name(c.machine) << " (!): warning: " << with_words(warning, word) << "\n";
  }
  return out.str();
}

std::vector<MachineComparison> compare_design(DesignValues values, const std::string& where, const SettingsValues& settings, DesignCheck check) {
  check.settings = shot_settings(settings);
  check.given.reset();  // `settings` are the design's own with the caller's over them
  check.settings.release_at = release_of(values, where);
  // Machines are compared as contest ranks them and the peers shoot them: for range, unless the quality is given.
  if (!settings.quality && !settings.n) check.settings.criterion.release = Release::range;
  if (values.machine == MachineKind::whipper)
    throw Error(ErrorKind::usage,
                "compare starts from an engine of the other machines (theta_i from 0 to 90 deg) and builds the whipper's column from it; "
                "give that engine, without the machine whipper");
  // Read as a machine that takes it (L3 = 0 is not the hinged engine's, a prop only its); each
  // machine then checks what it takes.
  values.machine = values.psi_i_deg.value_or(0) != 0 ? MachineKind::hinged : MachineKind::fixed;
  return compare_machines(engine_record(values, where), check);
}

nlohmann::ordered_json comparison_json(const std::vector<MachineComparison>& comparison, const std::function<std::string(std::string_view)>& word) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const MachineComparison& c : comparison) {
    nlohmann::ordered_json one = c.report ? c.report->json
                                          : nlohmann::ordered_json{{"machine", machine_name(c.machine)}, {"error", c.error->message(word)}};
    if (c.report && c.limited) {  // under a contest's limits: those it breaks, with what it measures
      nlohmann::ordered_json broken = nlohmann::ordered_json::array();
      for (const BrokenLimit& b : c.broken) broken.push_back({{"key", b.key}, {"measured", b.measured}, {"limit", b.limit}});
      one["within_limits"] = c.broken.empty() && !c.unmeasured;
      one["breaks"] = broken;
      if (c.unmeasured) one["limits_not_measured"] = c.unmeasured->message(word);
    }
    out.push_back(one);
  }
  return out;
}

void check_monte_carlo_work(std::int64_t samples, std::int64_t shots_per_sample, const std::string& sampled) {
  if (samples * shots_per_sample <= max_run_shots) return;
  throw Error(ErrorKind::usage,
              "{{samples}} " + std::to_string(samples) + " of " + sampled + " at " + std::to_string(shots_per_sample) + " shot(s) each would take " +
                  std::to_string(samples * shots_per_sample) + " shots, more than the " + std::to_string(max_run_shots) +
                  " a run may take (about 30 s on two cores); give {{samples}} " +
                  std::to_string(std::max<std::int64_t>(1, max_run_shots / shots_per_sample)) + " or fewer");
}

std::int64_t shots_per_completion(const std::function<Completion()>& trial) {
  try {
    return trial().simulations;
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::numerical) throw;
    return 300;
  }
}

void refuse_when_no_sample_worked(const MonteCarloSummary& summary) {
  if (!summary.values.empty()) return;
  const SampleFailures& most = summary.failures.front();
  throw Error(most.kind,
              "no sample worked; the most frequent reason (" + std::to_string(most.count) + " of " + std::to_string(summary.samples) +
                  "), in its first sample: " + most.first);
}

std::string describe_uncertain(const UncertainInput& u) {
  const Spread& s = u.spread;
  const char* unit = u.dimension == UnitDimension::length ? " m"
      : u.dimension == UnitDimension::mass                ? " kg"
      : u.dimension == UnitDimension::angle               ? " deg"
      : u.dimension == UnitDimension::speed               ? " m/s"
      : u.dimension == UnitDimension::density             ? " kg/m3"
                                                          : "";
  return u.name +
      (s.kind == Spread::Kind::uniform ? " uniform " + format_significant(s.a, 6) + ".." + format_significant(s.b, 6)
                                       : " normal " + format_significant(s.a, 6) + "±" + format_significant(s.b, 6)) +
      unit;
}

namespace {

// The median of input k over the samples that worked (0 when none did).
double median_drawn(const MonteCarloSummary& summary, std::size_t k) {
  std::vector<double> all;
  for (const std::vector<double>& drawn : summary.drawn) all.push_back(drawn[k]);
  if (all.empty()) return 0;
  std::sort(all.begin(), all.end());
  return gsl_stats_median_from_sorted_data(all.data(), 1, all.size());
}

// A drawn input's CSV column: its key with its SI unit, "M_kg", "theta_i_deg", "wind_m_s".
std::string draw_column(const UncertainInput& input) {
  std::string key = input.name.substr(input.name.find_first_not_of('-'));
  std::replace(key.begin(), key.end(), '-', '_');
  if (const InputField* field = find_field(key)) return csv_column_of(*field);
  for (const InputField& field : input_fields())
    if (input.name == field.flag) return csv_column_of(field);
  // A setting's (the target level, the wind, the air's density): its SI unit as the CSV columns write it.
  switch (input.dimension) {
    case UnitDimension::length: return key + "_m";
    case UnitDimension::speed: return key + "_m_s";
    case UnitDimension::density: return key + "_kg_m3";
    default: return key;
  }
}

}  // namespace

namespace {

// A range at one end of a span, and whether it reaches the claim: "718.9 m (reaches it)".
std::string reach_text(const std::optional<double>& R, double claim) {
  if (!R) return "not shot there";
  return format_significant(*R, 4) + " m (" + (*R >= claim ? "reaches it" : "falls short") + ")";
}

// How a user settles a value left at its default (ClaimSpan::key).
std::string settle_text(const std::string& key) {
  if (key == "air") return "add --air";
  if (key == "projectile") return "give --projectile, or the ball's --projectile-diameter (a range of it too)";
  return "give --" + key + ", or a range of it";
}

// What decides a claim's verdict, in words for a historian (ClaimContext).
std::string claim_context_text(const ClaimContext& c, double claim) {
  if (!c.unavailable.empty()) return "  what decides it is not known: the run's middle could not be shot (" + c.unavailable + ")\n";
  std::string out = "  what decides it, at the run's middle (each range at its centre, each spread at its mean):\n";
  out += "    the energy bound 2 Delta U/(m g) = " + format_significant(c.energy_bound, 4) +
      " m, the farthest any engine of this energy throws, in vacuum to the target level: " +
      (claim <= c.energy_bound ? "the claim is within it" : "the claim is BEYOND it") + "\n";
  out += std::string("    this engine's farthest throw, ") + (c.given_release ? "at the run's release" : "released where the range peaks") + ": " +
      reach_text(c.farthest, claim) + "\n";
  for (const ClaimSpan& s : c.spans) {
    const std::string verdict = s.decides ? "DECIDES it" : s.R_low && s.R_high ? "does not decide it" : "may decide it (an end was not shot)";
    out += "    " + s.what + ", left at its default, " + verdict + ": " + s.low + " " + reach_text(s.R_low, claim) + ", " + s.high + " " +
        reach_text(s.R_high, claim) + (s.decides ? "; " + settle_text(s.key) : std::string()) + "\n";
  }
  return out;
}

nlohmann::ordered_json claim_context_json(const ClaimContext& c) {
  if (!c.unavailable.empty()) return {{"unavailable", c.unavailable}};
  nlohmann::ordered_json defaults = nlohmann::ordered_json::array();
  const auto range = [](const std::optional<double>& R) { return R ? nlohmann::ordered_json(*R) : nlohmann::ordered_json(nullptr); };
  for (const ClaimSpan& s : c.spans)
    defaults.push_back({{"input", s.key},
                        {"what", s.what},
                        {"low", s.low},
                        {"high", s.high},
                        {"R_low", range(s.R_low)},
                        {"R_high", range(s.R_high)},
                        {"decides", s.decides}});
  return {{"energy_bound", c.energy_bound}, {"farthest", c.farthest}, {"farthest_at_given_release", c.given_release}, {"defaults", defaults}};
}

}  // namespace

nlohmann::ordered_json monte_carlo_json(const MonteCarloReport& r) {
  const MonteCarloSummary& summary = r.summary;
  nlohmann::ordered_json out;
  out["samples"] = summary.samples;
  out["seed"] = r.seed;
  out["worked"] = summary.values.size();
  for (const auto& item : r.request.items()) out[item.key()] = item.value();
  nlohmann::ordered_json uncertain = nlohmann::ordered_json::array();
  for (const auto& [name, dimension, spread] : r.inputs) {
    const bool uniform = spread.kind == Spread::Kind::uniform;
    uncertain.push_back({{"option", name},
                         {"distribution", uniform ? "uniform" : "normal"},
                         {uniform ? "from" : "mean", spread.a},
                         {uniform ? "to" : "deviation", spread.b}});
  }
  out["uncertain"] = uncertain;
  nlohmann::ordered_json fixed = nlohmann::ordered_json::object();
  for (const FixedInput& f : r.fixed) fixed[f.name] = f.value;
  out["fixed"] = fixed;
  out["assumptions"] = r.assumptions;
  for (std::size_t k = 0; k < sample_names.size(); ++k)
    if (!summary.values.empty())
      out["percentiles"][sample_names[k]] = {
          {"p5", summary.percentiles[k][0]}, {"p50", summary.percentiles[k][1]}, {"p95", summary.percentiles[k][2]}};
  nlohmann::ordered_json failures = nlohmann::ordered_json::array();
  for (const SampleFailures& f : summary.failures) failures.push_back({{"reason", f.reason}, {"count", f.count}, {"first", f.first}});
  out["failures"] = failures;
  out["air"] = r.in_air ? "air" : "vacuum";
  if (r.claim) {
    const ClaimAssessment c = assess_claim(summary, *r.claim);
    nlohmann::ordered_json medians = nlohmann::ordered_json::object(), medians_all = nlohmann::ordered_json::object();
    for (std::size_t k = 0; k < r.inputs.size(); ++k) medians_all[r.inputs[k].name] = median_drawn(summary, k);
    for (std::size_t k = 0; k < r.inputs.size(); ++k)
      medians[r.inputs[k].name] = k < c.median_reaching.size() ? nlohmann::ordered_json(c.median_reaching[k]) : nlohmann::ordered_json(nullptr);
    out["claim"] = {{"R", c.claim},
                    {"reached", c.reached},
                    {"worked", c.worked},
                    {"probability", c.probability},
                    {"interval_95", {c.low, c.high}},
                    {"interval_method", "Wilson score"},
                    {"median_reaching", medians},
                    {"median_all", medians_all}};
    if (r.claim_context) out["claim"]["decided_by"] = claim_context_json(*r.claim_context);
  }
  const std::vector<RankCorrelation> rho = rank_correlations(summary);
  if (!rho.empty()) {
    nlohmann::ordered_json ranking = nlohmann::ordered_json::array();
    for (std::size_t k : strongest_first(rho))
      ranking.push_back(
          {{"input", r.inputs[k].name}, {"spearman_R", rho[k].rho}, {"interval_95", {rho[k].low, rho[k].high}}, {"resolved", rho[k].resolved()}});
    out["sensitivity"] = {{"method", rank_correlation_method}, {"ranking", ranking}};
  }
  nlohmann::ordered_json draws = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < r.inputs.size(); ++k) {
    nlohmann::ordered_json column = nlohmann::ordered_json::array();
    for (const SampleOutcome& o : summary.outcomes) column.push_back(k < o.drawn.size() ? nlohmann::ordered_json(o.drawn[k]) : nullptr);
    draws[r.inputs[k].name] = column;
  }
  for (std::size_t q = 0; q < sample_names.size(); ++q) {
    nlohmann::ordered_json column = nlohmann::ordered_json::array();
    for (const SampleOutcome& o : summary.outcomes) column.push_back(o.failure.empty() ? nlohmann::ordered_json(o.values[q]) : nullptr);
    draws[sample_names[q]] = column;
  }
  nlohmann::ordered_json failed = nlohmann::ordered_json::array();
  for (const SampleOutcome& o : summary.outcomes)
    failed.push_back(o.failure.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(o.failure));
  draws["failure"] = failed;
  out["draws"] = draws;
  out["wall_time_s"] = r.seconds;
  out[version_key] = project_version();
  return out;
}

std::string monte_carlo_draws_csv(const MonteCarloReport& r) {
  constexpr int digits = 17;  // every digit of a double
  std::vector<std::string> header{"sample"};
  for (const UncertainInput& input : r.inputs) header.push_back(draw_column(input));
  header.insert(header.end(), {"R_m", "T_J", "eps", "v_m_s"});
  if (r.claim) header.push_back("reaches_claim");
  header.push_back("failure");
  std::string out = join(header, ",") + "\n";
  for (std::size_t i = 0; i < r.summary.outcomes.size(); ++i) {
    const SampleOutcome& o = r.summary.outcomes[i];
    out += std::to_string(i);
    for (std::size_t k = 0; k < r.inputs.size(); ++k) {
      out += ',';
      if (k < o.drawn.size()) append_csv_number(out, o.drawn[k], digits);
    }
    for (double value : o.values) {
      out += ',';
      if (o.failure.empty()) append_csv_number(out, value, digits);
    }
    if (r.claim) out += o.failure.empty() ? (o.values[0] >= *r.claim ? ",yes" : ",no") : ",";
    out += ',';
    append_csv_cell(out, o.failure);
    out += '\n';
  }
  return out;
}

std::string monte_carlo_csv(const MonteCarloReport& r, int digits) {
  std::string out = "quantity,p5,p50,p95\n";
  if (r.summary.values.empty()) return out;
  const char* columns[] = {"R_m", "T_J", "eps", "v_m_s"};
  for (std::size_t k = 0; k < sample_names.size(); ++k) {
    out += columns[k];
    for (double p : r.summary.percentiles[k]) {
      out += ',';
      append_csv_number(out, p, digits);
    }
    out += '\n';
  }
  return out;
}

std::string monte_carlo_table(const MonteCarloReport& r) {
  const MonteCarloSummary& summary = r.summary;
  std::vector<std::string> described;
  for (const UncertainInput& u : r.inputs) described.push_back(describe_uncertain(u));
  std::vector<std::string> fixed;
  for (const FixedInput& f : r.fixed) {
    const std::string name = f.name.size() > 4 && f.name.substr(f.name.size() - 4) == "_deg" ? f.name.substr(0, f.name.size() - 4) : f.name;
    fixed.push_back(name + " " + quantity_text(f.value, f.dimension, UnitSystem::si, 6));
  }
  if (fixed.empty()) fixed.push_back("none");
  std::ostringstream out;
  out << "Monte Carlo: " << summary.samples << " samples (--seed " << r.seed << ") of " << r.subject << ", " << format_significant(r.seconds, 3)
      << " s on " << r.threads << " thread(s)\n"
      << "uncertain: " << join(described, ", ") << "\n"
      << "fixed: " << join(fixed, ", ") << "\n"
      << "assumptions: " << r.assumptions << "\n"
      << "ranges in " << r.air << "\n";
  if (!summary.values.empty()) {
    const char* labels[] = {"R [m]", "T [kJ]", "eps [%]", "v [m/s]"};
    const double scales[] = {1, 1e-3, 100, 1};
    out << "           5 %        50 %       95 %\n";
    for (std::size_t k = 0; k < sample_names.size(); ++k) {
      std::string line = labels[k];
      line.resize(9, ' ');
      for (double p : summary.percentiles[k]) {
        std::string cell = format_significant(p * scales[k], 4);
        cell.resize(11, ' ');
        line += cell;
      }
      out << line.substr(0, line.find_last_not_of(' ') + 1) << "\n";
    }
  }
  out << "failed: " << summary.samples - static_cast<int>(summary.values.size()) << " samples";
  for (const SampleFailures& f : summary.failures) out << "; " << f.count << " " << f.reason;
  out << "\n";
  // An input's value in words, as its user gave it: "--M 3.6 t".
  const auto value_of = [&](std::size_t k, double value) {
    return r.inputs[k].name + " " + quantity_text(value, r.inputs[k].dimension, UnitSystem::si, 3);
  };
  if (r.claim && !summary.values.empty()) {
    const ClaimAssessment c = assess_claim(summary, *r.claim);
    out << "claim R >= " << format_significant(c.claim, 4) << " m: reached by " << c.reached << " of the " << c.worked << " samples that worked, "
        << format_significant(100 * c.probability, 3) << " % (95 %: " << format_significant(100 * c.low, 3) << " to "
        << format_significant(100 * c.high, 3) << " %, Wilson)\n";
    if (!c.median_reaching.empty()) {
      std::vector<std::string> medians;
      for (std::size_t k = 0; k < c.median_reaching.size(); ++k) {
        medians.push_back(value_of(k, c.median_reaching[k]) +
                          " (all: " + quantity_text(median_drawn(summary, k), r.inputs[k].dimension, UnitSystem::si, 3) + ")");
      }
      out << "  the samples that reach it, at their median: " << join(medians, ", ") << "\n";
    }
    if (r.claim_context) out << claim_context_text(*r.claim_context, c.claim);
  }
  const std::vector<RankCorrelation> rho = rank_correlations(summary);
  if (!rho.empty()) {
    std::vector<std::string> names;
    for (const UncertainInput& input : r.inputs) names.push_back(input.name);
    out << moves_most_text("R", "R", names, rho, summary.values.size()) << "\n";
  }
  return out.str();
}

CompletionReport complete_with_longest(const CompletionRequest& request, const std::function<std::string(std::string_view)>& word) {
  CompletionReport report{complete_engine(request), std::nullopt, ""};
  if (request.settings.criterion.release != Release::range) {
    CompletionRequest for_range = request;
    for_range.settings.criterion.release = Release::range;
    try {
      report.longest = complete_engine(for_range);
    } catch (const Error& e) {
      report.longest_note = e.message(word);
    }
  }
  return report;
}

}  // namespace trebuchet
