#include "trebuchet/app/run/calibration_run.hpp"

#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/input/settings.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {

namespace {

// The engine and settings of a request's values as they stand, released as they give it.
std::pair<Engine, ShotSettings> engine_of_values(const MonteCarloRequest& sample) {
  ShotSettings settings = shot_settings(sample.settings);
  settings.release_at = release_of(sample.values, sample.where);
  return {engine_record(sample.values, sample.where).engine, settings};
}

// One draw: the unknowns and the measured range drawn, the friction fitted to it.
SampleOutcome calibration_sample(const CalibrationRunInputs& in, std::mt19937_64& random) {
  SampleOutcome outcome;
  try {
    const MonteCarloRequest sample = with_draws(in.request, [&](const Spread& s) {
      outcome.drawn.push_back(draw(s, random));  // with_draws asks each spread once, in the run's order
      return outcome.drawn.back();
    });
    const MeasuredRange& m = in.measured;
    const double range = m.uncertainty > 0 ? draw(Spread{Spread::Kind::normal, m.range, m.uncertainty}, random) : m.range;
    outcome.drawn.push_back(range);
    const auto [engine, settings] = engine_of_values(sample);
    outcome.values = {fit_friction(engine, range, settings), range, 0, 0};
  } catch (const Error& e) {
    outcome.failure = e.message([](std::string_view key) { return "--" + std::string(key); });
    outcome.failure_kind = e.kind();
  }
  return outcome;
}

std::string percent(double fraction) { return format_significant(100 * fraction, 3) + " %"; }

}  // namespace

CalibrationRun calibrate_over_unknowns(const CalibrationRunInputs& in, const Progress& progress) {
  const double lo = in.plausible[0], hi = in.plausible[1];
  if (!(lo >= 0 && lo < hi && hi <= 2))
    throw Error(ErrorKind::bad_number,
                "{{plausible_friction}} = " + format_significant(lo, 4) + ".." + format_significant(hi, 4) +
                    ": give the plausible friction coefficients as a range from 0 to at most 2, e.g. 0.1..0.5");
  if (!(in.measured.range > 0 && in.measured.uncertainty >= 0 && in.measured.uncertainty < in.measured.range))
    throw Error(ErrorKind::bad_number,
                "{{measured}} = " + format_significant(in.measured.range, 4) + " m ± " + format_significant(in.measured.uncertainty, 4) +
                    " m: give the measured range, e.g. 34.4m±1.5m");
  // The friction at the pins is what the run fits: drawn as an unknown, it would be fitted over
  // itself (issue 62: a "coefficient" of 2.9 to 82 from --axle-friction 0..0.3).
  for (const SpreadInput& spread : in.request.spreads)
    if (spread.value == &DesignValues::axle_friction || spread.value == &DesignValues::hinge_friction)
      throw Error(ErrorKind::usage,
                  "{{" + std::string(field_of(spread.value).key) +
                      "}} is what calibrate fits: drop its range (the span you deem plausible is --plausible-friction, "
                      "0.1..0.5 by default)");
  CalibrationRun run;
  run.given = in;
  // Bad input ends the run before it starts, with its exit code: the engine at the unknowns'
  // first values (in its own words), then at each end of each unknown's range (a normal spread's
  // 4 sigma), the others at their first (in the range's words): a range of radii that reaches
  // zero leaves nothing to fit at its end.
  const auto engine_at = [&](const SpreadInput* varied, double value) {
    const MonteCarloRequest sample = with_draws(in.request, [&](const Spread& s) { return varied && &s == &varied->input.spread ? value : s.a; });
    const auto [engine, settings] = engine_of_values(sample);
    check_engine(engine);
    check_shot_settings(settings);
    try {
      return friction_fit_of(engine);
    } catch (const Error&) {  // a pin of no radius at a range's end: say so in the range's words
      if (!varied) throw;
      throw Error(ErrorKind::bad_number, "no pin has a radius for a friction to act on there; start the range above 0");
    }
  };
  {  // the first values: a refusal of the engine there is its own, in its own words
    const auto [engine, settings] = engine_of_values(with_draws(in.request, [](const Spread& s) { return s.a; }));
    check_engine(engine);
    check_shot_settings(settings);
  }
  for (const SpreadInput& spread : in.request.spreads) {
    const Spread& s = spread.input.spread;
    const bool uniform = s.kind == Spread::Kind::uniform;
    for (const double end : {uniform ? s.a : s.a - 4 * s.b, uniform ? s.b : s.a + 4 * s.b}) try {
        engine_at(&spread, end);
      } catch (const Error& e) {
        throw Error(ErrorKind::bad_number,
                    describe_uncertain(spread.input) + (uniform ? " reaches " : " reaches, 4 sigma out, ") + format_significant(end, 4) + ": " +
                        e.message([](std::string_view key) { return "{{" + std::string(key) + "}}"; }));
      }
  }
  run.fitted = engine_at(nullptr, 0);
  for (const SpreadInput& spread : in.request.spreads) run.unknowns.push_back(spread.input);
  run.unknowns.push_back({"--measured", UnitDimension::length, {Spread::Kind::normal, in.measured.range, in.measured.uncertainty}});
  const auto start = std::chrono::steady_clock::now();
  run.summary = run_monte_carlo(
      in.samples, in.seed, in.threads, [&](std::mt19937_64& random) { return calibration_sample(in, random); }, progress);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.threads = thread_count(in.threads, static_cast<std::size_t>(in.samples));
  std::vector<double> fits;
  for (const auto& values : run.summary.values) fits.push_back(values[0]);
  std::sort(fits.begin(), fits.end());
  if (!fits.empty()) {
    const double at[5] = {0.05, 0.25, 0.5, 0.75, 0.95};
    for (int k = 0; k < 5; ++k) run.percentiles[k] = gsl_stats_quantile_from_sorted_data(fits.data(), 1, fits.size(), at[k]);
  }
  run.plausible = static_cast<int>(std::count_if(fits.begin(), fits.end(), [&](double mu) { return mu >= lo && mu <= hi; }));
  run.share = binomial_share(run.plausible, run.summary.samples);
  run.moves = rank_correlations(run.summary);
  return run;
}

