// trebuchet-verify: the ab-initio shot of an engine (appendix A), its capacity, efficiency,
// forces and quality at the best release, checked against a predicted capacity. Parses,
// calls the library, prints. Exit codes: 0 pass, 1 outside --tol, 2 bad input, 3 numerical
// failure (docs/verifier.md).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <optional>
#include <thread>
#include <tuple>
#include <unistd.h>

#include "trebuchet/capacity_fit.hpp"
#include "trebuchet/design_input.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/program.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/request.hpp"
#include "trebuchet/sweep.hpp"
#include "trebuchet/table_derivation.hpp"
#include "trebuchet/units.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/verification_report.hpp"

namespace {

using namespace trebuchet;

constexpr int exit_pass = 0, exit_outside_tolerance = 1, exit_bad_input = 2, exit_numerical = 3;

int exit_code_of(const Error& e) { return e.kind() == ErrorKind::numerical ? exit_numerical : exit_bad_input; }

struct Options {
  std::string input;  // file, "-" for stdin, empty for flags
  std::map<std::string, std::string> engine_flags;  // L1 L2 L3 F L4 M m mb
  std::string theta = "30", g, R, T;
  std::string tolerance = "0.02";
  std::string beta2;
  std::string target_level = "0";
  std::string format = "table";
  std::string series;
  std::string quality = "Q";
  std::string n = "1";
  IntegratorSettings integrator;
  std::string rtol, atol;
  bool fit = false;
  bool optimize = false;
  bool derive_table = false;
  std::string X_grid = "-0.55:0.55:0.05";
  int threads = std::max(1u, std::thread::hardware_concurrency());
  std::string shard;
  std::vector<std::string> merge;
};

const std::pair<const char*, UnitDimension> engine_keys[] = {
    {"L1", UnitDimension::length}, {"L2", UnitDimension::length}, {"L3", UnitDimension::length},
    {"F", UnitDimension::dimensionless}, {"L4", UnitDimension::length}, {"M", UnitDimension::mass},
    {"m", UnitDimension::mass}, {"mb", UnitDimension::mass}};

// The flags as one JSON design, so that flags and files go through the same checks.
nlohmann::json design_from_flags(const Options& o) {
  nlohmann::json design;
  for (const auto& [key, text] : o.engine_flags)
    if (!text.empty()) design[key] = text;
  if (!o.theta.empty()) design["theta_i_deg"] = o.theta;
  if (!o.R.empty()) design["R"] = o.R;
  if (!o.T.empty()) design["T"] = o.T;
  return design;
}

// The JSON of a file, or of stdin for "-"; `expected` says what it should hold, for messages.
template <class Json>
Json read_json(const std::string& path, const std::string& expected) {
  std::string text;
  if (path == "-") {
    text.assign(std::istreambuf_iterator<char>(std::cin), {});
  } else {
    std::ifstream file(path);
    if (!file) throw Error(ErrorKind::usage, "cannot read '" + path + "'; give a JSON file, or - for stdin");
    text.assign(std::istreambuf_iterator<char>(file), {});
  }
  const std::string source = path == "-" ? std::string("stdin") : "'" + path + "'";
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw Error(ErrorKind::usage, source + " is empty; give " + expected);
  try {
    return Json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw Error(ErrorKind::usage, source + " is not valid JSON (" + e.what() + "); give " + expected);
  }
}

nlohmann::json read_input(const std::string& path) { return read_json<nlohmann::json>(path, "a design object or an array of them"); }

// The material that ties masses to lengths when the program sizes engines (--fit, --optimize,
// --derive-table): eq:kMkD's wood, --beta2 (default 1/300) and the shot's g.
Material material_of(const Options& o, const ShotSettings& settings) {
  Material material;
  material.g = settings.g;
  if (!o.beta2.empty()) material.beta2 = parse_positive(o.beta2, UnitDimension::dimensionless, "--beta2");
  return material;
}

struct Outcome {
  nlohmann::ordered_json json;
  std::string table;
  int code = exit_pass;
};

Outcome verify_one(const nlohmann::json& object, const std::string& where, const Options& o, const ShotSettings& base,
                   double tolerance) {
  const DesignInput in = design_from_json(object, where);
  ShotSettings settings = base;
  if (in.g && o.g.empty()) settings.g = *in.g;
  Outcome out;
  Engine engine = in.engine;
  std::optional<CapacityCheck> check;
  nlohmann::ordered_json fitted;
  std::string fitted_table;
  if (o.fit) {
    if (!in.R) throw Error(ErrorKind::usage, "--fit needs a capacity; give --R and --T, or \"R\" and \"T\" in the input");
    const CapacityFit fit = fit_capacity(engine_shape(engine), *in.R, *in.T, material_of(o, settings), settings);
    engine = fit.engine;
    fitted = engine_json(engine);
    fitted["simulations"] = fit.simulations;
    fitted_table = "fitted engine (" + std::to_string(fit.simulations) + " shots):\n" + engine_table(engine);
  }
  std::vector<TracePoint> trace;
  const Verification v = verify_engine(engine, settings, o.series.empty() ? nullptr : &trace);
  if (in.R) check = check_capacity(v, *in.R, *in.T, tolerance);
  out.json = verification_json(v, check);
  out.table = verification_table(v, check);
  if (o.fit) {
    out.json["engine"] = fitted;
    out.table = fitted_table + out.table;
  }
  if (!o.series.empty()) {
    std::ofstream file(o.series);
    file << trace_csv(trace, engine, settings.g);
    if (!file) throw Error(ErrorKind::usage, "--series: cannot write '" + o.series + "'");
  }
  if (check && !check->pass) out.code = exit_outside_tolerance;
  return out;
}

// The block of --optimize and --derive-table: --theta (default 30) and --F (default 2/3).
std::pair<double, double> theta_and_F(const Options& o) {
  return {o.theta.empty() ? 30 : parse_theta(o.theta, "--theta"),
          o.engine_flags.at("F").empty() ? 2.0 / 3 : parse_positive(o.engine_flags.at("F"), UnitDimension::dimensionless, "--F")};
}

// --optimize: the ab-initio optimum for the capacity, one per start (branch).
int run_optimizer(const Options& o, const ShotSettings& settings) {
  if (o.R.empty() || o.T.empty()) throw Error(ErrorKind::usage, "--optimize needs a capacity; give --R and --T, e.g. --R 425m --T 224kJ");
  if (!o.input.empty()) throw Error(ErrorKind::usage, "--optimize designs the engine itself; drop the input file");
  OptimizeRequest request;
  request.R = parse_positive(o.R, UnitDimension::length, "--R");
  request.T = parse_positive(o.T, UnitDimension::energy, "--T");
  std::tie(request.theta_i_deg, request.F) = theta_and_F(o);
  request.material = material_of(o, settings);
  request.settings = settings;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Optimum> optima = optimize(request);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const Optimum& optimum : optima) {
    const Engine& e = optimum.fit.engine;
    nlohmann::ordered_json design = engine_json(e);
    design["Lb"] = beam_length(e);
    design["H"] = pivot_height(e);
    design["l"] = optimum.shape.l;
    design["l4"] = optimum.shape.l4;
    design["mu"] = e.m / e.M;
    design["mu_b"] = optimum.shape.mu_b;
    design["start"] = optimum.start;
    design["simulations"] = optimum.simulations;
    design["iterations"] = optimum.iterations;
    design["wall_time_s"] = seconds;
    nlohmann::ordered_json shot = verification_json(optimum.fit.verification, std::nullopt);
    for (const auto& [key, value] : shot.items()) design[key] = value;
    all.push_back(design);
    if (o.format == "table")
      std::cout << "optimum from the " << optimum.start << " start (" << optimum.simulations << " shots, " << optimum.iterations
                << " simplex iterations):\n" << engine_table(e) << verification_table(optimum.fit.verification, std::nullopt) << "\n";
  }
  if (o.format == "json") std::cout << all.dump(2) << "\n";
  else std::cout << "wall time " << format_significant(seconds, 3) << " s\n";
  return exit_pass;
}

