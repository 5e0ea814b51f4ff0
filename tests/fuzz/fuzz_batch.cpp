// Fuzz target: the calculator's CSV batch reader with the built-in table. Every row is a design
// or a named error; a design the calculator returns must write as a row of finite numbers (a
// throw there is a defect, not an input error); every cell passed through and every message is
// UTF-8 (a Latin-1 file is read as such); the batch itself may only end in an Error.
#include <cstdlib>
#include <sstream>
#include <string>

#include "oracle.hpp"
#include "trebuchet/app/run/batch.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/records/search_records.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/app/input/text_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  std::istringstream input(std::string(reinterpret_cast<const char*>(data), size));
  try {
    trebuchet::run_batch(
        input, trebuchet::builtin_scaling_table(), trebuchet::DesignRequest{},
        [](const std::vector<std::string>& passed) {
          for (const std::string& name : passed)
            if (!trebuchet::is_utf8(name)) std::abort();
        },
        [](const trebuchet::BatchRow& row) {
          if (row.design) require_writes([&] { trebuchet::design_csv_text(*row.design, 17); });
          for (const std::string& cell : row.passed)
            if (!trebuchet::is_utf8(cell)) std::abort();
          if (row.error && !trebuchet::is_utf8(row.error->what())) std::abort();
        });
  } catch (const trebuchet::Error&) {
  }
  return 0;
}
