// calibrate: the friction of an engine fitted to the range it threw (calibration.hpp), and what
// it then does with another projectile or counterweight.
#include <algorithm>
#include <iostream>
#include <vector>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/app/output/output_files.hpp"
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/app/run/calibration_run.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/output/pictures.hpp"
#include "trebuchet/app/run/verifier.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet::verify {

namespace {

// The friction fitted over the unknowns given as ranges or spreads (calibration_run.hpp).
int run_calibrate_over_unknowns(const Options& o, const DesignValues& values) {
  for (const auto& [given, flag] :
       {std::pair{!o.predict_m.empty(), "--predict-m"}, {!o.predict_M.empty(), "--predict-M"}, {!o.series.empty(), "--series"}})
    if (given)
      throw Error(ErrorKind::usage,
                  std::string(flag) + " follows one calibrated engine; with unknowns given as ranges or spreads there is one per draw: drop " + flag +
                      ", or give each unknown one value");
  const MonteCarloRequest request{values, o.settings, o.spreads, false, "", {}};
  return run_calibration(o, {request, *o.measured, o.plausible_friction, o.settings.samples.value_or(200), o.settings.seed.value_or(1), o.threads});
}

}  // namespace

int run_calibration(const Options& o, CalibrationRunInputs inputs) {
  inputs.threads = o.threads;
  check_monte_carlo_work(inputs.samples, 12, "fits");  // about a dozen shots a fit
  const CalibrationRun run = calibrate_over_unknowns(inputs, progress_bar("fits"));
  if (o.format == Format::json)
    std::cout << pretty_json(calibration_run_json(run));
  else
    std::cout << calibration_run_table(run);
  refuse_when_no_sample_worked(run.summary);  // after the report of the failures; no histogram
  if (!o.plot.empty()) write_picture_folder(o.plot, calibration_run_pictures(run), {"friction.gp"});
  return exit_success;
}

int run_calibrate(const Options& flags) {
  Options o = flags;  // with a file's settings under the flags'
  if (!o.measured)
    throw Error(ErrorKind::usage, "--measured is missing; give the range the engine threw, with its uncertainty, e.g. --measured 34.4m±1.5m");
  DesignValues values = o.design;
  std::string where;
  if (!o.input.empty()) {
    const DesignInputs in = read_design_inputs(read_text(o.input, "a design object like {\"L1\": \"6.13m\", ...}"), o.input);
    // One engine: an object, or an array or CSV of one row.
    if (in.rows.size() != 1)
      throw Error(ErrorKind::usage, "calibrate fits one engine; " + source_name(o.input) + " holds " + std::to_string(in.rows.size()));
    if (const std::string refusal = row_refusal(in.rows.front(), flags.settings); !refusal.empty())
      throw Error(ErrorKind::usage, in.where.front() + ": " + refusal);
    where = in.where.front();
    // What the flags give (the parts as built, the release, an unknown's range) over the file's, each change noted.
    std::vector<std::string> notes;
    SettingsValues own;
    values = overlay_flags(read_design_values(in.rows.front().design, where, nullptr, &own), o.design, where, notes);
    for (std::string& note : settings_notes(own, flags.settings, where)) notes.push_back(std::move(note));
    print_notes(notes);
    o.settings = overlay(own, flags.settings);
  }
  if (!o.spreads.empty()) return run_calibrate_over_unknowns(o, values);
  // --samples and --seed draw the unknowns; with none, they would go unused without a word.
  for (const auto& [given, flag] : {std::pair{o.settings.samples.has_value(), "--samples"}, {o.settings.seed.has_value(), "--seed"}})
    if (given)
      throw Error(ErrorKind::usage,
                  std::string(flag) + " draws the unknowns of a calibration, and none is given as a range or a spread: drop " + flag +
                      ", or give an unknown as one (--axle-radius 2cm..3cm)");
  const EngineRecord record = engine_record(values, where);
  Engine engine = record.engine;
  engine.material = material_of(o.design, engine.material);  // the flags' material over a file's
  if (record.mb_from_D) engine.mb = wood_beam_mass(engine);  // in the wood of the run
  ShotSettings settings = settings_of(o);
  settings.release_at = release_of(o.design, "");  // the release the measured engine made, when known: the flags' over the file's
  if (!settings.release_at) settings.release_at = record.release_at;
  for (double m : o.predict_m) check_ordinary(m, 1e-9, 1e12, "predict_m", "kg", "projectile mass to predict with");
  for (double M : o.predict_M) check_ordinary(M, 1e-9, 1e12, "predict_M", "kg", "counterweight mass to predict with");
  if (!o.series.empty()) refuse_output_over_input(o.series, "series", {o.input});
  const Calibration calibration = calibrate(engine, *o.measured, settings);
  if (!o.series.empty() || !o.plot.empty()) {  // the calibrated engine's shot, drawn and written as shot draws and writes one
    DesignCheck check;
    check.settings = settings;
    check.series_path = o.series;
    check.series_dt_s = o.series_dt_s;
    check.plot_dir = o.plot;
    check.inputs = {o.input};
    check.units = o.units;
    EngineRecord calibrated;
    calibrated.engine = calibration.engine;
    check_design(calibrated, check);
  }
  std::vector<Prediction> predictions;
  for (double m : o.predict_m) {
    Engine changed = calibration.engine;
    changed.m = m;
    predictions.push_back(predict(calibration, changed, "m = " + quantity_text(m, UnitDimension::mass, o.units, 4), settings));
  }
  for (double M : o.predict_M) {
    Engine changed = calibration.engine;
    changed.parts.counterweight_inertia *= M / changed.M;  // the same counterweight, heavier: its radius of gyration kept
    changed.M = M;
    predictions.push_back(predict(calibration, changed, "M = " + quantity_text(M, UnitDimension::mass, o.units, 4), settings));
  }
  if (o.format == Format::json)
    std::cout << pretty_json(calibration_json(calibration, *o.measured, predictions, settings));
  else
    std::cout << calibration_table(calibration, *o.measured, predictions, settings, o.units);
  return exit_success;
}

}  // namespace trebuchet::verify
