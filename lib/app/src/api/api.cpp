#include "trebuchet/app/api/api.hpp"

#include "api_input.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "trebuchet/air.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/completion.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/quantity.hpp"
#include "trebuchet/scaling_table.hpp"
#include "trebuchet/sweep.hpp"
#include "trebuchet/uncertainty.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/output/pictures.hpp"
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/input/request.hpp"
#include "trebuchet/app/run/requests.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/records/search_records.hpp"
#include "trebuchet/app/input/settings.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/app/input/units.hpp"
#include "trebuchet/app/run/verifier.hpp"
#include "trebuchet/app/run/what_if.hpp"

namespace trebuchet::api {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

// The messages of this API name each value by its key, bare: "L1", "design.L1"; an input's
// alias by its key. A setting is named as the request gave it.
std::string key_word(std::string_view name) {
  if (const InputField* field = find_field(name)) return field->key;  // an input's key, as the request gives it
  return std::string(name);
}

bool flag_of(const json& request, const std::string& key) {
  if (!request.contains(key)) return false;
  if (!request[key].is_boolean()) throw Error(ErrorKind::usage, "{{" + key + "}}: " + brief_json(request[key]) + " must be true or false");
  return request[key].get<bool>();
}

// `values` with the material rows of `material` put over its own.
DesignValues with_material(DesignValues values, const DesignValues& material) {
  for (const InputField& field : input_fields())
    if (field.group == FieldGroup::material && material.*field.member) values.*field.member = material.*field.member;
  return values;
}

// The attested values of a request's object (or of complete's Monte Carlo report, read back),
// each given as a range or a spread taken at `at`(spread) and, with `spreads`, kept there with
// where its draws go; the settings it gives (a report's) go to `settings`. A key near an input's
// name is refused with that name.
DesignValues attested_of(const json& given, const std::string& where, const std::function<double(const Spread&)>& at, json& passed,
                         SettingsValues& settings, std::vector<SpreadInput>* spreads = nullptr) {
  if (!given.is_object()) throw Error(ErrorKind::usage, where + ": expected a JSON object");
  if (given.contains("uncertain") && given.contains("design"))
    throw Error(ErrorKind::usage, where + ": this is the report of a Monte Carlo run of shots; give it as {{design}}, which runs it again");
  const json& object = given.contains("uncertain") && given.contains("attested") ? given["attested"] : given;
  std::vector<SpreadInput> taken;
  const json plain = take_spreads(object, op_complete, where, taken, at);
  if (spreads) *spreads = taken;
  settings = read_settings(plain, req_monte_carlo, where);
  // Attested values: a near miss is refused, any other key passes through, named in the answer.
  const std::vector<std::string> known = input_names(op_complete);
  for (const auto& [key, value] : object.items())
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      if (const SettingRow* row = find_setting(key, req_monte_carlo); row && read_by_table(row->id)) continue;  // read above
      // An input of a shot that a completion does not take is refused by name, never passed over.
      if (const InputField* field = find_field(key))
        throw Error(ErrorKind::usage,
                    where + "." + key + ": complete does not take the " + field->label +
                        " (it chooses a uniform beam, a point or given counterweight, the paper's release); leave it out, and "
                        "give it to shot with the completed engine");
      pass_through(key, value, known, where, &passed);
    }
  return read_input_values(plain, where, op_complete);
}

// The values of a request's "design" with its "over" laid on them, its keys no reader knows in
// `passed` and its own settings in `own`. The notes of what "over" replaced are the programs';
// a request's "over" is its caller's own.
DesignValues design_values_of(const json& request, json& passed, SettingsValues& own) {
  std::vector<std::string> notes;
  return overlay_flags(read_design_values(request["design"], "design", &passed, &own), over_of(request, op_shot), "design", notes);
}

// A value given as a range or a spread, completed at its middle (a range's midpoint, a spread's mean).
double middle(const Spread& spread) { return spread.kind == Spread::Kind::uniform ? (spread.a + spread.b) / 2 : spread.a; }

ordered_json completion_answer(const CompletionRequest& request) {
  CompletionReport report = complete_with_longest(request, key_word);
  report.completion.calculator_note = with_words(report.completion.calculator_note, key_word);
  if (report.completion.calculator)
    for (std::string& warning : report.completion.calculator->warnings) warning = with_words(warning, key_word);
  return completion_json(report.completion, request.settings, report.longest ? &*report.longest : nullptr, report.longest_note);
}

