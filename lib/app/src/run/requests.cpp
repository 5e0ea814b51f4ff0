#include "trebuchet/app/run/requests.hpp"

#include <algorithm>
#include <cmath>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/uncertainty.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {

ContestRequest contest_request(const DesignValues& v, const ShotSettings& settings, std::optional<double> beam_per_m, bool efficiency) {
  ContestRequest request;
  request.machine = v.machine.value_or(MachineKind::hinged);
  if (!v.m) throw Error(ErrorKind::usage, "contest needs the projectile's mass; give {{m}}, e.g. {{m}} 0.5kg");
  request.projectile_mass = *v.m;
  request.material = material_of(v, Material{});
  if (beam_per_m && v.D) throw Error(ErrorKind::usage, "{{mb_per_m}} and {{D}} both give the beam's mass per metre; give one");
  if (!beam_per_m && !v.D)
    throw Error(
        ErrorKind::usage,
        "contest needs the beam: its diameter {{D}} (of the wood, {{wood_density}}) or its mass per metre {{mb_per_m}}, e.g. {{mb_per_m}} 1.5");
  request.beam_mass_per_length = beam_per_m ? *beam_per_m : request.material.wood_density * M_PI / 4 * *v.D * *v.D;  // eq:BeamMass per metre
  request.theta_i_deg = v.theta_i_deg.value_or(standard_theta_i_deg);
  if (!(request.theta_i_deg > 0 && request.theta_i_deg < 90))
    throw Error(ErrorKind::bad_number,
                "{{theta_i_deg}} = " + format_significant(request.theta_i_deg, 6) + ": the initial beam angle must lie between 0 and 90 degrees");
  request.settings = settings;
  request.efficiency = efficiency;
  request.settings.criterion.release = efficiency ? Release::efficiency : Release::range;  // released where the objective peaks
  request.box_width = v.box_width, request.box_height = v.box_height;
  request.rope_mass = v.rope_mass.value_or(0), request.pouch_mass = v.pouch_mass.value_or(0), request.pin_friction = v.pin_friction.value_or(0);
  request.projectile_diameter = v.projectile_diameter;
  return request;
}

CompletionRequest completion_request(const DesignValues& v, const ShotSettings& settings) {
  CompletionRequest request;
  Attested& a = request.attested;
  a.Lb = v.Lb, a.L1 = v.L1, a.L2 = v.L2, a.H = v.H, a.L4 = v.L4, a.M = v.M, a.m = v.m, a.mb = v.mb, a.D = v.D, a.l = v.l;
  a.theta_i_deg = v.theta_i_deg, a.F = v.F, a.drop = v.drop;
  request.material = material_of(v, Material{});
  request.settings = settings;
  request.parts = independent_parts(v);
  request.projectile_diameter = v.projectile_diameter;
  return request;
}

OptimizeRequest optimize_request(const DesignValues& v, const ShotSettings& settings) {
  if (!v.R || v.T.has_value() == v.m.has_value())
    throw Error(
        ErrorKind::usage,
        "optimize needs a capacity: {{R}} with {{T}}, or {{R}} with the stone's {{m}}; e.g. {{R}} 425m {{T}} 224kJ, or {{R}} 450m {{m}} 100kg");
  OptimizeRequest request;
  request.capacity = {*v.R, v.T.value_or(0), 0};
  request.projectile_mass = v.m;
  request.theta_i_deg = v.theta_i_deg.value_or(standard_theta_i_deg);
  request.F = v.F.value_or(standard_F);
  request.machine = v.machine.value_or(MachineKind::hinged);
  if (request.machine != MachineKind::hinged && v.F)
    throw Error(ErrorKind::usage,
                "{{F}}: optimize builds the fixed counterweight and the floating arm with the counterweight at the short arm's end (L3 = 0); "
                "leave out {{F}}");
  request.material = material_of(v, Material{});
  request.settings = settings;
  if (v.l) {
    check_fixed_beam_ratio(*v.l, "{{l}}");
    request.fixed_l = v.l;
  }
  return request;
}

