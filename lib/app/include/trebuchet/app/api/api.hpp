// The library as JSON in and JSON out, for callers that are no command line: the browser page's
// window.trebuchet (web/) and the Python module to come. A request's keys are the programs' JSON
// keys (docs/schema.md); a value is an SI number or a string with a unit ("150m", "3.1t"). Each
// answer is what the programs print with --format json. docs/web.md lists every request.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "trebuchet/error.hpp"

namespace trebuchet::api {

/// The calculator (trebuchet-calc --format json): two givens among R, T, L1, L2, L4, D, M, m, mb,
/// Lb, l; optional theta_i_deg, F, branch ("auto", "lower", "upper"), extrapolate, scale and the
/// material (beta2, youngs_modulus, wood_density, g).
nlohmann::ordered_json design(const nlohmann::json& request);

/// One shot (trebuchet-verify --format json): "design" (an engine object, its parts as built
/// among its keys), and the settings of settings.def that a shot takes, under the programs'
/// names: "quality" ("Q", "eps", "range"; alias "release"), "n", "tol" on a capacity the design
/// carries (alias "tolerance"), "stepper", "rtol", "atol", "target_level", "range_from" ("pivot",
/// "release"), "air" (false, true or an object of density, drag_coefficient, projectile_density,
/// wind, drag_in_sling), or its details as the flags give them ("air_density", "cd", "projectile",
/// "wind", "drag_in_sling"); the material's keys (g, youngs_modulus, wood_density,
/// modulus_of_rupture) over the design's own; "fit" (fit the design to its capacity first). With
/// "series": true the answer adds "series", the motion the viewer draws (shot_series_json).
nlohmann::ordered_json shot(const nlohmann::json& request);

/// A what-if sweep (trebuchet-verify sweep --format json, what_if.hpp): "design" (as shot's),
/// "vary" ("L4=2m..5m": a value of the engine, its parts or its release, and its range),
/// "points" (2 to 1000, default 21) and the settings of shot. Each point's record is the shot's
/// answer for that engine, or {key: value, "error"}.
nlohmann::ordered_json sweep(const nlohmann::json& request);

/// One engine's parts built as each machine, side by side (trebuchet-verify compare --format
/// json): "design" (as shot's, a record too) and the settings of shot; released where the range
/// peaks unless "quality" says otherwise.
nlohmann::ordered_json compare(const nlohmann::json& request);

/// The best engine of a machine within a contest's limits (trebuchet-verify contest --format
/// json): "m", the beam by "D" or "mb_per_m", "machine", "theta_i_deg", the material, the box,
/// the limits ("max_width", ..., "min_clearance"), "objective" (range or eps), "pareto" and the
/// air and the target's settings. "machine": "all" answers each machine's best by its name (or
/// the error object that machine was refused with) side by side, as --machine all; a refusal
/// every machine gives alike is the answer's own.
nlohmann::ordered_json contest(const nlohmann::json& request);

/// The ab-initio optimum (trebuchet-verify optimize --format json, an array of the optima found):
/// "R" with "T" or with the stone's "m"; optional "theta_i_deg", "F", "l" (a fixed beam ratio),
/// the material (beta2, youngs_modulus, wood_density, g) and the settings of shot.
nlohmann::ordered_json optimize(const nlohmann::json& request);

/// The completion of an attested engine (trebuchet-verify complete --format json): "attested"
/// (Lb, L1, L2, H, L4, M, m, mb, D, l, theta_i_deg, F, the material's keys, and the parts as built
/// that complete takes: the pins' friction, counterweight_inertia, the rope) and the settings
/// of shot. Without "release": "range", the engine of the longest range is completed too. A
/// value given as a range or a spread is completed at its middle (monte_carlo samples it).
nlohmann::ordered_json complete(const nlohmann::json& request);

/// A Monte Carlo run (trebuchet-verify ... --format json with a range or a spread): "design"
/// (for shots) or "attested" (for completions) whose values may be ranges "2.5t..3.5t" or spreads
/// "3.5m±0.2m", the settings of shot, "samples" and "seed". A run may be split among workers:
/// "first" and "count" give those samples' outcomes alone ({"outcomes": [...]}, each [R, T, eps,
/// v] or {"failure", "kind"}), and "outcomes" (all of them, in sample order) gives the report of
/// the whole run, the same as one run of every sample. With "draws_csv": true the report adds
/// "draws_csv", every sample's drawn inputs and outcomes as trebuchet-verify --draws writes them.
nlohmann::ordered_json monte_carlo(const nlohmann::json& request);

/// A value as a user typed it, read as the programs read it: {"key": an input's key or alias,
/// "text": "19ft"} gives {"key", "value": SI (angles in degrees)}. For a page's typed boxes.
nlohmann::ordered_json value(const nlohmann::json& request);

/// The table of inputs (fields.hpp) and the table of settings (settings.hpp), for a page or a
/// notebook that builds its forms from them: {"fields": [{key, flag, aliases, dimension, unit,
/// units (the suffixes taken), group, operations ("given", "design" for the calculator's
/// settings, "shot", "complete", "optimize"), label, help, example, default, range}, ...],
/// "settings": [{key, flag, aliases, dimension, requests (the requests here that take it), help,
/// default, range}, ...]}. The request is {}.
nlohmann::ordered_json fields(const nlohmann::json& request);

/// A request as text, for callers across a language boundary (the page's bindings, the Python
/// module): read as the programs read a JSON file (bounded depth, no key given twice, no number
/// beyond a double), answered as text. A refusal, or an internal error, is error_json's answer,
/// never an exception. `where_documented` ends the message of text that is no request.
using Request = nlohmann::ordered_json (*)(const nlohmann::json&);
std::string answer_text(Request request, const std::string& text, const std::string& where_documented);

/// An error as an answer: {"error": the message, naming the request's keys, "kind": "bad_number",
/// "names": the keys it speaks of}.
nlohmann::ordered_json error_json(const Error& error);

}  // namespace trebuchet::api