constexpr ErrorKind all_kinds[] = {ErrorKind::usage,        ErrorKind::given_count, ErrorKind::bad_number, ErrorKind::unknown_unit,
                                   ErrorKind::out_of_range, ErrorKind::data_file,   ErrorKind::batch_rows, ErrorKind::numerical};

const char* kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::usage: return "usage";
    case ErrorKind::given_count: return "given_count";
    case ErrorKind::bad_number: return "bad_number";
    case ErrorKind::unknown_unit: return "unknown_unit";
    case ErrorKind::out_of_range: return "out_of_range";
    case ErrorKind::data_file: return "data_file";
    case ErrorKind::batch_rows: return "batch_rows";
    case ErrorKind::numerical: return "numerical";
  }
  return "numerical";
}

ErrorKind kind_of(const std::string& name) {
  for (ErrorKind kind : all_kinds)
    if (name == kind_name(kind)) return kind;
  throw Error(ErrorKind::usage, "{{outcomes}}: '" + name + "' is no kind of failure");
}

}  // namespace

ordered_json design(const json& request) {
  std::vector<std::string> known = input_names(op_given | op_calculator);
  for (const std::string& key : keys_of(req_design)) known.push_back(key);
  require_keys(request, known, "design");
  // Another machine's optimum from its own table (docs/machines.md), as trebuchet-calc --machine.
  const MachineKind machine = request.contains(machine_key) ? parse_machine(text_of(request[machine_key], machine_key), "{{machine}}")
                                                            : MachineKind::hinged;
  const ScalingTable& table = builtin_scaling_table(machine);
  if (machine != MachineKind::hinged && request.contains("F"))
    throw Error(ErrorKind::usage,
                "{{F}}: the " + machine_name(machine) + " machine's table holds the counterweight at the short arm's end; leave out {{F}}");
  DesignRequest r;
  std::vector<Given> givens;
  for (Quantity q : all_quantities) {
    const std::string key(quantity_name(q));
    if (const auto value = positive_value(request, key, unit_dimension(quantity_dimension(q)))) givens.push_back({q, *value});
  }
  if (givens.size() != 2) {
    std::vector<std::string> names;
    for (Quantity q : all_quantities) names.emplace_back(quantity_name(q));
    throw Error(ErrorKind::given_count,
                "found " + std::to_string(givens.size()) + " given(s); give exactly two of " + join(names, ", ") +
                    ", e.g. {\"R\": \"150m\", \"m\": \"50kg\"}");
  }
  r.first = givens[0], r.second = givens[1];
  const auto theta = read_value(request, request.contains("theta") ? "theta" : "theta_i_deg", UnitDimension::angle, "");
  if (theta) r.theta_i_deg = parse_theta(format_number(*theta), request.contains("theta") ? "{{theta}}" : "{{theta_i_deg}}");
  if (const auto F = read_value(request, "F", UnitDimension::dimensionless, "")) r.F = *F;
  if (request.contains("branch")) r.branch = parse_branch_choice(text_of(request["branch"], "branch"));
  r.extrapolate = flag_of(request, "extrapolate");
  if (const auto scale = positive_value(request, "scale", UnitDimension::dimensionless)) r.scale = *scale;
  r.material = material_of(material_of_request(request, op_calculator), table.reference);
  check_material(r.material);
  OptimalEngine optimal = design_optimal_engine(table, r);
  for (std::string& warning : optimal.warnings) warning = with_words(warning, key_word);
  return design_json(optimal);
}

ordered_json optimize(const json& request) {
  std::vector<std::string> known = input_names(op_optimize);
  for (const std::string& key : keys_of(req_optimize)) known.push_back(key);
  require_keys(request, known, "optimize");
  // The capacity, the stone and the material must be positive, as the programs' options are.
  DesignValues v;
  for (const InputField& field : input_fields()) {
    if (!(field.operations & op_optimize)) continue;
    const bool positive = field.group == FieldGroup::capacity || field.group == FieldGroup::material || field.member == &DesignValues::m;
    for (const char* name : names_of(field)) {
      const auto value = positive ? positive_value(request, name, field.dimension) : read_value(request, name, field.dimension, "");
      if (value && v.*field.member)
        throw Error(ErrorKind::usage, std::string("{{") + field.key + "}} and {{" + name + "}} are one value given twice; keep one");
      if (value) v.*field.member = value;
    }
  }
  ordered_json all = ordered_json::array();
  const OptimizeRequest r = optimize_request(v, settings_of(request, req_optimize));
  for (const Optimum& optimum : trebuchet::optimize(r)) all.push_back(optimum_json(optimum, r.settings, 0));
  return all;
}