namespace {

// What the friction fitted is, in words: "one coefficient at both pins" or "the scale of the coefficients".
const char* fitted_words(FrictionFit fitted) {
  return fitted == FrictionFit::pin_coefficient ? "one friction coefficient at both pins" : "the scale of the engine's friction coefficients";
}

// The plain sentence on plausibility, and what remains where plausible values do not explain the range.
std::string verdict(const CalibrationRun& run) {
  const auto [lo, hi] = run.given.plausible;
  const std::string inside = "a friction inside " + format_significant(lo, 3) + " to " + format_significant(hi, 3);
  const std::string share = percent(run.share.fraction) + " of the draws (" + percent(run.share.low) + " to " + percent(run.share.high) + ")";
  if (run.share.fraction >= 0.5) return "Plausible: " + inside + " explains the measured range in " + share + ".";
  int above = 0, below = 0;
  for (const auto& values : run.summary.values) above += values[0] > hi, below += values[0] < lo;
  for (const SampleFailures& f : run.summary.failures) {  // a draw that failed otherwise counts neither way
    if (f.reason.rfind("friction alone", 0) == 0) above += f.count;
    if (f.reason.rfind("no friction", 0) == 0) below += f.count;
  }
  const std::string remains = above >= below
      ? "most draws ask more friction than that, or more than any friction gives: the engine loses range to something the model does not "
        "hold (a sling that stretches, a beam that bends, a release that drags; docs/verifier.md, \"What is still left out\"), or an unknown "
        "lies outside the ranges given"
      : "most draws ask less friction than that, or none: the model already loses too much without it; check the air, the release and the "
        "engine's values";
  return std::string(run.share.fraction >= 0.05 ? "Partly plausible: " : "Not plausible: ") + inside + " explains the measured range in only " +
      share + "; " + remains + ".";
}

}  // namespace

