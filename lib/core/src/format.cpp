#include "trebuchet/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace trebuchet {

// The fewest significant digits that read back as the same double, written fixed ("150",
// "0.001") or in scientific notation ("3.1e-05"), whichever is shorter, as std::to_chars writes
// it. By C's printf: messages only (the application layer writes data with {fmt}), and portable
// to builds whose library has no floating-point std::to_chars, such as a browser's.
std::string format_number(double value) {
  if (!std::isfinite(value)) return value != value ? "nan" : value > 0 ? "inf" : "-inf";
  char scientific[40];
  int digits = 1;
  for (; digits < 17; ++digits) {
    std::snprintf(scientific, sizeof scientific, "%.*e", digits - 1, value);
    if (std::strtod(scientific, nullptr) == value) break;
  }
  std::snprintf(scientific, sizeof scientific, "%.*e", digits - 1, value);
  const int exponent = std::atoi(std::strchr(scientific, 'e') + 1);
  char fixed[400];
  std::snprintf(fixed, sizeof fixed, "%.*f", std::max(0, digits - 1 - exponent), value);
  return std::strlen(fixed) <= std::strlen(scientific) ? fixed : scientific;
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