// Prints a table or sweep part; each X without an optimum is named on stderr and gives exit 3.
int print_derived(const nlohmann::ordered_json& json, const std::vector<double>& failed) {
  std::cout << json.dump(2) << "\n";
  for (double X : failed) std::cerr << "trebuchet-verify: no optimum at X = " << format_number(X) << "; its reason is in the output, the fit used the other points\n";
  return failed.empty() ? exit_pass : exit_numerical;
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

// --derive-table: optimise along X for one block; the table, or with --shard a part to --merge.
int run_derive_table(const Options& o, const ShotSettings& settings) {
  if (!o.input.empty()) throw Error(ErrorKind::usage, "--derive-table optimises its own engines; drop the input file");
  SweepSpec spec;
  std::tie(spec.theta_i_deg, spec.F) = theta_and_F(o);
  spec.material = material_of(o, settings);
  spec.quality = settings.quality;
  char c1 = 0, c2 = 0, rest = 0;
  if (std::sscanf(o.X_grid.c_str(), "%lf%c%lf%c%lf%c", &spec.X_from, &c1, &spec.X_to, &c2, &spec.X_step, &rest) != 5 || c1 != ':' || c2 != ':')
    throw Error(ErrorKind::usage, "--X: '" + o.X_grid + "' is not from:to:step; e.g. --X -0.55:0.55:0.05");
  if (o.threads < 1) throw Error(ErrorKind::usage, "--threads: " + std::to_string(o.threads) + " must be 1 or more");
  const Shard shard = o.shard.empty() ? Shard{} : parse_shard(o.shard);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<SweepPoint> points = run_sweep(spec, shard, o.threads, progress_bar());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int shots = 0;
  for (const SweepPoint& p : points) shots += p.simulations;
  std::cerr << "trebuchet-verify: " << points.size() << " X points, " << shots << " shots, " << format_significant(seconds, 3) << " s on "
            << o.threads << " threads\n";
  const nlohmann::ordered_json part = sweep_json(spec, shard, points);
  const nlohmann::ordered_json out = o.shard.empty() ? derive_table({{"the sweep", part}}) : part;
  std::vector<double> failed;
  for (const SweepPoint& p : points)
    if (!p.error.empty()) failed.push_back(p.X);
  return print_derived(out, failed);
}

// --merge: sweep parts into one table.
int run_merge(const Options& o) {
  std::vector<SweepPart> parts;
  for (const std::string& path : o.merge) {
    parts.push_back({"'" + path + "'", read_json<nlohmann::ordered_json>(path, "a part written by --derive-table --shard k/N")});
  }
  const nlohmann::ordered_json table = derive_table(parts);
  return print_derived(table, failed_points(table));
}

int run(const Options& o) {
  if (o.format != "table" && o.format != "json")
    throw Error(ErrorKind::usage, "--format: '" + o.format + "' is not a format; use table or json");
  ShotSettings settings;
  settings.integrator = o.integrator;
  if (!o.rtol.empty()) settings.integrator.rtol = parse_positive(o.rtol, UnitDimension::dimensionless, "--rtol");
  if (!o.atol.empty()) settings.integrator.atol = parse_positive(o.atol, UnitDimension::dimensionless, "--atol");
  if (!o.g.empty()) settings.g = parse_positive(o.g, UnitDimension::acceleration, "--g");
  settings.target_level = parse_value(o.target_level, UnitDimension::length, "--target-level");
  settings.quality.release = parse_release(o.quality);
  settings.quality.n = parse_value(o.n, UnitDimension::dimensionless, "--n");
  if (!(settings.quality.n >= 0)) throw Error(ErrorKind::bad_number, "--n: '" + o.n + "' must be 0 or more (eq:Q_n)");
  const double tolerance = parse_positive(o.tolerance, UnitDimension::dimensionless, "--tol");
  if (o.optimize) return run_optimizer(o, settings);
  if (o.derive_table) return run_derive_table(o, settings);
  if (!o.merge.empty()) return run_merge(o);

  const bool has_engine_flags = !o.theta.empty() || std::any_of(o.engine_flags.begin(), o.engine_flags.end(),
                                                                 [](const auto& kv) { return !kv.second.empty(); });
  nlohmann::json input;
  bool is_array = false;
  if (!o.input.empty()) {
    if (has_engine_flags)
      throw Error(ErrorKind::usage, "the engine comes from '" + o.input + "'; drop the engine flags (--L1 ... --theta), or drop the file");
    input = read_input(o.input);
    is_array = input.is_array();
    // --R/--T on the command line give the capacity of a single design from a file.
    if (!is_array && (!o.R.empty() || !o.T.empty())) {
      if (!o.R.empty()) input["R"] = o.R;
      if (!o.T.empty()) input["T"] = o.T;
    }
  } else {
    if (!has_engine_flags) throw Error(ErrorKind::usage, "no design; give a JSON file (or - for stdin), or flags like --L1 6.13m --L2 1.08m --F 1 --L4 5.8m --M 14.3t --m 100kg --mb 660kg");
    input = design_from_flags(o);
  }
  if (is_array && !o.series.empty() && input.size() != 1)
    throw Error(ErrorKind::usage, "--series writes the motion of one design; the input holds " + std::to_string(input.size()));
  if (!is_array) {
    const Outcome out = verify_one(input, o.input.empty() ? "" : "design", o, settings, tolerance);
    if (o.format == "json") std::cout << out.json.dump(2) << "\n";
    else std::cout << out.table;
    return out.code;
  }
  // An array: every design is tried; a failing one is reported in its place, the others kept.
  nlohmann::ordered_json results = nlohmann::ordered_json::array();
  int code = exit_pass, index = 0;
  for (const auto& object : input) {
    const std::string where = "design[" + std::to_string(index++) + "]";
    try {
      const Outcome out = verify_one(object, where, o, settings, tolerance);
      results.push_back(out.json);
      if (o.format == "table") std::cout << where << "\n" << out.table << "\n";
      code = std::max(code, out.code);
    } catch (const Error& e) {
      std::cerr << "trebuchet-verify: " << (std::string(e.what()).rfind(where, 0) == 0 ? "" : where + ": ") << e.what() << "\n";
      results.push_back({{"error", e.what()}, {"exit_code", exit_code_of(e)}});
      code = std::max(code, exit_code_of(e));
    }
  }
  if (o.format == "json") std::cout << results.dump(2) << "\n";
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "trebuchet-verify: the ab-initio shot of a swinging-counterweight trebuchet (Horsdal, appendix A):\n"
      "range, energy, efficiency, forces and quality at the best release, checked against a predicted\n"
      "capacity. Give a JSON design (the calculator's output, or hand-written), an array of them, or flags.\n"
      "Values take SI suffixes (6.13m, 14.3t, 224kJ). Exit codes: 0 pass, 1 outside --tol, 2 bad input,\n"
      "3 numerical failure.",
      "trebuchet-verify"};
  Options o;
  o.theta.clear();
  app.add_option("input", o.input, "JSON file with a design or an array of designs; - for stdin");
  const std::map<std::string, std::string> help = {
      {"L1", "long beam section"}, {"L2", "short beam section"}, {"L3", "counterweight arm (or --F)"},
      {"F", "arm fraction (L2+L3)/H, instead of --L3"}, {"L4", "sling length"}, {"M", "counterweight mass"},
      {"m", "projectile mass"}, {"mb", "beam mass"}};
  for (const auto& [key, dimension] : engine_keys) {
    o.engine_flags[key];
    app.add_option("--" + std::string(key), o.engine_flags[key],
                   help.at(key) + (dimension == UnitDimension::dimensionless ? "" : " [" + unit_list(dimension) + "]"));
  }
  app.add_option("--theta", o.theta, "initial beam angle theta_i [deg] (default 30)");
  app.add_option("--g", o.g, "gravitational acceleration (default: the input's, else 9.81m/s2)");
  app.add_option("--R", o.R, "predicted range to check, or the range to --fit");
  app.add_option("--T", o.T, "predicted energy to check, or the energy to --fit");
  app.add_option("--tol", o.tolerance, "relative tolerance on the predicted R and T")->capture_default_str();
  app.add_option("--beta2", o.beta2, "allowed beam bending u2/L2 when sizing engines (--fit, --optimize, --derive-table; default 1/300)");
  app.add_flag("--optimize", o.optimize, "find the ab-initio optimum for --R and --T at --theta and --F (section 5)");
  app.add_flag("--derive-table", o.derive_table, "re-derive tab:CPNC for --theta and --F: optimise along --X and fit eq:f_ZX (JSON for the calculator's --table)");
  app.add_option("--X", o.X_grid, "X points of --derive-table, from:to:step (eq:Xi)")->capture_default_str();
  app.add_option("--threads", o.threads, "threads for --derive-table (default: the cores)");
  app.add_option("--shard", o.shard, "with --derive-table: run part k of N of the X points, e.g. 2/8, for --merge");
  app.add_option("--merge", o.merge, "join the parts written by --derive-table --shard into one table");
  app.add_flag("--fit", o.fit, "keep the design's shape (l, l4, mu_b, theta_i, F); fit mu and the size to --R and --T");
  app.add_option("--target-level", o.target_level, "target height relative to the engine's base, e.g. -54m")->capture_default_str();
  app.add_option("--quality", o.quality, "what the release maximises: Q (eq:Q, eq:Q_n), eps (appendix B) or range (Denny)")->capture_default_str();
  app.add_option("--n", o.n, "exponent of eps in eq:Q_n")->capture_default_str();
  app.add_option("--format", o.format, "table or json")->capture_default_str();
  app.add_option("--series", o.series, "write the time series of the shot (angles, forces, energy) to this CSV file");
  app.add_option("--stepper", o.integrator.stepper, "GSL odeiv2 stepper: " + stepper_names())->capture_default_str();
  app.add_option("--rtol", o.rtol, "relative tolerance per step (default 1e-12)");
  app.add_option("--atol", o.atol, "absolute tolerance per step, scaled units (default 1e-13)");
  return run_program(app, argc, argv, exit_bad_input, [&] { return run(o); }, exit_code_of);
}