std::string calibration_run_table(const CalibrationRun& run) {
  std::ostringstream out;
  const MonteCarloSummary& s = run.summary;
  out << "calibrated over unknowns: " << s.samples << " draws, seed " << run.given.seed << ", " << format_significant(run.seconds, 3) << " s on "
      << run.threads << (run.threads == 1 ? " thread" : " threads") << "\n";
  for (const UncertainInput& u : run.unknowns) out << "  " << describe_uncertain(u) << "\n";
  out << "fitted: " << fitted_words(run.fitted) << ", in " << s.values.size() << " of " << s.samples << " draws\n";
  if (!s.values.empty()) {
    const auto& p = run.percentiles;
    out << "  percentiles 5 / 25 / 50 / 75 / 95 %: " << format_significant(p[0], 3) << " / " << format_significant(p[1], 3) << " / "
        << format_significant(p[2], 3) << " / " << format_significant(p[3], 3) << " / " << format_significant(p[4], 3) << "\n";
  }
  for (const SampleFailures& f : s.failures) out << "  " << f.count << (f.count == 1 ? " draw: " : " draws: ") << f.first << "\n";
  if (!run.moves.empty()) {
    std::vector<std::string> names;
    for (const UncertainInput& unknown : run.unknowns) names.push_back(unknown.name);
    out << moves_most_text("the fit", "the fitted friction", names, run.moves, s.values.size()) << "\n";
  }
  out << verdict(run) << "\n";
  return out.str();
}

nlohmann::ordered_json calibration_run_json(const CalibrationRun& run) {
  nlohmann::ordered_json out;
  const MonteCarloSummary& s = run.summary;
  out["samples"] = s.samples;
  out["seed"] = run.given.seed;
  out["fitted"] = run.fitted == FrictionFit::pin_coefficient ? "pin_coefficient" : "friction_scale";
  out["measured"] = {{"R", run.given.measured.range}, {"uncertainty", run.given.measured.uncertainty}};
  nlohmann::ordered_json unknowns = nlohmann::ordered_json::array();
  const std::vector<SpreadInput>& spreads = run.given.request.spreads;  // the unknowns, then the measured range
  for (std::size_t k = 0; k < run.unknowns.size(); ++k) {
    const UncertainInput& u = run.unknowns[k];
    unknowns.push_back(
        {{"name", k < spreads.size() ? spread_key(spreads[k]) : std::string("measured")},
         {"distribution", u.spread.kind == Spread::Kind::uniform ? "uniform" : "normal"},
         {"a", u.spread.a},
         {"b", u.spread.b},
         {"rank_correlation", k < run.moves.size() ? nlohmann::ordered_json(run.moves[k].rho) : nlohmann::ordered_json()},
         {"rank_correlation_interval_95",
          k < run.moves.size() ? nlohmann::ordered_json{run.moves[k].low, run.moves[k].high} : nlohmann::ordered_json()},
         {"rank_correlation_resolved", k < run.moves.size() ? nlohmann::ordered_json(run.moves[k].resolved()) : nlohmann::ordered_json()}});
  }
  out["unknowns"] = unknowns;
  out["fitted_draws"] = s.values.size();
  const auto& p = run.percentiles;
  out["percentiles"] = s.values.empty() ? nlohmann::ordered_json()
                                        : nlohmann::ordered_json{{"5", p[0]}, {"25", p[1]}, {"50", p[2]}, {"75", p[3]}, {"95", p[4]}};
  out["plausible"] = {{"range", {run.given.plausible[0], run.given.plausible[1]}},
                      {"draws", run.plausible},
                      {"share", run.share.fraction},
                      {"share_low", run.share.low},
                      {"share_high", run.share.high}};
  nlohmann::ordered_json failures = nlohmann::ordered_json::array();
  for (const SampleFailures& f : s.failures) failures.push_back({{"reason", f.reason}, {"count", f.count}, {"first", f.first}});
  out["failures"] = failures;
  out["verdict"] = verdict(run);
  out["wall_time_s"] = run.seconds;
  out[version_key] = project_version();
  out["design"] = monte_carlo_request_json(run.given.request, run.given.samples, run.given.seed)["design"];
  return out;
}