ordered_json shot(const json& request) {
  require_keys(request, keys_of(req_shot, op_shot), "shot");
  if (!request.contains("design"))
    throw Error(ErrorKind::usage, "{{design}} is missing; give the engine, e.g. {\"design\": {\"L1\": \"6.13m\", ...}}");
  const SettingsValues settings = settings_values_of(request, req_shot);
  DesignCheck check;
  check.settings = shot_settings_over_designs(settings);
  check.given = settings;  // over the design's own (a record's assumptions), checked there
  check.material = material_of_request(request, op_shot);
  check.tolerance = settings.tol.value_or(check.tolerance);
  check.fit = flag_of(request, "fit");
  const DesignValues over = over_of(request, op_shot);
  const DesignReport report = check_design(read_engine(request["design"], "design", &over), check);
  ordered_json answer = report.json;
  // The series is of the engine the answer reports (fitted first with "fit"), from its shot.
  if (flag_of(request, "series"))
    answer["series"] = shot_series_json(shot_series(report.engine, report.settings, report.verification), report.engine);
  return answer;
}

ordered_json sweep(const json& request) {
  require_keys(request, keys_of(req_sweep, op_shot), "sweep");
  if (!request.contains("design"))
    throw Error(ErrorKind::usage, "{{design}} is missing; give the engine, e.g. {\"design\": {\"L1\": \"6.13m\", ...}, \"vary\": \"L4=2m..5m\"}");
  if (!request.contains("vary")) throw Error(ErrorKind::usage, "{{vary}} is missing; give the value to vary and its range, e.g. \"L4=2m..5m\"");
  const double points = read_value(request, "points", UnitDimension::dimensionless, "").value_or(21);
  if (!(points >= 2 && points <= max_what_if_points) || points != std::floor(points))
    throw Error(ErrorKind::bad_number,
                "{{points}} = " + format_significant(points, 6) + " must be a whole number from 2 to " + std::to_string(max_what_if_points));
  const WhatIf what_if = parse_what_if(text_of(request["vary"], "vary"), static_cast<int>(points), "vary");
  json passed = json::object();
  SettingsValues own;
  const DesignValues values = design_values_of(request, passed, own);
  DesignCheck check;
  check.settings = shot_settings(overlay(own, settings_values_of(request, req_sweep)));  // the request's over the design's own
  check.material = material_of_request(request, op_shot);
  if (what_if.field->group != FieldGroup::release) check.settings.release_at = release_of(values, "design");
  ordered_json answer = what_if_json(what_if, run_what_if(values, "design", what_if, check, 1), key_word);
  if (!passed.empty()) answer["passed"] = passed;  // the design's keys no reader knows, as given
  return answer;
}

ordered_json compare(const json& request) {
  require_keys(request, keys_of(req_compare, op_shot), "compare");
  if (!request.contains("design"))
    throw Error(ErrorKind::usage, "{{design}} is missing; give the engine, e.g. {\"design\": {\"L1\": \"6.13m\", ...}}");
  json passed = json::object();
  SettingsValues own;
  const DesignValues values = design_values_of(request, passed, own);
  DesignCheck check;
  check.material = material_of_request(request, op_shot);
  // A contest's limits, each column measured against them (contest.hpp).
  for (std::size_t k = 0; k < contest_limit_count; ++k) {
    const std::string key = contest_limit_key(static_cast<ContestLimit>(k));
    check.limits.limits[k] = positive_value(request, key, find_setting(key, req_compare)->dimension);
  }
  check.limits.min_clearance = positive_value(request, "min_clearance", UnitDimension::length, true).value_or(0);
  // The request's settings over the design's own.
  ordered_json answer = comparison_json(compare_design(values, "design", overlay(own, settings_values_of(request, req_compare)), check), key_word);
  if (!passed.empty())  // the design's keys no reader knows, as given, in each machine's record
    for (ordered_json& record : answer) record["passed"] = passed;
  return answer;
}

