// Fuzz target: merge's reader of the parts derive-table --shard writes (parse_json, then
// read_sweep_part), and the join of a part with itself into a table (derive_table, as merge
// does). Every text is a part and a table that writes with finite numbers, or an Error.
#include <string>

#include "oracle.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/table_derivation.hpp"
#include "trebuchet/app/records/table_json.hpp"
#include "trebuchet/app/input/text_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const trebuchet::SweepPart part = trebuchet::read_sweep_part(trebuchet::parse_json(text, "fuzz", "a part"), "fuzz");
    const trebuchet::DerivedTable table = trebuchet::derive_table({part});
    require_writes([&] { trebuchet::derived_table_json(table).dump(); });
  } catch (const trebuchet::Error&) {
  }
  return 0;
}
