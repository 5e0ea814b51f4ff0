// trebuchet-verify: the ab-initio shot of an engine (appendix A), its capacity, efficiency,
// forces and quality at the best release, checked against a predicted capacity; and, as
// subcommands, the capacity fit, the ab-initio optimum and the re-derivation of tab:CPNC.
// Parses, calls the library, prints. Exit codes: cli/exit_codes.hpp, docs/exit_codes.md.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <sstream>
#include <map>
#include <random>
#include <optional>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "program.hpp"
#include "trebuchet/air.hpp"
#include "trebuchet/capacity_fit.hpp"
#include "trebuchet/completion.hpp"
#include "trebuchet/app/csv.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/app/names.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/parallel.hpp"
#include "trebuchet/app/pictures.hpp"
#include "trebuchet/app/report.hpp"
#include "trebuchet/app/request.hpp"
#include "trebuchet/app/schema.hpp"
#include "trebuchet/sweep.hpp"
#include "trebuchet/table_derivation.hpp"
#include "trebuchet/app/table_json.hpp"
#include "trebuchet/app/text_input.hpp"
#include "trebuchet/uncertainty.hpp"
#include "trebuchet/app/units.hpp"
#include "trebuchet/verification.hpp"

namespace {

using namespace trebuchet;

const char* const subcommands[] = {"shot", "fit", "optimize", "derive-table", "merge", "complete"};

// Options as typed; parsed after CLI11 has matched them, so that messages name the option.
struct Options {
  std::string input;                                 // file, "-" for stdin, empty for flags
  std::map<std::string, std::string> engine_flags;   // L1 L2 L3 F L4 M m mb
  std::string theta, psi_i, g, R, T, beta2;
  std::string tolerance = "0.02";
  std::string target_level = "0";
  std::string format = "table";
  std::string series, series_dt, plot;
  std::string quality = "Q", n = "1";
  std::string stepper = stepper_name(IntegratorSettings{}.stepper), rtol, atol;
  std::string X_grid = "-0.55:0.55:0.05";
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::string shard;
  std::vector<std::string> merge;
  std::string digits;  // empty: default_csv_digits
  bool air = false;
  std::string air_density, drag_coefficient, projectile, wind;
  std::string range_from = "pivot";
  std::string Lb, H, D, l, wood_density;  // complete: what a source attests
  int samples = 10000;                    // Monte Carlo, when a value is a range or a spread
  std::uint64_t seed = 1;
};

const std::pair<const char*, UnitDimension> engine_keys[] = {
    {"L1", UnitDimension::length}, {"L2", UnitDimension::length}, {"L3", UnitDimension::length},
    {"F", UnitDimension::dimensionless}, {"L4", UnitDimension::length}, {"M", UnitDimension::mass},
    {"m", UnitDimension::mass}, {"mb", UnitDimension::mass}};

// The JSON of a file, or of stdin for "-"; `expected` says what it should hold, for messages.
nlohmann::json read_json(const std::string& path, const std::string& expected) {
  return parse_json(read_text(path, expected), source_name(path), expected);
}

ShotSettings shot_settings(const Options& o) {
  ShotSettings settings;
  settings.integrator.stepper = parse_stepper(o.stepper, "--stepper");
  if (!o.rtol.empty()) settings.integrator.rtol = parse_positive(o.rtol, UnitDimension::dimensionless, "--rtol");
  if (!o.atol.empty()) settings.integrator.atol = parse_positive(o.atol, UnitDimension::dimensionless, "--atol");
  settings.target_level = parse_value(o.target_level, UnitDimension::length, "--target-level");
  settings.criterion.release = parse_release(o.quality, "--quality");
  settings.criterion.n = parse_value(o.n, UnitDimension::dimensionless, "--n");
  if (o.range_from != "pivot" && o.range_from != "release")
    throw Error(ErrorKind::usage, "--range-from: '" + o.range_from + "' is not a range; use pivot (the paper's) or release (Denny's)");
  settings.range_from_release = o.range_from == "release";
  const bool air_details = !o.air_density.empty() || !o.drag_coefficient.empty() || !o.projectile.empty() || !o.wind.empty();
  if (air_details && !o.air)
    throw Error(ErrorKind::usage, "--air-density, --cd, --projectile and --wind describe the air; add --air to fly through it (vacuum is the default)");
  if (o.air) {
    Air air;
    if (!o.air_density.empty()) air.density = parse_positive(o.air_density, UnitDimension::density, "--air-density");
    if (o.drag_coefficient == "Re") air.drag_coefficient.reset();
    else if (!o.drag_coefficient.empty()) air.drag_coefficient = parse_positive(o.drag_coefficient, UnitDimension::dimensionless, "--cd");
    if (o.projectile == "stone") air.projectile_density = 2500;
    else if (o.projectile == "iron") air.projectile_density = 7870;
    else if (!o.projectile.empty()) air.projectile_density = parse_positive(o.projectile, UnitDimension::density, "--projectile");
    if (!o.wind.empty()) air.wind = parse_value(o.wind, UnitDimension::speed, "--wind");
    settings.air = air;
  }
  if (!(settings.criterion.n >= 0)) throw Error(ErrorKind::bad_number, "--n: '" + o.n + "' must be 0 or more (eq:Q_n)");
  return settings;
}

// The material that sizes engines (fit, optimize, derive-table): eq:kMkD's wood, --beta2 and
// --g over `base`.
Material sizing_material(const Options& o, Material base) {
  if (!o.beta2.empty()) base.beta2 = parse_positive(o.beta2, UnitDimension::dimensionless, "--beta2");
  if (!o.wood_density.empty()) base.wood_density = parse_positive(o.wood_density, UnitDimension::density, "--wood-density");
  if (!o.g.empty()) base.g = parse_positive(o.g, UnitDimension::acceleration, "--g");
  return base;
}

void check_format(const Options& o, bool csv_too = false) {
  if (o.format != "table" && o.format != "json" && !(csv_too && o.format == "csv"))
    throw Error(ErrorKind::usage, "--format: '" + o.format + "' is not a format; use table" + (csv_too ? ", json or csv" : " or json"));
}

struct Outcome {
  nlohmann::ordered_json json;
  std::string table;
  std::vector<std::string> csv;  // with --format csv
  int code = exit_success;
};

// Runs gnuplot on `script` inside `folder`; an error names what failed and how to fix it.
void run_gnuplot(const std::filesystem::path& folder, const std::string& script) {
  // What is printed so far must not be copied into the child, whose freopen would flush it again.
  std::cout.flush();
  std::fflush(stdout);
  const pid_t child = fork();
  if (child == 0) {
    // gnuplot's own messages go to gnuplot.log in the folder.
    if (chdir(folder.c_str()) == 0 && std::freopen("gnuplot.log", "a", stderr) && std::freopen("gnuplot.log", "a", stdout))
      execlp("gnuplot", "gnuplot", script.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error(ErrorKind::usage, "--plot: gnuplot failed on " + (folder / script).string() + ", see gnuplot.log there" +
                                      (child >= 0 && WIFEXITED(status) && WEXITSTATUS(status) == 127 ? " (gnuplot is not installed; apt-get install gnuplot-nox)" : ""));
}

// --plot DIR: writes the picture files (pictures.hpp) into the folder, then runs gnuplot on
// each of `scripts` there.
void write_pictures(const std::string& dir, const std::vector<PictureFile>& files, const std::vector<std::string>& scripts) {
  const std::filesystem::path folder(dir);
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  std::filesystem::remove(folder / "gnuplot.log", ec);
  for (const PictureFile& file : files) {
    std::ofstream out(folder / file.name);
    out << file.text;
    if (!out) throw Error(ErrorKind::usage, "--plot: cannot write " + (folder / file.name).string() + "; give a folder you can write to");
  }
  for (const std::string& script : scripts) run_gnuplot(folder, script);
}

// One design: read, optionally fitted to its capacity, shot, and checked against its capacity.
Outcome verify_one(const nlohmann::json& object, const std::string& where, const Options& o, const ShotSettings& settings,
                   double tolerance, bool fit, int digits) {
  EngineRecord in = read_engine(object, where);
  Engine engine = in.engine;
  engine.material = sizing_material(o, engine.material);
  Outcome out;
  nlohmann::ordered_json fitted;
  std::string fitted_table;
  if (fit) {
    if (!in.capacity) throw Error(ErrorKind::usage, "fit needs a capacity; give --R and --T, or \"R\" and \"T\" in the input");
    const CapacityFit result = fit_capacity(scaled_design(engine), *in.capacity, engine.material, settings);
    engine = result.engine;
    write_engine(fitted, engine);
    fitted["simulations"] = result.simulations;
    fitted_table = "fitted engine (" + std::to_string(result.simulations) + " shots):\n" + engine_table(engine);
  }
  std::vector<TracePoint> trace;
  const double series_dt = o.series_dt.empty() ? 0 : parse_positive(o.series_dt, UnitDimension::time, "--series-dt");
  const Verification v = verify_engine(engine, settings, o.series.empty() ? nullptr : &trace, series_dt);
  if (!o.plot.empty()) write_pictures(o.plot, shot_pictures(engine, settings), picture_scripts());
  std::optional<CapacityCheck> check;
  if (in.capacity) check = check_capacity(v, *in.capacity, tolerance);
  out.json = verification_json(v, check);
  out.table = fitted_table + verification_table(engine, settings, v, check);
  if (o.format == "csv") out.csv = verification_csv_row(engine, settings, v, check, digits);
  // The engine simulated (for fit, the fitted one, with its shots) and what the shot assumed.
  if (!fit) write_engine(fitted, engine);
  out.json["engine"] = fitted;
  out.json["assumptions"] = assumptions_json(engine, settings);
  if (!o.series.empty()) {
    std::ofstream file(o.series);
    file << trace_csv(trace, engine);
    if (!file) throw Error(ErrorKind::usage, "--series: cannot write '" + o.series + "'");
  }
  if (check && !check->pass) out.code = exit_outside_tolerance;
  return out;
}

// The design given as flags (--L1 ... --theta, --psi-i), as the JSON object read_engine reads.
nlohmann::json flags_design(const Options& o) {
  nlohmann::json flags = nlohmann::json::object();
  for (const auto& [key, text] : o.engine_flags)
    if (!text.empty()) flags[key] = text;
  if (!o.theta.empty()) flags["theta_i_deg"] = o.theta;
  if (!o.psi_i.empty()) flags["psi_i_deg"] = o.psi_i;
  return flags;
}

// complete's request from the options (completion.hpp).
CompletionRequest completion_request(const Options& o) {
  CompletionRequest request;
  Attested& a = request.attested;
  auto read = [](const std::string& text, UnitDimension dimension, const char* name) {
    return text.empty() ? std::nullopt : std::optional<double>(parse_value(text, dimension, name));
  };
  a.Lb = read(o.Lb, UnitDimension::length, "--Lb");
  a.L1 = read(o.engine_flags.at("L1"), UnitDimension::length, "--L1");
  a.L2 = read(o.engine_flags.at("L2"), UnitDimension::length, "--L2");
  a.H = read(o.H, UnitDimension::length, "--H");
  a.L4 = read(o.engine_flags.at("L4"), UnitDimension::length, "--L4");
  a.M = read(o.engine_flags.at("M"), UnitDimension::mass, "--M");
  a.m = read(o.engine_flags.at("m"), UnitDimension::mass, "--m");
  a.mb = read(o.engine_flags.at("mb"), UnitDimension::mass, "--mb");
  a.D = read(o.D, UnitDimension::length, "--D");
  a.l = read(o.l, UnitDimension::dimensionless, "--l");
  a.theta_i_deg = read(o.theta, UnitDimension::angle, "--theta");
  a.F = read(o.engine_flags.at("F"), UnitDimension::dimensionless, "--F");
  request.material = sizing_material(o, Material{});
  request.settings = shot_settings(o);
  return request;
}

// The options whose value may be a range or a spread (uncertainty.hpp), in an Options.
struct SpreadOption {
  std::string name;
  std::string* text;
  UnitDimension dimension;
};

std::vector<SpreadOption> spread_options(Options& o) {
  std::vector<SpreadOption> all;
  for (const auto& [key, dimension] : engine_keys) all.push_back({"--" + std::string(key), &o.engine_flags[key], dimension});
  const std::pair<const char*, std::pair<std::string*, UnitDimension>> others[] = {
      {"--theta", {&o.theta, UnitDimension::angle}},        {"--psi-i", {&o.psi_i, UnitDimension::angle}},
      {"--target-level", {&o.target_level, UnitDimension::length}},
      {"--wind", {&o.wind, UnitDimension::speed}},          {"--air-density", {&o.air_density, UnitDimension::density}},
      {"--Lb", {&o.Lb, UnitDimension::length}},             {"--H", {&o.H, UnitDimension::length}},
      {"--D", {&o.D, UnitDimension::length}},               {"--l", {&o.l, UnitDimension::dimensionless}}};
  for (const auto& [name, option] : others) all.push_back({name, option.first, option.second});
  return all;
}

// An uncertain option of a run, with its distribution.
struct Uncertain {
  std::string name;
  UnitDimension dimension;
  Spread spread;
};

std::vector<Uncertain> spreads_of(const Options& o) {
  Options copy = o;
  std::vector<Uncertain> spreads;
  for (const SpreadOption& option : spread_options(copy))
    if (!option.text->empty())
      if (const auto spread = parse_spread(*option.text, option.dimension, option.name))
        spreads.push_back({option.name, option.dimension, *spread});
  return spreads;
}

bool has_spreads(const Options& o) { return !spreads_of(o).empty(); }

// The options with each uncertain one set to value(its spread), in SI units.
Options with_values(const Options& o, const std::vector<Uncertain>& spreads, const std::function<double(const Spread&)>& value) {
  Options set = o;
  for (SpreadOption& option : spread_options(set))
    for (const Uncertain& u : spreads)
      if (u.name == option.name) *option.text = format_number(value(u.spread));
  return set;
}

std::string describe_spread(const Uncertain& u) {
  const Spread& s = u.spread;
  const char* unit = u.dimension == UnitDimension::length ? " m" : u.dimension == UnitDimension::mass ? " kg"
                     : u.dimension == UnitDimension::angle ? " deg" : u.dimension == UnitDimension::speed ? " m/s"
                     : u.dimension == UnitDimension::density ? " kg/m3" : "";
  return u.name + (s.kind == Spread::Kind::uniform ? " uniform " + format_significant(s.a, 6) + ".." + format_significant(s.b, 6)
                                                   : " normal " + format_significant(s.a, 6) + "±" + format_significant(s.b, 6)) + unit;
}

// Monte Carlo over the uncertain options: each sample sets them to a draw (in SI units) and runs
// the shot or the completion; the percentiles of R, T, eps and v, the failures, a histogram.
int run_monte_carlo_of(const Options& o, bool complete) {
  if (!o.input.empty()) throw Error(ErrorKind::usage, "ranges and spreads are for values given as flags; drop the file '" + o.input + "'");
  // A million shots take about a minute on two cores; more is not a question worth asking here.
  if (o.samples < 1 || o.samples > 1000000)
    throw Error(ErrorKind::usage, "--samples: " + std::to_string(o.samples) + " must be 1 to 1000000; 10000 give the 5 and 95 % to about 1 %");
  if (!o.series.empty()) throw Error(ErrorKind::usage, "--series writes the motion of one shot; a Monte Carlo run has many");
  const auto spreads = spreads_of(o);
  std::vector<std::string> described;
  for (const Uncertain& u : spreads) described.push_back(describe_spread(u));
  const std::string title = join(described, ", ");
  const auto start = std::chrono::steady_clock::now();
  const MonteCarloSummary summary = run_monte_carlo(o.samples, o.seed, o.threads, [&](std::mt19937_64& random) {
    const Options sample = with_values(o, spreads, [&](const Spread& s) { return draw(s, random); });
    SampleOutcome outcome;
    try {
      Verification v;
      if (complete) {
        v = complete_engine(completion_request(sample)).verification;
      } else {
        Engine engine = read_engine(flags_design(sample), "").engine;
        engine.material = sizing_material(sample, engine.material);
        v = verify_engine(engine, shot_settings(sample));
      }
      outcome.values = {v.capacity.R, v.capacity.T, v.eps, v.v};
    } catch (const Error& e) {
      outcome.failure = e.what();
    }
    return outcome;
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The assumptions of the run, with each uncertain option at a value of its spread.
  const ShotSettings settings = shot_settings(with_values(o, spreads, [](const Spread& s) { return s.a; }));
  const std::string air = settings.air ? "air" : "vacuum";
  if (o.format == "json") {
    nlohmann::ordered_json out;
    out["samples"] = summary.samples;
    out["seed"] = o.seed;
    out["worked"] = summary.values.size();
    nlohmann::ordered_json uncertain = nlohmann::ordered_json::array();
    for (const auto& [name, dimension, spread] : spreads)
      uncertain.push_back({{"option", name}, {"distribution", spread.kind == Spread::Kind::uniform ? "uniform" : "normal"},
                           {spread.kind == Spread::Kind::uniform ? "from" : "mean", spread.a}, {spread.kind == Spread::Kind::uniform ? "to" : "deviation", spread.b}});
    out["uncertain"] = uncertain;
    for (std::size_t k = 0; k < sample_names.size(); ++k)
      if (!summary.values.empty())
        out["percentiles"][sample_names[k]] = {{"p5", summary.percentiles[k][0]}, {"p50", summary.percentiles[k][1]}, {"p95", summary.percentiles[k][2]}};
    nlohmann::ordered_json failures = nlohmann::ordered_json::array();
    for (const auto& [reason, count] : summary.failures) failures.push_back({{"reason", reason}, {"count", count}});
    out["failures"] = failures;
    out["air"] = air;
    out["wall_time_s"] = seconds;
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << "Monte Carlo: " << summary.samples << " samples (--seed " << o.seed << ") of " << (complete ? "the completed engine" : "the shot")
              << ", " << format_significant(seconds, 3) << " s on " << thread_count(o.threads, static_cast<std::size_t>(summary.samples)) << " thread(s)\n"
              << "uncertain: " << title << "\n"
              << "ranges in " << (settings.air ? describe_air(*settings.air, 0) : std::string("vacuum")) << "\n";
    if (!summary.values.empty()) {
      const char* labels[] = {"R [m]", "T [kJ]", "eps [%]", "v [m/s]"};
      const double scales[] = {1, 1e-3, 100, 1};
      std::cout << "           5 %        50 %       95 %\n";
      for (std::size_t k = 0; k < sample_names.size(); ++k) {
        std::string line = labels[k];
        line.resize(9, ' ');
        for (double p : summary.percentiles[k]) {
          std::string cell = format_significant(p * scales[k], 4);
          cell.resize(11, ' ');
          line += cell;
        }
        std::cout << line.substr(0, line.find_last_not_of(' ') + 1) << "\n";
      }
    }
    std::cout << "failed: " << summary.samples - static_cast<int>(summary.values.size()) << " samples";
    for (const auto& [reason, count] : summary.failures) std::cout << "; " << count << " " << reason;
    std::cout << "\n";
  }
  if (!o.plot.empty()) write_pictures(o.plot, histogram_pictures(summary, title), {"histogram.gp"});
  if (summary.values.empty()) throw Error(ErrorKind::numerical, "no sample worked; the first reason: " + summary.failures.front().first);
  return exit_success;
}

// The designs of a run: a JSON object, a JSON array, CSV rows (docs/csv.md), or the flags.
struct Inputs {
  std::vector<std::string> passed_columns;  // CSV columns that pass through, e.g. site
  std::vector<DesignRows::Row> rows;
  std::vector<std::string> where;           // how messages name each row: "design[2]", "line 3"
  bool single = true;                       // one object or the flags: an error ends the run
};

Inputs read_inputs(const Options& o) {
  Inputs in;
  const std::string expected = "a design object like {\"L1\": \"6.13m\", ...}, an array of them, or CSV with a header (docs/csv.md)";
  const std::string text = read_text(o.input, expected);
  // JSON if it is named .json, parses as JSON or opens like it (then its error is JSON's); else CSV.
  const std::size_t start = text.find_first_not_of(" \t\r\n", text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0);
  const bool named_json = o.input.size() >= 5 && o.input.compare(o.input.size() - 5, 5, ".json") == 0;
  const bool csv = !named_json && start != std::string::npos && text[start] != '{' && text[start] != '[' && !nlohmann::json::accept(text);
  if (csv) {
    std::istringstream stream(text);
    DesignRows csv = read_design_rows(stream, source_name(o.input));
    in.passed_columns = std::move(csv.passed_columns);
    in.rows = std::move(csv.rows);
    for (const auto& row : in.rows) in.where.push_back("line " + std::to_string(row.line));
    in.single = false;
    return in;
  }
  nlohmann::json json = parse_json(text, source_name(o.input), expected);
  if (!json.is_object() && !json.is_array())
    throw Error(ErrorKind::usage, source_name(o.input) + " holds " + json.dump() + ", not a design; give " + expected);
  in.single = json.is_object();
  // Moved, not copied: a copy of deeply nested input would recurse as deep as it nests.
  for (std::size_t i = 0; i < (in.single ? 1 : json.size()); ++i) {
    in.rows.push_back({0, in.single ? std::move(json) : std::move(json[i]), {}, ""});
    in.where.push_back(in.single ? "design" : "design[" + std::to_string(i) + "]");
  }
  return in;
}

// shot and fit: the design from a file, stdin or flags; many designs (a JSON array or CSV rows)
// are computed design by design.
int run_shot(const Options& o, bool fit) {
  check_format(o, true);
  if (!fit && has_spreads(o)) return run_monte_carlo_of(o, false);
  if (o.threads < 1) throw Error(ErrorKind::usage, "--threads: " + std::to_string(o.threads) + " must be 1 or more");
  const ShotSettings settings = shot_settings(o);
  const double tolerance = parse_positive(o.tolerance, UnitDimension::dimensionless, "--tol");
  const int digits = o.digits.empty() ? default_csv_digits : parse_digits(o.digits, "--digits");
  const bool has_engine_flags = !o.theta.empty() || !o.psi_i.empty() || std::any_of(o.engine_flags.begin(), o.engine_flags.end(),
                                                                 [](const auto& kv) { return !kv.second.empty(); });
  Inputs in;
  if (!o.input.empty()) {
    if (has_engine_flags)
      throw Error(ErrorKind::usage, "the engine comes from '" + o.input + "'; drop the engine flags (--L1 ... --theta), or drop the file");
    in = read_inputs(o);
  } else {
    if (!o.engine_flags.at("L3").empty() && !o.engine_flags.at("F").empty())
      throw Error(ErrorKind::usage, "--L3 and --F both fix the counterweight arm (L2 + L3 = F H); give one of them");
    if (!has_engine_flags)
      throw Error(ErrorKind::usage, "no design; give a JSON or CSV file (or - for stdin), or flags like --L1 6.13m --L2 1.08m --F 1 --L4 5.8m --M 14.3t --m 100kg --mb 660kg");
    in.rows.push_back({0, flags_design(o), {}, ""});
    in.where.push_back("");
  }
  const std::size_t count = in.rows.size();
  // --R/--T on the command line give the capacity of a single design.
  if (!in.single && (!o.R.empty() || !o.T.empty()))
    throw Error(ErrorKind::usage, "--R and --T give the capacity of one design, but " + source_name(o.input) + " holds " +
                                      std::to_string(count) + "; give R and T in each design instead");
  if (!o.series.empty() && count != 1)
    throw Error(ErrorKind::usage, "--series writes the motion of one design; the input holds " + std::to_string(count));
  if (!o.plot.empty() && count != 1)
    throw Error(ErrorKind::usage, "--plot draws one design; the input holds " + std::to_string(count));
  std::vector<std::string> csv_header = in.passed_columns;
  for (const std::string& column : verification_csv_header()) csv_header.push_back(column);
  if (in.single) {
    nlohmann::json& design = in.rows.front().design;
    if (!o.R.empty()) design["R"] = o.R;
    if (!o.T.empty()) design["T"] = o.T;
    const Outcome out = verify_one(design, in.where.front(), o, settings, tolerance, fit, digits);
    if (o.format == "json") std::cout << out.json.dump(2) << "\n";
    else if (o.format == "csv") std::cout << csv_line(csv_header) << csv_line(out.csv);
    else std::cout << out.table;
    return out.code;
  }
  // Many designs: every one is tried, on every core; a failing one is reported in its place, the
  // others kept. Each design's outcome goes to its own slot and all are printed in input order,
  // so the output is the same on any number of threads.
  std::vector<Outcome> outcomes(count);
  std::vector<std::optional<Error>> errors(count);
  for_each_index(count, o.threads, [&](std::size_t i) {
    if (!in.rows[i].error.empty()) {  // unreadable, or failed upstream (the calculator's "error" column)
      errors[i] = Error(ErrorKind::usage, in.rows[i].error);
      return;
    }
    try {
      outcomes[i] = verify_one(in.rows[i].design, in.where[i], o, settings, tolerance, fit, digits);
    } catch (const Error& e) {
      errors[i] = e;
    }
  });
  nlohmann::ordered_json results = nlohmann::ordered_json::array();
  if (o.format == "csv") {
    csv_header.push_back("error");
    std::cout << csv_line(csv_header);
  }
  int code = exit_success;
  for (std::size_t i = 0; i < count; ++i) {
    nlohmann::ordered_json passed = nlohmann::ordered_json::object();
    for (std::size_t k = 0; k < in.passed_columns.size(); ++k) passed[in.passed_columns[k]] = in.rows[i].passed[k];
    std::vector<std::string> cells = in.rows[i].passed;
    // Messages name the row by its input line and its pass-through cells, "line 3 (site Saone)".
    std::string cells_text;
    for (std::size_t k = 0; k < in.passed_columns.size(); ++k)
      if (in.passed_columns[k] != "line") cells_text += (cells_text.empty() ? "" : ", ") + in.passed_columns[k] + " " + in.rows[i].passed[k];
    const std::string name = in.where[i] + (cells_text.empty() ? "" : " (" + cells_text + ")");
    if (const auto& e = errors[i]) {
      const int error_code = exit_code(Program::verify, e->kind());
      const bool named = std::string(e->what()).rfind(in.where[i], 0) == 0;
      std::cerr << "trebuchet-verify: " << (named ? "" : name + ": ") << e->what() << "\n";
      passed.update({{"error", e->what()}, {"exit_code", error_code}});
      cells.resize(csv_header.size() - 1);
      cells.push_back(e->what());
      code = std::max(code, error_code);
    } else {
      passed.update(outcomes[i].json);
      cells.insert(cells.end(), outcomes[i].csv.begin(), outcomes[i].csv.end());
      cells.push_back("");
      if (o.format == "table") std::cout << name << "\n" << outcomes[i].table << "\n";
      code = std::max(code, outcomes[i].code);
    }
    results.push_back(passed);
    if (o.format == "csv") std::cout << csv_line(cells);
  }
  if (o.format == "json") std::cout << results.dump(2) << "\n";
  return code;
}

// The block of optimize and derive-table: --theta and --F, the paper's standard by default.
void read_block(const Options& o, double& theta_i_deg, double& F) {
  theta_i_deg = o.theta.empty() ? standard_theta_i_deg : parse_theta(o.theta, "--theta");
  const std::string& F_text = o.engine_flags.at("F");
  F = F_text.empty() ? standard_F : parse_positive(F_text, UnitDimension::dimensionless, "--F");
}

// optimize: the ab-initio optimum for the capacity, one per start (branch).
int run_optimize(const Options& o) {
  check_format(o);
  const std::string& m = o.engine_flags.at("m");
  if (o.R.empty() || o.T.empty() == m.empty())
    throw Error(ErrorKind::usage, "optimize needs a capacity: --R with --T, or --R with the stone's --m; e.g. --R 425m --T 224kJ, or --R 450m --m 100kg");
  OptimizeRequest request;
  request.capacity = {parse_positive(o.R, UnitDimension::length, "--R"), o.T.empty() ? 0 : parse_positive(o.T, UnitDimension::energy, "--T"), 0};
  if (!m.empty()) request.projectile_mass = parse_positive(m, UnitDimension::mass, "--m");
  read_block(o, request.theta_i_deg, request.F);
  request.material = sizing_material(o, Material{});
  request.settings = shot_settings(o);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Optimum> optima = optimize(request);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const Optimum& optimum : optima) {
    all.push_back(optimum_json(optimum, seconds));
    if (o.format == "table") std::cout << optimum_table(optimum, request.settings) << "\n";
  }
  if (o.format == "json") std::cout << all.dump(2) << "\n";
  else std::cout << "wall time " << format_significant(seconds, 3) << " s\n";
  return exit_success;
}

// Prints a table or sweep part; each X without an optimum is named on stderr and gives exit 3.
int print_derived(const nlohmann::ordered_json& json, const std::vector<double>& failed) {
  require_finite_json(json, "the table");
  std::cout << json.dump(2) << "\n";
  for (double X : failed) std::cerr << "trebuchet-verify: no optimum at X = " << format_number(X) << "; its reason is in the output, the fit used the other points\n";
  return failed.empty() ? exit_success : exit_code(Program::verify, ErrorKind::numerical);
}

// A progress bar on stderr, drawn only when stderr is a terminal.
std::function<void(int, int)> progress_bar() {
  if (!isatty(STDERR_FILENO)) return {};
  return [](int done, int total) {
    const int width = 30, filled = width * done / total;
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] " << done << "/" << total << " X points"
              << (done == total ? "\n" : "") << std::flush;
  };
}

// derive-table: optimise along X for one block; the table, or with --shard a part to merge.
int run_derive_table(const Options& o) {
  SweepPart part;
  part.origin = "the sweep";
  SweepSpec& spec = part.spec;
  read_block(o, spec.theta_i_deg, spec.F);
  spec.material = sizing_material(o, Material{});
  spec.criterion = shot_settings(o).criterion;
  char c1 = 0, c2 = 0, rest = 0;
  if (std::sscanf(o.X_grid.c_str(), "%lf%c%lf%c%lf%c", &spec.X_from, &c1, &spec.X_to, &c2, &spec.X_step, &rest) != 5 || c1 != ':' || c2 != ':')
    throw Error(ErrorKind::usage, "--X: '" + o.X_grid + "' is not from:to:step; e.g. --X -0.55:0.55:0.05");
  if (o.threads < 1) throw Error(ErrorKind::usage, "--threads: " + std::to_string(o.threads) + " must be 1 or more");
  if (!o.shard.empty()) part.shard = parse_shard(o.shard);
  const auto start = std::chrono::steady_clock::now();
  part.points = run_sweep(spec, part.shard, o.threads, progress_bar());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int shots = 0;
  std::vector<double> failed;
  for (const SweepPoint& p : part.points) {
    shots += p.simulations;
    if (!p.error.empty()) failed.push_back(p.X);
  }
  std::cerr << "trebuchet-verify: " << part.points.size() << " X points, " << shots << " shots, " << format_significant(seconds, 3)
            << " s on " << thread_count(o.threads, part.points.size()) << " threads\n";
  if (!o.shard.empty()) return print_derived(sweep_part_json(part), failed);
  const DerivedTable table = derive_table({part});
  return print_derived(derived_table_json(table), failed_points(table));
}

// complete: the best engine that keeps what a source attests (completion.hpp).
int run_complete(const Options& o) {
  check_format(o);
  if (has_spreads(o)) return run_monte_carlo_of(o, true);
  const CompletionRequest request = completion_request(o);
  Completion completion = complete_engine(request);
  completion.calculator_note = with_words(completion.calculator_note, option_word);
  if (o.format == "json") std::cout << completion_json(completion, request.settings).dump(2) << "\n";
  else std::cout << completion_table(completion, request.settings);
  return exit_success;
}

// merge: sweep parts into one table.
int run_merge(const Options& o) {
  std::vector<SweepPart> parts;
  for (const std::string& path : o.merge)
    parts.push_back(read_sweep_part(read_json(path, "a part written by derive-table --shard k/N"), "'" + path + "'"));
  const DerivedTable table = derive_table(parts);
  return print_derived(derived_table_json(table), failed_points(table));
}

void add_engine_options(CLI::App* app, Options& o) {
  app->add_option("input", o.input, "JSON file with a design or an array of designs, or CSV with a design a row (docs/csv.md); - for stdin");
  const std::map<std::string, std::string> help = {
      {"L1", "long beam section"}, {"L2", "short beam section"}, {"L3", "counterweight arm (or --F)"},
      {"F", "arm fraction (L2+L3)/H, instead of --L3"}, {"L4", "sling length"}, {"M", "counterweight mass"},
      {"m", "projectile mass"}, {"mb", "beam mass"}};
  for (const auto& [key, dimension] : engine_keys)
    app->add_option("--" + std::string(key), o.engine_flags[key],
                    help.at(key) + (dimension == UnitDimension::dimensionless ? "" : " [" + unit_list(dimension) + "]"));
  app->add_option("--theta", o.theta, "initial beam angle theta_i [deg] (default 30)");
  app->add_option("--psi-i", o.psi_i, "initial counterweight angle psi_i [deg] of a propped counterweight (default 0, hanging; "
                                      "negative: held back, the sense opposite to the beam's turn)");
  app->add_option("--R", o.R, "the predicted range to check (or to fit)");
  app->add_option("--T", o.T, "the predicted energy to check (or to fit)");
  app->add_option("--tol", o.tolerance, "relative tolerance on the predicted R and T")->capture_default_str();
  app->add_option("--target-level", o.target_level, "target height relative to the engine's base, e.g. -54m")->capture_default_str();
  app->add_option("--series", o.series, "write the time series of the shot (angles, forces, positions, energies) to this CSV file");
  app->add_option("--series-dt", o.series_dt, "sample the series every this many seconds (e.g. 5ms) instead of at the integrator's steps");
  app->add_option("--plot", o.plot, "draw the shot into this folder: SVG pictures, an animated GIF and index.html (needs gnuplot)");
  app->add_option("--threads", o.threads, "threads for an array of designs (default: the cores); the output is the same on any number");
}

void add_release_options(CLI::App* app, Options& o) {
  app->add_option("--quality", o.quality, "what the release maximises: Q (eq:Q, eq:Q_n), eps (appendix B) or range (Denny)")->capture_default_str();
  app->add_option("--n", o.n, "exponent of eps in eq:Q_n")->capture_default_str();
}

void add_integrator_options(CLI::App* app, Options& o) {
  app->add_option("--stepper", o.stepper, "GSL odeiv2 stepper: " + stepper_names())->capture_default_str();
  app->add_option("--rtol", o.rtol, "relative tolerance per step (default 1e-11)");
  app->add_option("--atol", o.atol, "absolute tolerance per step, scaled units (default 1e-11)");
}

void add_format_option(CLI::App* app, Options& o, bool csv_too = false) {
  app->add_option("--format", o.format, csv_too ? "table, json or csv" : "table or json")->capture_default_str();
  if (csv_too) app->add_option("--digits", o.digits, "significant digits of CSV numbers (default " + std::to_string(default_csv_digits) + "; 17: exact)");
}

void add_sizing_options(CLI::App* app, Options& o, const std::string& what) {
  app->add_option("--beta2", o.beta2, "allowed beam bending u2/L2 that sizes " + what + " (default: " + what + "'s own, else 1/300)");
}

// `trebuchet-verify design.json` means `trebuchet-verify shot design.json`: the subcommand
// `shot` is inserted unless argv names a subcommand or asks for the overall help.
std::vector<char*> with_default_subcommand(int argc, char** argv) {
  std::vector<char*> args(argv, argv + argc);
  static char shot[] = "shot";
  const std::string first = argc > 1 ? argv[1] : "";
  const bool named = std::find(std::begin(subcommands), std::end(subcommands), first) != std::end(subcommands);
  if (!named && first != "--help" && first != "-h") args.insert(args.begin() + 1, shot);
  return args;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "trebuchet-verify: the ab-initio physics of a swinging-counterweight trebuchet (Horsdal, appendix A).\n"
      "Values take SI suffixes (6.13m, 14.3t, 224kJ). Exit codes: 0 pass, 1 outside --tol, 2 bad input,\n"
      "3 numerical failure (docs/exit_codes.md). Without a subcommand, shot is meant.",
      "trebuchet-verify"};
  app.require_subcommand(1);
  Options o;
  CLI::App* shot = app.add_subcommand("shot", "range, energy, efficiency, forces and quality at the best release of a design "
                                              "(a JSON file, - for stdin, or flags), checked against a predicted capacity");
  CLI::App* fit = app.add_subcommand("fit", "keep a design's shape (l, l4, mu_b, theta_i, F); fit mu and the size to --R and --T, then shoot");
  CLI::App* optimizer = app.add_subcommand("optimize", "the ab-initio optimum for --R and --T (or --R and --m) at --theta and --F (section 5)");
  CLI::App* derive = app.add_subcommand("derive-table", "re-derive tab:CPNC for --theta and --F: optimise along --X and fit eq:f_ZX "
                                                        "(JSON for the calculator's --table)");
  CLI::App* merge = app.add_subcommand("merge", "join the parts written by derive-table --shard into one table");
  CLI::App* complete = app.add_subcommand("complete", "complete an engine from what a source attests (any of --Lb --L1 --L2 --H --L4 --M --m --mb --D "
                                                     "--theta --F): keep those, choose the rest for the highest Q (or --quality range)");
  for (CLI::App* sub : {shot, complete}) {
    sub->add_option("--samples", o.samples, "Monte Carlo samples, when a value is a range (2.5t..3.5t) or a spread (3.5m±0.2m)")->capture_default_str();
    sub->add_option("--seed", o.seed, "seed of the Monte Carlo draws: the same seed, the same result")->capture_default_str();
    sub->add_flag("--air", o.air, "fly through air (quadratic drag on a sphere) instead of vacuum; with --quality range the release maximises the range in air");
    sub->add_option("--air-density", o.air_density, "density of the air (default 1.2kg/m3)");
    sub->add_option("--cd", o.drag_coefficient, "drag coefficient of the sphere (default 0.47), or Re for Cd(Re) of a smooth sphere");
    sub->add_option("--projectile", o.projectile, "stone (2500kg/m3, the default), iron (7870kg/m3) or a density: gives the sphere's size");
    sub->add_option("--wind", o.wind, "horizontal wind toward the target, e.g. 5m/s or -20km/h (against)");
    sub->add_option("--range-from", o.range_from, "pivot (the paper's: to the target level) or release (Denny's: from the release point back to its height)")
        ->capture_default_str();
  }
  {
    const std::pair<const char*, std::string*> lengths[] = {{"--Lb", &o.Lb}, {"--H", &o.H}, {"--D", &o.D}};
    const char* help[] = {"beam length L1 + L2", "pivot height L1 cos(theta_i)", "beam diameter (instead of beta2)"};
    for (int k = 0; k < 3; ++k) complete->add_option(lengths[k].first, *lengths[k].second, std::string(help[k]) + " [" + unit_list(UnitDimension::length) + "]");
    complete->add_option("--l", o.l, "beam ratio L1/L2");
    for (const char* key : {"L1", "L2", "L4", "M", "m", "mb", "F"}) {
      const bool mass = key[0] == 'M' || key[0] == 'm';
      complete->add_option("--" + std::string(key), o.engine_flags[key], std::string("attested ") + key +
                                                                              (std::string(key) == "F" ? " (default 2/3)" : mass ? " [kg, t]" : " [m]"));
    }
    complete->add_option("--theta", o.theta, "attested initial beam angle theta_i [deg] (default 30, or from H and L1)");
    complete->add_option("--target-level", o.target_level, "target height relative to the engine's base, e.g. -54m")->capture_default_str();
    complete->add_option("--g", o.g, "gravitational acceleration (default 9.81m/s2)");
    complete->add_option("--threads", o.threads, "threads for a Monte Carlo run (default: the cores)");
    complete->add_option("--plot", o.plot, "with ranges or spreads: write the histogram of R and T into this folder (needs gnuplot)");
    complete->add_option("--wood-density", o.wood_density, "density of the beam's wood (default 700kg/m3), for D and mb");
    add_sizing_options(complete, o, "the beam");
    add_release_options(complete, o);
    add_integrator_options(complete, o);
    add_format_option(complete, o);
  }
  for (CLI::App* sub : {shot, fit}) {
    add_engine_options(sub, o);
    add_release_options(sub, o);
    add_integrator_options(sub, o);
    add_format_option(sub, o, true);
    sub->add_option("--g", o.g, "gravitational acceleration (default: the input's, else " + format_number(Material{}.g) + "m/s2)");
  }
  add_sizing_options(fit, o, "the design");
  optimizer->add_option("--R", o.R, "range [m]");
  optimizer->add_option("--T", o.T, "energy at the target [J]");
  optimizer->add_option("--m", o.engine_flags["m"], "projectile mass, instead of --T: the optimum for R with this stone, T free [kg]");
  for (CLI::App* sub : {optimizer, derive}) {
    sub->add_option("--theta", o.theta, "initial beam angle theta_i [deg] (default 30)");
    sub->add_option("--F", o.engine_flags["F"], "counterweight arm fraction (L2+L3)/H (default 2/3)");
    sub->add_option("--g", o.g, "gravitational acceleration (default " + format_number(Material{}.g) + "m/s2)");
    add_sizing_options(sub, o, "the engines");
    add_release_options(sub, o);
  }
  add_integrator_options(optimizer, o);
  add_format_option(optimizer, o);
  derive->add_option("--X", o.X_grid, "X points, from:to:step (eq:Xi)")->capture_default_str();
  derive->add_option("--threads", o.threads, "threads (default: the cores)");
  derive->add_option("--shard", o.shard, "run part k of N of the X points, e.g. 2/8, for merge");
  merge->add_option("parts", o.merge, "the files written by derive-table --shard k/N")->required();

  std::vector<char*> args = with_default_subcommand(argc, argv);
  return run_program(app, Program::verify, static_cast<int>(args.size()), args.data(), [&] {
    if (shot->parsed()) return run_shot(o, false);
    if (fit->parsed()) return run_shot(o, true);
    if (optimizer->parsed()) return run_optimize(o);
    if (derive->parsed()) return run_derive_table(o);
    if (complete->parsed()) return run_complete(o);
    return run_merge(o);
  });
}
