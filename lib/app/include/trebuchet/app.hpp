// The application layer over the core (trebuchet.hpp), in the rooms a request passes through
// (docs/architecture.md): what comes in (values with units as users type them, CSV, names, the
// tables of inputs and settings), the records written and read back, what goes out (reports,
// pictures), what runs (batches, the verifier's operations) and the api. The workbook writer is
// trebuchet/app/output/spreadsheet.hpp, in a target of its own (trebuchet::workbook).
#pragma once

#include "trebuchet.hpp"
#include "trebuchet/app/input/csv.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/input/request.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/app/input/units.hpp"
#include "trebuchet/app/output/output_files.hpp"
#include "trebuchet/app/output/pictures.hpp"
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/search_records.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/app/records/table_json.hpp"
#include "trebuchet/app/run/batch.hpp"
