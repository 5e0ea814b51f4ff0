#include "trebuchet/error.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "trebuchet/format.hpp"

namespace trebuchet {
namespace {

// A reference to a name is "{{name}}": a letter or _, then letters, digits, _ and -, in double
// braces, which text a user types (a path, a value) does not hold by chance. The length of the
// name of the reference at text[at], or 0 where none starts there.
std::size_t reference_length(std::string_view text, std::size_t at) {
  if (text.compare(at, 2, "{{") != 0 || at + 2 >= text.size()) return 0;
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; };
  if (!(std::isalpha(static_cast<unsigned char>(text[at + 2])) || text[at + 2] == '_')) return 0;
  std::size_t end = at + 2;
  while (end < text.size() && word(text[end])) ++end;
  return text.compare(end, 2, "}}") == 0 ? end - at - 2 : 0;
}

}  // namespace

std::string with_words(std::string_view text, const std::function<std::string(std::string_view)>& word) {
  if (text.find("{{") == std::string_view::npos) return std::string(text);
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    // The text up to the next "{{" as it stands, then the reference there, if it is one.
    const std::size_t brace = std::min(text.find("{{", at), text.size());
    out.append(text, at, brace - at);
    at = brace;
    if (at == text.size()) break;
    if (const std::size_t length = reference_length(text, at)) {
      out += word(text.substr(at + 2, length));
      at += length + 4;
    } else {
      out += text[at++];
    }
  }
  return out;
}

Error::Error(ErrorKind kind, const std::string& message)
    : std::runtime_error(with_words(message, [](std::string_view name) { return std::string(name); })), kind_(kind), text_(message) {}

std::string Error::message(const std::function<std::string(std::string_view name)>& word) const { return with_words(text_, word); }

std::vector<std::string> Error::names() const {
  std::vector<std::string> out;
  for (std::size_t at = 0; at < text_.size(); ++at)
    if (const std::size_t length = reference_length(text_, at)) out.emplace_back(text_.substr(at + 2, length));
  return out;
}

void check_ordinary(double value, double lowest, double highest, std::string_view key, std::string_view unit, std::string_view what) {
  if (value >= lowest && value <= highest) return;
  // Called for every shot: the text is built only when the value is refused.
  const std::string space = unit.empty() ? "" : " " + std::string(unit);
  if (!std::isfinite(value))
    throw Error(ErrorKind::bad_number,
                "{{" + std::string(key) + "}} is not a finite number for the " + std::string(what) + "; give one from " +
                    format_significant(lowest, 6) + " to " + format_significant(highest, 6) + space);
  throw Error(ErrorKind::bad_number,
              "{{" + std::string(key) + "}} = " + format_significant(value, 6) + space + " is not of ordinary size for the " + std::string(what) +
                  "; give one from " + format_significant(lowest, 6) + " to " + format_significant(highest, 6) + space);
}

}  // namespace trebuchet
