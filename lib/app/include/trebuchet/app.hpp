// The application layer over the core (trebuchet.hpp): values with units as users type them,
// JSON and CSV, reports, pictures and batches. The workbook writer is trebuchet/app/spreadsheet.hpp,
// in a target of its own (trebuchet::workbook).
#pragma once

#include "trebuchet.hpp"
#include "trebuchet/app/batch.hpp"
#include "trebuchet/app/csv.hpp"
#include "trebuchet/app/names.hpp"
#include "trebuchet/app/output_files.hpp"
#include "trebuchet/app/pictures.hpp"
#include "trebuchet/app/report.hpp"
#include "trebuchet/app/request.hpp"
#include "trebuchet/app/schema.hpp"
#include "trebuchet/app/design_input.hpp"
#include "trebuchet/app/design_record.hpp"
#include "trebuchet/app/search_records.hpp"
#include "trebuchet/app/shot_record.hpp"
#include "trebuchet/app/table_json.hpp"
#include "trebuchet/app/text_input.hpp"
#include "trebuchet/app/units.hpp"
