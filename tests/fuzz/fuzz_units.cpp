// Fuzz target: the unit parser and the ranges and spreads built on it (2.5t..3.5t, 3.5m±0.2m).
// Every text is a finite value (a finite range or spread) or an Error of its named kinds;
// anything else (another exception, a crash, a sanitizer report) is a defect.
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "trebuchet/error.hpp"
#include "trebuchet/uncertainty.hpp"
#include "trebuchet/app/input/units.hpp"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  using trebuchet::UnitDimension;
  for (UnitDimension d : {UnitDimension::length, UnitDimension::mass, UnitDimension::energy, UnitDimension::dimensionless, UnitDimension::angle,
                          UnitDimension::acceleration, UnitDimension::pressure, UnitDimension::density, UnitDimension::time, UnitDimension::speed}) {
    try {
      if (!std::isfinite(trebuchet::parse_value(text, d, "--x"))) std::abort();
    } catch (const trebuchet::Error& e) {
      if (e.kind() != trebuchet::ErrorKind::bad_number && e.kind() != trebuchet::ErrorKind::unknown_unit) std::abort();
    }
    try {
      if (const auto spread = trebuchet::parse_spread(text, d, "--x"))
        if (!std::isfinite(spread->a) || !std::isfinite(spread->b)) std::abort();
    } catch (const trebuchet::Error& e) {
      if (e.kind() != trebuchet::ErrorKind::bad_number && e.kind() != trebuchet::ErrorKind::unknown_unit) std::abort();
    }
  }
  return 0;
}
