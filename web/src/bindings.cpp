// The library in the browser: each of api.hpp's requests as a function of JSON text to JSON text,
// for web/app.js (window.trebuchet) and the Web Workers of a Monte Carlo run. An error is an
// answer too ({"error": ...}), never an exception across into JavaScript.
#include <emscripten/bind.h>

#include <string>

#include "trebuchet/app/api/api.hpp"

namespace {

std::string answer(trebuchet::api::Request request, const std::string& text) { return trebuchet::api::answer_text(request, text, "docs/web.md"); }

std::string design(const std::string& text) { return answer(trebuchet::api::design, text); }
std::string shot(const std::string& text) { return answer(trebuchet::api::shot, text); }
std::string sweep(const std::string& text) { return answer(trebuchet::api::sweep, text); }
std::string complete(const std::string& text) { return answer(trebuchet::api::complete, text); }
std::string monte_carlo(const std::string& text) { return answer(trebuchet::api::monte_carlo, text); }
std::string value(const std::string& text) { return answer(trebuchet::api::value, text); }
std::string fields(const std::string& text) { return answer(trebuchet::api::fields, text); }

}  // namespace

EMSCRIPTEN_BINDINGS(trebuchet) {
  emscripten::function("design", &design);
  emscripten::function("shot", &shot);
  emscripten::function("sweep", &sweep);
  emscripten::function("complete", &complete);
  emscripten::function("monteCarlo", &monte_carlo);
  emscripten::function("value", &value);
  emscripten::function("fields", &fields);
}