namespace {

// A design's capacity (a calculator's R and T, or a check's, with its tolerance) is taken out of
// a Monte Carlo run, which reports the spread of R and T and checks none, with a note; a check's
// setting without a capacity (a tolerance) is refused by name.
void leave_out_capacity(nlohmann::json& design, const std::string& where, std::vector<std::string>& notes) {
  std::vector<std::string> keys;
  for (const char* key : {"R", "T"})
    if (design.contains(key)) keys.emplace_back(key);
  for (const auto& [key, value] : design.items())
    if (find_setting(key, req_shot) && !find_setting(key, req_monte_carlo)) {
      if (keys.empty()) throw Error(ErrorKind::usage, engine_key_name(where, key) + ": a Monte Carlo run checks no capacity; leave out " + key);
      keys.push_back(key);
    }
  if (keys.empty()) return;
  std::vector<std::string> names;
  for (const std::string& key : keys) names.push_back(engine_key_name(where, key)), design.erase(key);
  notes.push_back(join(names, ", ") + ": the capacity the design gives is not checked; a Monte Carlo run reports the spread of R and T");
}

}  // namespace

MonteCarloRequest read_monte_carlo_design(const nlohmann::json& design, const std::string& where, nlohmann::json& passed) {
  MonteCarloRequest run;
  run.where = where;
  nlohmann::json plain = take_spreads(design_object(design), op_shot, where, run.spreads);
  run.settings = read_settings(plain, req_monte_carlo, where);
  if (plain.is_object()) {
    for (const Setting id : {Setting::samples, Setting::seed, Setting::claim}) plain.erase(setting_row(id).key);  // a run's own
    leave_out_capacity(plain, where, run.notes);
  }
  run.values = read_design_values(plain, where, &passed);
  return run;
}

void lay_over_run(MonteCarloRequest& run, const DesignValues& values, const SettingsValues& settings, const std::vector<SpreadInput>& spreads,
                  const std::string& where) {
  std::vector<std::string>& notes = run.notes;
  // What the caller gives for a value or setting, as a note writes it: its spread, Cd(Re), or its value.
  const auto flag_text = [&](const SpreadInput& s) -> std::string {
    for (const SpreadInput& flag : spreads)
      if (flag.value == s.value && flag.setting == s.setting) return spread_text(flag.input.spread, flag.input.dimension);
    if (s.setting == &SettingsValues::cd && settings.cd_of_reynolds) return "Cd(Re)";
    return quantity_text(*(s.value ? values.*s.value : settings.*s.setting), s.input.dimension, UnitSystem::si, 6);
  };
  const auto note = [&](const SpreadInput& s, const std::string& replaced) {
    const std::string key = spread_key(s);  // named by its key: a flag's is its flag, a request's its key
    notes.push_back("{{" + key + "}} " + flag_text(s) + " replaces " + where + "." + key + " = " + replaced);
  };
  // A run's spread that the caller gives (one value, a spread, Cd(Re), or vacuum for the air's) is no longer drawn.
  std::erase_if(run.spreads, [&](const SpreadInput& s) {
    const bool flagged = s.value ? (values.*s.value).has_value() : replaces_spread(settings, s);
    if (!flagged) return false;
    if (s.value || !settings.vacuum) note(s, spread_text(s.input.spread, s.input.dimension));  // vacuum has its own note
    if (s.value)
      run.values.*s.value = std::nullopt;
    else
      run.settings.*s.setting = std::nullopt;
    return true;
  });
  // A caller's spread over the run's one value: noted with its spread, not its first number.
  for (const SpreadInput& s : spreads) {
    std::optional<double>& own = s.value ? run.values.*s.value : run.settings.*s.setting;
    if (!own) continue;
    note(s, quantity_text(*own, s.input.dimension, UnitSystem::si, 6));
    own = std::nullopt;
  }
  run.values = overlay_flags(run.values, values, where, notes);
  // A spread whose value the caller fixes another way goes with it (--F over the file's spread L3).
  std::erase_if(run.spreads, [&](const SpreadInput& s) { return s.value && !(run.values.*s.value); });
  for (std::string& note_text : settings_notes(run.settings, settings, where)) notes.push_back(std::move(note_text));
  run.settings = overlay(run.settings, settings);
  for (const SpreadInput& spread : spreads) add_spread(run.spreads, spread);
}

