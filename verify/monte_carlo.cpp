// A shot or a completion whose values are given as ranges or spreads: each sample sets them to a
// draw (in SI units, on the typed options) and runs; the percentiles of R, T, eps and v, the
// failures by reason, and with --plot a histogram.
#include <algorithm>
#include <chrono>
#include <tuple>
#include <iostream>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/output/output_files.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/parallel.hpp"
#include "trebuchet/app/output/pictures.hpp"
#include "trebuchet/app/output/report.hpp"

namespace trebuchet::verify {

void refuse_monte_carlo_settings(const Options& o) {
  if (o.settings.samples || o.settings.seed)
    throw Error(ErrorKind::usage,
                "--samples and --seed set a Monte Carlo run; give a value as a range (2.5t..3.5t) or a spread "
                "(3.5m±0.2m), or drop them");
  if (o.settings.claim || !o.draws.empty())
    throw Error(ErrorKind::usage,
                "--claim and --draws report a Monte Carlo run; give a value as a range (2.5t..3.5t) or a spread "
                "(3.5m±0.2m), or drop them");
}

namespace {

// The run of a design file's (its values, spreads and settings, or a run's report read back)
// with the flags' values, spreads and settings over its own, each change a note.
MonteCarloRequest file_run(const Options& o, const nlohmann::json& design, const std::string& where) {
  nlohmann::json passed;
  MonteCarloRequest run = read_monte_carlo_design(design, where, passed);
  lay_over_run(run, o.design, o.settings, o.spreads, where);
  print_notes(run.notes);
  if (run.spreads.empty())
    throw Error(ErrorKind::usage,
                "the flags give one value to each of " + where +
                    "'s ranges and spreads, so nothing is left to draw; give a value as a range or a spread, or drop "
                    "the file's samples, seed and claim and shoot it once");
  return run;
}

}  // namespace

int run_monte_carlo(const Options& o, bool complete, const nlohmann::json* design, const std::string& where) {
  if (!o.series.empty()) throw Error(ErrorKind::usage, "--series writes the motion of one shot; a Monte Carlo run has many");
  if (!o.draws.empty()) refuse_output_over_input(o.draws, "draws", {o.input});
  if (o.design.R || o.design.T || o.settings.tol) {
    const bool tolerance_alone = !o.design.R && !o.design.T;
    throw Error(ErrorKind::usage,
                std::string(tolerance_alone ? "--tol checks" : "--R and --T check") +
                    " one shot against a predicted capacity; a Monte Carlo run reports the spread of R and T instead: drop " +
                    (tolerance_alone ? "it" : "them") + ", or give each value as one number");
  }
  // The run's assumptions are those of each uncertain value at its first number (a range's low
  // end, a spread's mean). A design that is bad input there is refused before the run, with the
  // exit code of bad input: a range must hold only values that make an engine.
  const MonteCarloRequest request = design ? file_run(o, *design, where) : monte_carlo_request(o, complete);
  const ShotSettings settings = shot_settings(with_draws(request, [](const Spread& s) { return s.a; }).settings);
  const std::int64_t shots = shots_per_sample(request);
  const int samples = request.settings.samples.value_or(complete ? default_completion_samples : default_shot_samples);
  const std::uint64_t seed = request.settings.seed.value_or(1);
  check_monte_carlo_work(samples, shots, complete ? "completions" : "shots");
  const auto start = std::chrono::steady_clock::now();
  const MonteCarloSummary summary = trebuchet::run_monte_carlo(
      samples, seed, o.threads, [&](std::mt19937_64& random) { return sample_outcome(request, random, option_word); },
      progress_bar(complete ? "completions" : "shots"));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  MonteCarloReport report = monte_carlo_report(request, summary, samples, seed, option_word);
  report.seconds = seconds;
  report.threads = thread_count(o.threads, static_cast<std::size_t>(summary.samples));
  if (o.format == Format::json) {
    std::cout << pretty_json(monte_carlo_json(report));
  } else if (o.format == Format::csv) {
    // CSV holds the percentiles; what the table says around them goes to stderr.
    std::cout << monte_carlo_csv(report, o.digits);
    std::cerr << monte_carlo_table(report);
  } else {
    std::cout << monte_carlo_table(report);
  }
  if (!o.draws.empty()) write_output_file(o.draws, monte_carlo_draws_csv(report), "draws");
  refuse_when_no_sample_worked(summary);  // after the report of the failures; no histogram
  if (!o.plot.empty()) {
    std::vector<std::string> described;
    for (const UncertainInput& u : report.inputs) described.push_back(describe_uncertain(u));
    // The title says what was sampled and how each shot flew and was released; a backslash and n break its line in gnuplot.
    const std::string scene = (settings.air ? describe_air(*settings.air, 0) : std::string("in vacuum")) + ", " +
        describe_monte_carlo_release(request);
    write_picture_folder(o.plot, histogram_pictures(summary, join(described, ", ") + "\\n" + scene), {"histogram.gp"});
  }
  return exit_success;
}

}  // namespace trebuchet::verify
