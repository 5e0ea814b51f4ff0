// Fuzz target: the design readers, as the verifier reads a file: parse_json, then read_engine
// on the object or on each member of an array; and the same bytes as CSV (read_design_rows),
// then read_engine on each row; and read_design_inputs, which tells JSON from CSV, checks the
// columns passed through and reads text that is not UTF-8. A design read must be finite and must
// write and read back as itself; every cell passed through must be UTF-8.
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include "trebuchet/error.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/records/search_records.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/app/run/verifier.hpp"

namespace {

void read_one(const nlohmann::json& object, const std::string& where) {
  try {
    const trebuchet::EngineRecord record = trebuchet::read_engine(object, where);
    nlohmann::ordered_json written;
    trebuchet::write_engine(written, record.engine);
    const trebuchet::Engine back = trebuchet::read_engine(nlohmann::json::parse(written.dump()), where).engine;
    if (back.L1 != record.engine.L1 || back.M != record.engine.M || back.L3 != record.engine.L3) std::abort();
  } catch (const trebuchet::Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const nlohmann::json input = trebuchet::parse_json(text, "fuzz", "a design");
    if (input.is_array()) {
      for (std::size_t i = 0; i < input.size(); ++i) read_one(input[i], "design[" + std::to_string(i) + "]");
    } else {
      read_one(input, "design");
    }
  } catch (const trebuchet::Error&) {
  }
  try {
    const trebuchet::DesignInputs in = trebuchet::read_design_inputs(text, "fuzz.csv");
    for (const auto& row : in.rows)
      for (const std::string& cell : row.passed)
        if (!trebuchet::is_utf8(cell)) std::abort();
  } catch (const trebuchet::Error&) {
  }
  try {
    std::istringstream csv(text);
    for (const auto& row : trebuchet::read_design_rows(csv, "fuzz").rows)
      if (row.error.empty()) read_one(row.design, "line " + std::to_string(row.line));
  } catch (const trebuchet::Error&) {
  }
  return 0;
}