nlohmann::ordered_json monte_carlo_request_json(const MonteCarloRequest& request, int samples, std::uint64_t seed) {
  const MonteCarloRequest first = with_draws(request, [](const Spread& s) { return s.a; });
  nlohmann::ordered_json design = nlohmann::ordered_json::object();
  const auto spread_of = [&](const auto& found) -> const SpreadInput* {
    const auto at = std::find_if(request.spreads.begin(), request.spreads.end(), found);
    return at == request.spreads.end() ? nullptr : &*at;
  };
  for (const InputField& field : input_fields()) {
    if (field.group == FieldGroup::capacity || !(first.values.*field.member)) continue;
    const SpreadInput* spread = spread_of([&](const SpreadInput& s) { return s.value == field.member; });
    design[field.key] = spread ? nlohmann::ordered_json(spread_text(spread->input.spread, field.dimension))
                               : nlohmann::ordered_json(*(first.values.*field.member));
  }
  if (first.values.machine) design[machine_key] = machine_name(*first.values.machine);
  nlohmann::ordered_json settings = settings_json(shot_settings(first.settings), nullptr);
  // A ball of given diameter gives the projectile's density; the air says none of its own.
  if (first.values.projectile_diameter && settings["air"].is_object()) settings["air"].erase("projectile_density");
  // A claim's verdict names the air's values left at their defaults (claim_context): they stay
  // unwritten, so that the run read back leaves them at their defaults too.
  if (request.settings.claim && settings["air"].is_object()) {
    if (!first.settings.cd && !first.settings.cd_of_reynolds) settings["air"].erase("drag_coefficient");
    if (!first.settings.projectile) settings["air"].erase("projectile_density");
    if (!first.settings.wind) settings["air"].erase("wind");
  }
  // A spread setting's text in its place: under its key (the target level) or in the air.
  for (const SpreadInput& spread : request.spreads) {
    if (!spread.setting) continue;
    const std::string path = spread_setting_path(spread.setting), text = spread_text(spread.input.spread, spread.input.dimension);
    if (path.rfind("air.", 0) == 0)
      settings["air"][path.substr(4)] = text;
    else
      settings[path] = text;
  }
  for (const auto& item : settings.items()) design[item.key()] = item.value();
  design["samples"] = samples;
  design["seed"] = seed;
  if (request.settings.claim) design["claim"] = *request.settings.claim;
  return {{request.completes ? "attested" : "design", design}};
}

MonteCarloRequest with_draws(const MonteCarloRequest& request, const std::function<double(const Spread&)>& value) {
  MonteCarloRequest sample = request;
  for (const SpreadInput& spread : request.spreads) {
    const double drawn = value(spread.input.spread);
    if (spread.value)
      sample.values.*spread.value = drawn;
    else
      sample.settings.*spread.setting = drawn;
  }
  return sample;
}

Verification sample_verification(const MonteCarloRequest& sample) {
  ShotSettings settings = shot_settings(sample.settings);
  if (sample.completes) return complete_engine(completion_request(sample.values, settings)).verification;
  settings.loads = false;  // a sample reports R, T, eps and v
  settings.release_at = release_of(sample.values, sample.where);
  return verify_engine(engine_record(sample.values, sample.where).engine, settings);
}

std::string describe_monte_carlo_air(const MonteCarloRequest& request) {
  const MonteCarloRequest first = with_draws(request, [](const Spread& s) { return s.a; });
  ShotSettings settings = shot_settings(first.settings);
  if (!settings.air) return "vacuum";
  AirDrawn drawn;
  for (const SpreadInput& spread : request.spreads) {
    drawn.cd = drawn.cd || spread.setting == &SettingsValues::cd;
    drawn.density = drawn.density || spread.setting == &SettingsValues::air_density;
    drawn.wind = drawn.wind || spread.setting == &SettingsValues::wind;
    // A given diameter makes the sphere's density follow its mass and its diameter.
    drawn.projectile = drawn.projectile ||
        (first.values.projectile_diameter && (spread.value == &DesignValues::projectile_diameter || spread.value == &DesignValues::m));
  }
  const std::optional<double>& d = first.values.projectile_diameter;
  if (d && first.values.m) settings.air->projectile_density = sphere_density(*first.values.m, *d);
  drawn.projectile = drawn.projectile || (d && !first.values.m);  // complete chooses each sample's m
  return describe_air(*settings.air, 0, drawn);
}