std::vector<PictureFile> calibration_run_pictures(const CalibrationRun& run) {
  std::ostringstream data, gp;
  data << "# the friction fitted in each draw that has one\n";
  for (const auto& values : run.summary.values) data << format_significant(values[0], 8) << "\n";
  const auto [lo, hi] = run.given.plausible;
  const auto& p = run.percentiles;
  double least = lo, most = hi;
  for (const auto& values : run.summary.values) least = std::min(least, values[0]), most = std::max(most, values[0]);
  const double from = least - (most - least) / 20, to = most + (most - least) / 20, width = std::max((to - from) / 40, 1e-9);
  std::vector<std::string> described;
  for (const UncertainInput& u : run.unknowns) described.push_back(describe_uncertain(u));
  gp << "set terminal svg size 900,480 dynamic font 'sans,12'\nset output 'friction.svg'\n"
     << "set title \"The friction fitted to the measured range over the unknowns\\n"
     << join(described, ", ") << "\\n"
     << run.summary.values.size() << " of " << run.summary.samples << " draws fitted; shaded: the plausible " << format_significant(lo, 3) << " to "
     << format_significant(hi, 3) << ", red: the median\"\n"
     << "set xlabel '" << fitted_words(run.fitted) << "'\nset ylabel 'draws'\nset yrange [0:*]\nset tmargin 6\nset grid ytics\n"
     << "set xrange [" << from << ":" << to << "]\nset boxwidth " << width << " absolute\n"
     << "set object 1 rect from " << lo << ", graph 0 to " << hi << ", graph 1 fc rgb '#d8ecd8' fs solid 0.6 behind\n"
     << "set arrow 1 from " << p[2] << ", graph 0 to " << p[2] << ", graph 1 nohead lw 2 lc rgb '#b22222'\n"
     << "bin(x) = " << from << " + " << width << " * (floor((x - " << from << ") / " << width << ") + 0.5)\n";
  if (run.summary.values.empty())
    gp << "set label 1 'no draw has a friction that explains the range' at graph 0.5, graph 0.5 center\nplot [" << from << ":" << to
       << "] [0:1] 2 notitle\n";
  else
    gp << "plot 'friction.dat' using (bin($1)):(1) smooth frequency with boxes fs solid 0.5 lc rgb '#4682b4' notitle\n";
  return {{"friction.dat", data.str()}, {"friction.gp", gp.str()}};
}

CalibrationRunInputs calibration_run_inputs(const nlohmann::json& report, const std::string& where) {
  CalibrationRunInputs in;
  nlohmann::json passed;
  in.request = read_monte_carlo_design(report["design"], where + ".design", passed);
  in.samples = in.request.settings.samples.value_or(in.samples);
  in.seed = in.request.settings.seed.value_or(in.seed);
  const auto number = [&](const nlohmann::json& object, const char* key, const std::string& path) {
    if (!object.is_object() || !object.contains(key) || !object[key].is_number() || !std::isfinite(object[key].get<double>()))
      throw Error(ErrorKind::usage, path + "." + key + ": expected a number, as calibrate writes it");
    return object[key].get<double>();
  };
  in.measured = {number(report["measured"], "R", where + ".measured"), number(report["measured"], "uncertainty", where + ".measured")};
  if (report.contains("plausible")) {
    const nlohmann::json& range = report["plausible"].is_object() && report["plausible"].contains("range") ? report["plausible"]["range"] : nullptr;
    if (!range.is_array() || range.size() != 2 || !range[0].is_number() || !range[1].is_number() ||
        !(range[0].get<double>() >= 0 && range[0].get<double>() < range[1].get<double>()))
      throw Error(ErrorKind::usage, where + ".plausible.range: expected two friction coefficients, the low one first, as calibrate writes them");
    in.plausible = {range[0].get<double>(), range[1].get<double>()};
  }
  return in;
}

}  // namespace trebuchet
