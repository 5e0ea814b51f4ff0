// How the API's requests (api.hpp) read their keys: shared by api.cpp and api_contest.cpp (the
// contest's own room, which the page's build leaves out).
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/input/settings.hpp"

namespace trebuchet::api {

/// An optional value that must be positive (as the programs' options are), or 0 or more.
std::optional<double> positive_value(const nlohmann::json& request, const std::string& key, UnitDimension dimension, bool zero_allowed = false);
/// A request must be an object of known keys; a key it does not know is named with the keys it does.
void require_keys(const nlohmann::json& request, const std::vector<std::string>& known, const std::string& what);
/// The keys a request of `door` takes: its own, the settings of that door (settings.def) and,
/// where it shoots a design, the material's rows of `material_operation`.
std::vector<std::string> keys_of(unsigned door, unsigned material_operation = 0);
/// The string under `key`, or a refusal naming it.
std::string text_of(const nlohmann::json& value, const std::string& key);
/// The settings of a request of `door` (settings.def), each read as its flag is.
SettingsValues settings_values_of(const nlohmann::json& request, unsigned door);
/// The shot's settings from a request's keys, checked as the programs check their options.
ShotSettings settings_of(const nlohmann::json& request, unsigned door);
/// The request's "over": the engine's inputs that `operation` takes (fields(), the machine too)
/// laid over its design's own, as the programs' flags go over a file's (overlay_flags). With
/// `spreads`, each range or spread is taken there (a Monte Carlo run's, take_spreads); without,
/// refused unless `at` gives the value it stands for (complete's: a range's middle). A key of no
/// input is refused by name; the settings go beside the design instead.
DesignValues over_of(const nlohmann::json& request, unsigned operation, std::vector<SpreadInput>* spreads = nullptr,
                     const std::function<double(const Spread&)>& at = nullptr);
/// The material's rows a request gives over its design's own, each positive.
DesignValues material_of_request(const nlohmann::json& request, unsigned operation);

}  // namespace trebuchet::api