ordered_json complete(const json& request) {
  require_keys(request, keys_of(req_complete, op_complete), "complete");
  if (!request.contains("attested"))
    throw Error(ErrorKind::usage,
                "{{attested}} is missing; give what the source attests, e.g. {\"attested\": {\"Lb\": \"9.5m\", \"M\": \"3t\", \"m\": \"50kg\"}}");
  json passed = json::object();
  SettingsValues own;
  std::vector<std::string> notes;  // the programs print them; a request's "over" is its caller's own
  const DesignValues attested = with_material(overlay_flags(attested_of(request["attested"], "attested", middle, passed, own),
                                                            over_of(request, op_complete, nullptr, middle), "attested", notes),
                                              material_of_request(request, op_complete));
  ordered_json answer = completion_answer(completion_request(attested, shot_settings(overlay(own, settings_values_of(request, req_complete)))));
  if (!passed.empty()) answer["passed"] = passed;  // the attested keys no reader knows, as given
  return answer;
}

namespace {

// The run a monte_carlo request asks for: a design's shots or an attested engine's completions,
// the request's settings over the design's own (each may be a range or a spread too, the wind
// say; a setting the request gives is no longer drawn from the design's).
MonteCarloRequest monte_carlo_run_of(const json& request, json& passed) {
  const bool completes = request.contains("attested");
  if (completes == request.contains("design"))
    throw Error(ErrorKind::usage, "give {{design}} (a shot of each sample) or {{attested}} (a completion of each sample), one of them");
  const std::string where = completes ? "attested" : "design";
  const unsigned operation = completes ? op_complete : op_shot;
  MonteCarloRequest run;
  if (completes) {
    run.values = attested_of(
        request[where], where, [](const Spread& s) { return s.a; }, passed, run.settings, &run.spreads);
    run.where = where;
  } else {
    run = read_monte_carlo_design(request[where], where, passed);  // a design, or a run's report read back
  }
  run.values = with_material(run.values, material_of_request(request, operation));
  run.completes = completes;
  // The caller's own values ("over", Python's keywords) replace the run's without a note, as in
  // shot and complete; the request's settings over a design's own are noted, as the programs note them.
  std::vector<SpreadInput> over_spreads, setting_spreads;
  const DesignValues over = over_of(request, operation, &over_spreads);
  const std::size_t notes = run.notes.size();
  lay_over_run(run, over, SettingsValues{}, over_spreads, where);
  run.notes.resize(notes);
  const SettingsValues given = settings_values_of(take_spreads(request, op_shot, "", setting_spreads), req_monte_carlo);
  lay_over_run(run, DesignValues{}, given, setting_spreads, where);
  if (run.spreads.empty())  // as the programs refuse a run of identical samples
    throw Error(ErrorKind::usage,
                "monte_carlo samples the values of {{" + where +
                    "}} given as a range (\"2.5t..3.5t\") or a spread (\"3.5m±0.2m\"); give one, or call shot for one value each");
  return run;
}

// One worker's part of a run: the outcomes of the samples from `first`, `count` of them, each
// [R, T, eps, v, then the drawn inputs] or its failure.
template <class Sample>
ordered_json monte_carlo_part(const json& request, int samples, std::uint64_t seed, const Sample& sample) {
  const auto first = read_value(request, "first", UnitDimension::dimensionless, "").value_or(0);
  const auto count = read_value(request, "count", UnitDimension::dimensionless, "").value_or(samples - first);
  if (!(first >= 0 && count >= 0 && first + count <= samples) || first != std::floor(first) || count != std::floor(count))
    throw Error(ErrorKind::bad_number, "{{first}} and {{count}} must pick samples from 0 to {{samples}} - 1");
  ordered_json part = ordered_json::array();
  for (auto i = static_cast<std::size_t>(first); i < static_cast<std::size_t>(first + count); ++i) {
    const SampleOutcome o = run_sample(seed, i, sample);
    if (o.failure.empty()) {  // R, T, eps, v, then the drawn inputs
      ordered_json values(o.values);
      for (double x : o.drawn) values.push_back(x);
      part.push_back(values);
    } else {
      part.push_back({{"failure", o.failure}, {"kind", kind_name(o.failure_kind)}, {"drawn", o.drawn}});
    }
  }
  return {{"samples", samples}, {"outcomes", part}};
}

// The parts put together: one outcome for each sample, in order, as monte_carlo_part gives them.
std::vector<SampleOutcome> read_outcomes(const json& given, int samples, std::size_t drawn_count) {
  std::vector<SampleOutcome> outcomes;
  if (!given.is_array() || given.size() != static_cast<std::size_t>(samples))
    throw Error(ErrorKind::usage, "{{outcomes}} must hold one outcome for each of the " + std::to_string(samples) + " samples, in order");
  for (const json& o : given) {
    SampleOutcome outcome;
    const auto numbers = [&](const json& a) {
      return a.is_array() && a.size() == 4 + drawn_count && std::all_of(a.begin(), a.end(), [](const json& x) { return x.is_number(); });
    };
    const auto drawn_ok = [&](const json& a) {
      return a.is_array() && a.size() == drawn_count && std::all_of(a.begin(), a.end(), [](const json& x) { return x.is_number(); });
    };
    if (numbers(o)) {
      for (std::size_t k = 0; k < 4; ++k) outcome.values[k] = o[k].get<double>();
      for (std::size_t k = 4; k < o.size(); ++k) outcome.drawn.push_back(o[k].get<double>());
    } else if (o.is_object() && o.contains("failure") && o["failure"].is_string() && (!o.contains("kind") || o["kind"].is_string()) &&
               o.contains("drawn") && drawn_ok(o["drawn"])) {
      outcome.failure = o["failure"].get<std::string>();
      outcome.failure_kind = kind_of(o.value("kind", "numerical"));
      outcome.drawn = o["drawn"].get<std::vector<double>>();
    } else {
      throw Error(ErrorKind::usage,
                  "{{outcomes}}: " + brief_json(o) + " is no outcome; give [R, T, eps, v, then the " + std::to_string(drawn_count) +
                      " drawn inputs] or {\"failure\": ..., \"drawn\": [...]}, as a part of the run gives them");
    }
    outcomes.push_back(outcome);
  }
  return outcomes;
}

}  // namespace

