// An engine to verify, as users and the calculator write it in JSON: keys L1, L2, L3 (or F),
// L4, M, m, mb, theta_i_deg, optional g, and optional R and T (a predicted capacity). Values
// are SI numbers or strings with unit suffixes ("6.13m", "14.3t"). Other keys are ignored, so
// the calculator's output can be piped in as it is.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "trebuchet/engine.hpp"

namespace trebuchet {

struct DesignInput {
  Engine engine;
  std::optional<double> g;                 ///< [m/s^2], when the input names one
  std::optional<double> R, T;              ///< predicted capacity [m], [J], when the input carries one
};

/// Reads one design from a JSON object; `where` names it in messages ("design[2]"; empty:
/// the command line, whose keys are named as flags, "--L4").
/// Throws Error(bad_number | unknown_unit | usage) naming the key and the fix.
DesignInput design_from_json(const nlohmann::json& object, const std::string& where);

/// Checks an engine assembled from flags or JSON: lengths and masses positive (mb may be 0),
/// theta_i in (0, 90) degrees. Throws Error(bad_number) naming the parameter.
void check_engine(const Engine& engine, const std::string& where);

}  // namespace trebuchet
