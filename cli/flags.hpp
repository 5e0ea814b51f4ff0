// The programs' options that CLI11 hands over as text, read into typed values at once: text
// becomes a number here, at the edge, and nowhere else. Each message names the option.
#pragma once

#include <CLI/CLI.hpp>
#include <charconv>
#include <functional>
#include <string>
#include <type_traits>

#include "trebuchet/error.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {

// An option whose text CLI11 hands to `parse` as soon as it reads it; an empty value is refused.
inline CLI::Option* parsed_option(CLI::App* app, const std::string& name, const std::function<void(const std::string&)>& parse,
                                  const std::string& help) {
  return app->add_option_function<std::string>(
      name,
      [name, parse](const std::string& text) {
        if (text.empty()) throw Error(ErrorKind::usage, name + " was given an empty value; give a value after it, or leave it out");
        parse(text);
      },
      help);
}

// A strictly positive value with a unit into a double.
inline CLI::Option* positive_option(CLI::App* app, const std::string& name, double& target, UnitDimension dimension, const std::string& help) {
  return parsed_option(
      app, name, [&target, name, dimension](const std::string& text) { target = parse_positive(text, dimension, name); }, help);
}

// A whole number from `lowest` to `highest` into `target`; the message names the option and the range.
template <class Integer, class Target>
void integer_option(CLI::App* app, const std::string& name, Target& target, Integer lowest, Integer highest, const std::string& range,
                    const std::string& help) {
  parsed_option(
      app, name,
      [&target, name, lowest, highest, range](const std::string& text) {
        // Read as a wider integer of the same signedness: a negative seed is refused, not wrapped.
        using Wide = std::conditional_t<std::is_signed_v<Integer>, long long, unsigned long long>;
        Wide value = 0;
        const bool negative = !text.empty() && text.front() == '-';
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if ((negative && std::is_unsigned_v<Integer>) ||
            (ec == std::errc() && end == text.data() + text.size() && (value < lowest || (highest > 0 && value > highest))))
          throw Error(ErrorKind::usage, name + ": " + text + " must be " + range);
        if (ec != std::errc() || end != text.data() + text.size())
          throw Error(ErrorKind::usage, name + ": '" + text + "' is not a whole number; give " + range);
        target = static_cast<Integer>(value);
      },
      help);
}

}  // namespace trebuchet