ordered_json monte_carlo(const json& request) {
  require_keys(request, keys_of(req_monte_carlo, op_shot | op_complete), "monte_carlo");
  json passed = json::object();
  const MonteCarloRequest run = monte_carlo_run_of(request, passed);
  const bool completes = run.completes;
  // As the program does: the design at each spread's first number must be an engine.
  const std::int64_t shots = shots_per_sample(run);
  const int samples = run.settings.samples.value_or(completes ? default_completion_samples : default_shot_samples);
  check_monte_carlo_work(samples, shots, completes ? "completions" : "shots");
  const std::uint64_t seed = run.settings.seed.value_or(1);
  const auto sample = [&](std::mt19937_64& random) { return sample_outcome(run, random, key_word); };
  if (request.contains("first") || request.contains("count")) return monte_carlo_part(request, samples, seed, sample);
  std::vector<SampleOutcome> outcomes;
  if (request.contains("outcomes"))  // the parts put together
    outcomes = read_outcomes(request["outcomes"], samples, run.spreads.size());
  else
    for (std::size_t i = 0; i < static_cast<std::size_t>(samples); ++i) outcomes.push_back(run_sample(seed, i, sample));
  const MonteCarloSummary summary = summarize_samples(outcomes);
  refuse_when_no_sample_worked(summary);
  const MonteCarloReport report = monte_carlo_report(run, summary, samples, seed, key_word);
  ordered_json answer = monte_carlo_json(report);
  answer.erase("wall_time_s");  // a time is the caller's to measure; the report is the same on any machine
  // Every sample's drawn inputs and outcomes as the programs' --draws writes them, to 17 digits: the run's own numbers.
  if (flag_of(request, "draws_csv")) answer["draws_csv"] = monte_carlo_draws_csv(report);
  // What reading the design left out and what the request's settings replaced, as the programs'
  // notes say, in the request's keys.
  if (!run.notes.empty()) {
    std::vector<std::string> notes;
    for (const std::string& note : run.notes) notes.push_back(with_words(note, key_word));
    answer["notes"] = notes;
  }
  if (!passed.empty()) answer["passed"] = passed;
  return answer;
}

ordered_json value(const json& request) {
  require_keys(request, keys_of(req_value), "value");
  const std::string key = request.contains("key") ? text_of(request["key"], "key") : "";
  const InputField* field = find_field(key);
  if (!field) throw Error(ErrorKind::usage, "{{key}}: '" + key + "' is no input's key; use one of " + join(input_names(~0u), ", "));
  if (!request.contains("text"))
    throw Error(ErrorKind::usage, "{{text}} is missing; give the value as typed, e.g. \"" + std::string(field->example) + "\"");
  const std::string text = request["text"].is_number() ? format_number(request["text"].get<double>()) : text_of(request["text"], "text");
  return {{"key", field->key}, {"value", parse_value(text, field->dimension, field->key)}};
}

