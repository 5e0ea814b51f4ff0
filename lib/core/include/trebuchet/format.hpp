// Number formatting shared by messages, CSV and tables.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace trebuchet {

/// Shortest text that reads back as the same double ("150", "0.1", "3.1e-05").
std::string format_number(double value);

/// `value` rounded to `significant` digits, without trailing zeros in the exponent form.
std::string format_significant(double value, int significant);

/// The texts one after another with `separator` between them ("L1, L2, L4").
std::string join(const std::vector<std::string>& texts, std::string_view separator);

/// A simple fraction for values such as F and beta2 ("2/3", "1/300", "1"), else the number.
std::string format_fraction(double value);

}  // namespace trebuchet
