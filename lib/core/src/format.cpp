#include "trebuchet/format.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace trebuchet {

std::string format_number(double value) {
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

std::string format_significant(double value, int significant) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
  return buffer;
}

std::string join(const std::vector<std::string>& texts, std::string_view separator) {
  std::string joined;
  for (std::size_t k = 0; k < texts.size(); ++k) joined += (k ? std::string(separator) : "") + texts[k];
  return joined;
}

std::string format_fraction(double value) {
  for (int denominator = 1; denominator <= 1000; ++denominator) {
    const double numerator = std::round(value * denominator);
    if (numerator >= 1 && numerator <= 1000 && std::abs(value - numerator / denominator) < 1e-12 * std::abs(value))
      return denominator == 1 ? format_number(numerator) : format_number(numerator) + "/" + std::to_string(denominator);
  }
  return format_number(value);
}

}  // namespace trebuchet
