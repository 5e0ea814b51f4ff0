// Fuzz target: the constants-table loader. A table that loads must serve a request: the
// calculator gives a design or a named error, and a design it gives writes with finite numbers.
#include <cstdlib>
#include <optional>
#include <string>

#include "oracle.hpp"
#include "trebuchet/app/records/table_json.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/records/search_records.hpp"
#include "trebuchet/app/records/shot_record.hpp"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  try {
    const trebuchet::ScalingTable table = trebuchet::parse_scaling_table(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
    for (const trebuchet::TableBlock& block : table.blocks) {
      trebuchet::DesignRequest request;
      request.first = {trebuchet::Quantity::R, 150};
      request.second = {trebuchet::Quantity::m, 50};
      request.theta_i_deg = block.theta_i_deg, request.F = block.F, request.extrapolate = true;
      std::optional<trebuchet::OptimalEngine> design;
      try {
        design = trebuchet::design_optimal_engine(table, request);
      } catch (const trebuchet::Error&) {
      }
      if (design) require_writes([&] { trebuchet::design_json(*design); });
    }
  } catch (const trebuchet::Error&) {
  }
  return 0;
}