std::string describe_monte_carlo_release(const MonteCarloRequest& request) {
  const MonteCarloRequest first = with_draws(request, [](const Spread& s) { return s.a; });
  ShotSettings settings = shot_settings(first.settings);
  if (!request.completes) settings.release_at = release_of(first.values, first.where);
  for (const SpreadInput& spread : request.spreads)
    if (spread.value && field_of(spread.value).group == FieldGroup::release) {
      // The release is drawn: the rule's words give way to the spread's name; the level's stay.
      const std::string label = field_of(spread.value).label;  // "pin angle [deg]"
      return "release at the " + label.substr(0, label.find(" [")) + " drawn from " + spread.input.name + "'s spread, " + describe_target(settings);
    }
  return describe_release(settings);
}

std::int64_t shots_per_sample(const MonteCarloRequest& request) {
  const MonteCarloRequest first = with_draws(request, [](const Spread& s) { return s.a; });
  const ShotSettings settings = shot_settings(first.settings);
  if (!request.completes) {
    // Bad input at the first values (a release that cannot be made, say) ends the run before it
    // starts; a numerical failure there is one sample's, counted with the run's.
    try {
      sample_verification(first);
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::numerical) throw;
    }
    return 1;
  }
  return shots_per_completion([&] { return complete_engine(completion_request(first.values, settings)); });
}

std::vector<UncertainInput> uncertain_inputs(const MonteCarloRequest& request) {
  std::vector<UncertainInput> inputs;
  for (const SpreadInput& spread : request.spreads) inputs.push_back(spread.input);
  return inputs;
}

std::vector<FixedInput> fixed_inputs(const MonteCarloRequest& request) {
  std::vector<FixedInput> fixed;
  for (const bool completion_only : {true, false})
    for (const InputField& field : input_fields()) {
      const std::optional<double>& value = request.values.*field.member;
      if (field.group == FieldGroup::capacity || !value || completion_only == static_cast<bool>(field.operations & op_shot)) continue;
      const bool spread = std::any_of(request.spreads.begin(), request.spreads.end(), [&](const SpreadInput& s) { return s.value == field.member; });
      if (!spread) fixed.push_back({field.key, field.dimension, *value});
    }
  return fixed;
}

SampleOutcome sample_outcome(const MonteCarloRequest& request, std::mt19937_64& random, const std::function<std::string(std::string_view)>& word) {
  SampleOutcome outcome;
  try {
    const Verification v = sample_verification(with_draws(request, [&](const Spread& s) {
      outcome.drawn.push_back(draw(s, random));  // with_draws asks each spread once, in the run's order
      return outcome.drawn.back();
    }));
    outcome.values = {v.capacity.R, v.capacity.T, v.eps, v.v};
  } catch (const Error& e) {
    outcome.failure = e.message(word);
    outcome.failure_kind = e.kind();
  }
  return outcome;
}

