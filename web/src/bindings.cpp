// The library in the browser: each of api.hpp's requests as a function of JSON text to JSON text,
// for web/app.js (window.trebuchet) and the Web Workers of a Monte Carlo run. An error is an
// answer too ({"error": ...}), never an exception across into JavaScript.
#include <emscripten/bind.h>

#include <string>

#include "trebuchet/app/api.hpp"
#include "trebuchet/app/text_input.hpp"

namespace {

using Request = nlohmann::ordered_json (*)(const nlohmann::json&);

std::string answer(Request request, const std::string& text) {
  try {
    // As the programs read a JSON file: bounded depth, no key given twice, no number beyond a double.
    return request(trebuchet::parse_json(text, "the request", "a JSON object of the request's keys (docs/web.md)")).dump();
  } catch (const trebuchet::Error& e) {
    return trebuchet::api::error_json(e).dump();
  } catch (const std::exception& e) {
    return trebuchet::api::error_json(trebuchet::Error(trebuchet::ErrorKind::numerical, std::string("internal error: ") + e.what())).dump();
  }
}

std::string design(const std::string& text) { return answer(trebuchet::api::design, text); }
std::string shot(const std::string& text) { return answer(trebuchet::api::shot, text); }
std::string complete(const std::string& text) { return answer(trebuchet::api::complete, text); }
std::string monte_carlo(const std::string& text) { return answer(trebuchet::api::monte_carlo, text); }

}  // namespace

EMSCRIPTEN_BINDINGS(trebuchet) {
  emscripten::function("design", &design);
  emscripten::function("shot", &shot);
  emscripten::function("complete", &complete);
  emscripten::function("monteCarlo", &monte_carlo);
}