ordered_json fields(const json& request) {
  require_keys(request, {}, "fields");
  const std::pair<unsigned, const char*> operation_names[] = {
      {op_given, "given"}, {op_calculator, "design"}, {op_shot, "shot"}, {op_complete, "complete"}, {op_optimize, "optimize"}};
  const char* const group_names[] = {"engine", "alternative", "material", "capacity", "release", "part"};
  ordered_json rows = ordered_json::array();
  for (const InputField& field : input_fields()) {
    ordered_json operations = ordered_json::array();
    for (const auto& [bit, name] : operation_names)
      if (field.operations & bit) operations.push_back(name);
    ordered_json units = ordered_json::array();
    for (const UnitFactor& unit : unit_factors())
      if (unit.dimension == field.dimension) units.push_back(unit.suffix);
    rows.push_back({{"key", field.key},
                    {"flag", field.flag},
                    {"aliases", field.aliases},
                    {"dimension", dimension_name(field.dimension)},
                    {"unit", field.unit},
                    {"units", units},
                    {"group", group_names[static_cast<int>(field.group)]},
                    {"operations", operations},
                    {"label", field.label},
                    {"help", field.help},
                    {"example", field.example},
                    {"default", field.fallback},
                    {"range", field.range}});
  }
  // The machine, a name rather than a number: a key of the engine as the others are.
  rows.push_back({{"key", machine_key},
                  {"flag", "--machine"},
                  {"aliases", ordered_json::array()},
                  {"dimension", "name"},
                  {"unit", ""},
                  {"units", ordered_json::array()},
                  {"group", "engine"},
                  {"operations", {"design", "shot", "optimize"}},
                  {"label", "machine"},
                  {"help", setting_row(Setting::machine).help},
                  {"example", "fixed"},
                  {"default", setting_row(Setting::machine).fallback},
                  {"range", setting_row(Setting::machine).range}});
  // The settings (settings.def): each with the requests that take it, by their names here.
  const std::pair<unsigned, const char*> request_names[] = {{req_design, "design"},     {req_shot, "shot"},         {req_sweep, "sweep"},
                                                            {req_optimize, "optimize"}, {req_complete, "complete"}, {req_monte_carlo, "monte_carlo"},
                                                            {req_value, "value"},       {req_compare, "compare"},   {req_contest, "contest"}};
  ordered_json settings = ordered_json::array();
  for (const SettingRow& row : setting_rows()) {
    if (!*row.key) continue;  // the programs' alone
    ordered_json requests = ordered_json::array();
    for (const auto& [bit, name] : request_names)
      if (row.doors & bit) requests.push_back(name);
    settings.push_back({{"key", row.key},
                        {"flag", row.flag},
                        {"aliases", row.aliases},
                        {"dimension", dimension_name(row.dimension)},
                        {"requests", requests},
                        {"help", row.help},
                        {"default", row.fallback},
                        {"range", row.range}});
  }
  return {{"fields", rows}, {"settings", settings}};
}

std::string answer_text(Request request, const std::string& text, const std::string& where_documented) {
  try {
    return request(parse_json(text, "the request", "a JSON object of the request's keys (" + where_documented + ")")).dump();
  } catch (const Error& e) {
    return error_json(e).dump();
  } catch (const std::exception& e) {
    return error_json(Error(ErrorKind::numerical, std::string("internal error: ") + e.what())).dump();
  }
}

ordered_json error_json(const Error& error) {
  std::vector<std::string> names;
  const auto name = [&](const std::string& key) {
    if (std::find(names.begin(), names.end(), key) == names.end()) names.push_back(key);
  };
  for (const std::string& given : error.names()) name(key_word(given));
  // A value of a request's object is named "design.M", "attested[2].Lb": its key is named too.
  static const std::regex in_object(R"((?:design|attested)(?:\[\d+\])?\.([A-Za-z_][A-Za-z0-9_]*))");
  const std::string text = error.message(key_word);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), in_object); it != std::sregex_iterator(); ++it) name(key_word((*it)[1].str()));
  // A key no reader knows is named as the user gave it (issue 62): unknown key "tol", or
  // 'rope_mass' is no key of this request; or a value a record holds but does not read: "L4" beside a record's "engine".
  static const std::regex unknown_key(R"re(unknown key "([^"]+)"|'([^']+)' is no key|"([^"]+)" beside a record's)re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), unknown_key); it != std::sregex_iterator(); ++it)
    for (int group = 1; group <= 3; ++group)
      if ((*it)[group].matched) name((*it)[group].str());
  return {{"error", text}, {"kind", kind_name(error.kind())}, {"names", names}};
}

}  // namespace trebuchet::api
