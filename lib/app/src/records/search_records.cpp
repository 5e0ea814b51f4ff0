#include "trebuchet/app/records/search_records.hpp"

#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/records/shot_record.hpp"

namespace trebuchet {

nlohmann::ordered_json optimum_json(const Optimum& optimum, const ShotSettings& settings, double wall_time_s) {
  nlohmann::ordered_json out;
  write_engine(out, optimum.fit.engine);
  out["start"] = optimum.start;
  out["simulations"] = optimum.simulations;
  out["iterations"] = optimum.iterations;
  out["wall_time_s"] = wall_time_s;
  if (!optimum.note.empty()) out["note"] = optimum.note;
  const nlohmann::ordered_json shot = verification_json(optimum.fit.verification);
  for (const auto& [key, value] : shot.items()) out[key] = value;
  out["assumptions"] = assumptions_json(optimum.fit.engine, settings);
  out[version_key] = project_version();
  return out;
}

nlohmann::ordered_json calibration_json(const Calibration& c, const MeasuredRange& measured, const std::vector<Prediction>& predictions,
                                        const ShotSettings& settings) {
  nlohmann::ordered_json out;
  nlohmann::ordered_json engine;
  write_engine(engine, c.engine);
  out["engine"] = engine;
  out["assumptions"] = assumptions_json(c.engine, settings);
  out["measured"] = {{"R", measured.range}, {"uncertainty", measured.uncertainty}};
  nlohmann::ordered_json steps = nlohmann::ordered_json::array();
  for (const CalibrationStep& step : c.steps) steps.push_back({{"step", step.what}, {"R", step.R}});
  out["steps"] = steps;
  out["fitted"] = c.fitted == FrictionFit::scale ? "scale" : "pin_coefficient";
  out["value"] = c.value;
  out["value_low"] = c.value_low;
  out["value_high"] = c.value_high;
  out["band_clipped"] = c.band_clipped;
  if (c.jams_at) out["jams_at"] = *c.jams_at;
  const EngineParts& p = c.engine.parts;
  out["axle_friction"] = p.axle.friction, out["hinge_friction"] = p.hinge.friction, out["trough_friction"] = p.trough_friction;
  out["R_frictionless"] = c.frictionless.capacity.R;
  out["T_frictionless"] = c.frictionless.capacity.T;
  out["shot"] = verification_json(c.shot, std::nullopt);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const Prediction& prediction : predictions) {
    list.push_back({{"changed", prediction.changed},
                    {"R", prediction.R},
                    {"R_low", prediction.R_low ? nlohmann::ordered_json(*prediction.R_low) : nlohmann::ordered_json(nullptr)},
                    {"R_high", prediction.R_high ? nlohmann::ordered_json(*prediction.R_high) : nlohmann::ordered_json(nullptr)},
                    {"T", prediction.shot.capacity.T},
                    {"eps", prediction.shot.eps}});
    if (!prediction.band_end_refused.empty()) list.back()["band_end_refused"] = prediction.band_end_refused;
  }
  out["predictions"] = list;
  out["simulations"] = c.simulations;
  require_finite_json(out, "the calibration");
  out[version_key] = project_version();
  return out;
}

nlohmann::ordered_json completion_json(const Completion& c, const ShotSettings& settings, const Completion* longest,
                                       const std::string& longest_note) {
  nlohmann::ordered_json out;
  write_engine(out, c.engine);
  out["attested"] = c.attested;
  out["implied"] = c.implied;
  out["chosen"] = c.chosen;
  out["simulations"] = c.simulations;
  const nlohmann::ordered_json shot = verification_json(c.verification);
  for (const auto& [key, value] : shot.items()) out[key] = value;
  out["assumptions"] = assumptions_json(c.engine, settings);
  if (c.calculator)
    out["calculator"] = design_json(*c.calculator);
  else
    out["calculator_note"] = c.calculator_note;
  if (longest) {
    nlohmann::ordered_json alternative;
    write_engine(alternative, longest->engine);
    alternative["chosen"] = longest->chosen;
    alternative.update(verification_json(longest->verification));
    out["longest_range"] = alternative;
  } else if (!longest_note.empty()) {
    out["longest_range_note"] = longest_note;
  }
  out[version_key] = project_version();
  return out;
}

}  // namespace trebuchet