namespace {

// The spans of the air's values left at their defaults (docs/verifier.md, "What decides a
// claim"): Cd from a smooth sphere's Cd(Re), which falls to about 0.1 past its drag crisis, to
// 0.5, a rough ball below it; the density from fired clay (1800 kg/m3) to basalt (3000 kg/m3);
// the wind a moderate breeze (Beaufort 4, 5 m/s) against the shot or with it.
constexpr double densest_stone = 3000, lightest_shot = 1800, breeze = 5, roughest_cd = 0.5;

ClaimSpan span_of(const Engine& engine, const ShotSettings& settings, std::string key, std::string what, std::string low_text,
                  const std::function<void(ShotSettings&)>& low, std::string high_text, const std::function<void(ShotSettings&)>& high) {
  const auto range_at = [&](const std::function<void(ShotSettings&)>& end) -> std::optional<double> {
    ShotSettings at = settings;
    end(at);
    try {
      return verify_engine(engine, at).capacity.R;
    } catch (const Error&) {
      return std::nullopt;  // the span's end is shown as not shot
    }
  };
  return {std::move(key), std::move(what), std::move(low_text), std::move(high_text), range_at(low), range_at(high), false};
}

ClaimContext middle_context(const MonteCarloRequest& request, double claim) {
  const MonteCarloRequest middle = with_draws(request, [](const Spread& s) { return s.kind == Spread::Kind::uniform ? (s.a + s.b) / 2 : s.a; });
  ShotSettings settings = shot_settings(middle.settings);
  settings.loads = false;
  Engine engine;
  if (middle.completes) {
    engine = complete_engine(completion_request(middle.values, settings)).engine;  // as the run's samples complete it
  } else {
    engine = engine_record(middle.values, middle.where).engine;
    settings.release_at = release_of(middle.values, middle.where);  // a given release stays the engine's
  }
  settings.criterion.release = Release::range;
  ClaimContext c;
  // Siano's black box: Delta U given whole to the projectile on the ground, v^2 = 2 Delta U/m,
  // thrown at its best angle to a target `level` above the base: (v^2/g) sqrt(1 - 2 g level/v^2).
  const double g = engine.material.g, v2 = 2 * potential_energy_drop(engine) / engine.m;
  c.energy_bound = v2 / g * std::sqrt(std::max(0.0, 1 - 2 * g * settings.target_level / v2));
  c.given_release = settings.release_at.has_value();
  c.farthest = verify_engine(engine, settings).capacity.R;
  const SettingsValues& given = middle.settings;  // a spread's setting holds its middle here
  if (!settings.air) {
    c.spans.push_back(span_of(
        engine, settings, "air", "the air (vacuum is the default)", "vacuum", [](ShotSettings&) {},
        "air at its defaults (Cd 0.47, a stone sphere, no wind)", [](ShotSettings& s) { s.air = Air{}; }));
  } else {
    if (!given.cd && !given.cd_of_reynolds)
      c.spans.push_back(span_of(
          engine, settings, "cd", "the drag coefficient Cd", "Cd(Re) of a smooth sphere", [](ShotSettings& s) { s.air->drag_coefficient.reset(); },
          format_significant(roughest_cd, 2), [](ShotSettings& s) { s.air->drag_coefficient = roughest_cd; }));
    if (!given.projectile && !middle.values.projectile_diameter)
      c.spans.push_back(span_of(
          engine, settings, "projectile", "the projectile's density", "fired clay, 1800 kg/m3",
          [](ShotSettings& s) { s.air->projectile_density = lightest_shot; }, "basalt, 3000 kg/m3",
          [](ShotSettings& s) { s.air->projectile_density = densest_stone; }));
    if (!given.wind)
      c.spans.push_back(span_of(
          engine, settings, "wind", "the wind", "5 m/s against the shot", [](ShotSettings& s) { s.air->wind = -breeze; }, "5 m/s with it",
          [](ShotSettings& s) { s.air->wind = breeze; }));
  }
  for (ClaimSpan& span : c.spans) span.decides = span.R_low && span.R_high && (*span.R_low >= claim) != (*span.R_high >= claim);
  return c;
}

}  // namespace

ClaimContext claim_context(const MonteCarloRequest& request, double claim, const std::function<std::string(std::string_view)>& word) {
  try {
    return middle_context(request, claim);
  } catch (const Error& e) {
    ClaimContext c;
    c.unavailable = e.message(word);
    return c;
  }
}

MonteCarloReport monte_carlo_report(const MonteCarloRequest& run, const MonteCarloSummary& summary, int samples, std::uint64_t seed,
                                    const std::function<std::string(std::string_view)>& word) {
  const std::optional<double> claim = run.settings.claim;
  // The air as the run's first sample flies it: each spread at its first number.
  const bool in_air = shot_settings(with_draws(run, [](const Spread& s) { return s.a; }).settings).air.has_value();
  return MonteCarloReport{summary,
                          uncertain_inputs(run),
                          fixed_inputs(run),
                          describe_monte_carlo_release(run),
                          seed,
                          run.completes ? "the completed engine" : "the shot",
                          describe_monte_carlo_air(run),
                          in_air,
                          0,
                          1,
                          claim,
                          monte_carlo_request_json(run, samples, seed),
                          claim ? std::optional(claim_context(run, *claim, word)) : std::nullopt};
}

}  // namespace trebuchet
