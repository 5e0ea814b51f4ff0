// CSV as spreadsheets write it, read and written the same way by both programs (docs/csv.md):
// a UTF-8 byte-order mark, CRLF line ends, comma, semicolon or tab separators, quoted cells,
// decimal commas, units in the header ("R_m", "M_t") or in the cell ("150 m").
#pragma once

#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace trebuchet {

/// One data line of a CSV file: its line number (from 1, counting every line) and its cells,
/// unquoted and trimmed.
struct CsvRow {
  int line = 0;
  std::vector<std::string> cells;
};

/// Reads a CSV file line by line. The header is the first line that is neither blank nor a
/// comment ('#'); its separator (';' or tab if the header has one outside quotes and no comma,
/// else ',') is the file's. Lines end at LF, CRLF or CR. A line longer than 64 KiB is refused
/// and the next read after it; one without an end within max_input_bytes ends the input, so an
/// endless input ends. UTF-16 and NUL bytes are refused; a line not in UTF-8 is read as
/// Windows-1252 (as_utf8).
class CsvReader {
 public:
  /// Reads up to the header. Throws Error(usage) naming `source` for an input without one.
  CsvReader(std::istream& input, std::string source);
  const std::vector<std::string>& header() const { return header_; }
  char separator() const { return separator_; }
  /// The next data row; false at the end. Throws Error(usage) for a line of the wrong number
  /// of cells or with an unclosed quote: the caller reports that row and reads on.
  bool next(CsvRow& row);

 private:
  bool read_line(std::string& line);
  std::istream& input_;
  std::string source_;
  int line_number_ = 0;
  char separator_ = ',';
  bool ended_ = false;  ///< a line without an end within max_input_bytes ended the input
  std::vector<std::string> header_;
};

/// A column name split into the key it names and the unit its bare numbers are in:
/// "R_m" -> (R, "m"), "M_t" -> (M, "t"), "wood_density_kg_m3" -> (wood_density, "kg/m3");
/// a name equal to a key has no unit. nullopt when the name starts with no key of `keys`.
struct ColumnName {
  std::string key;
  std::string unit;
};
std::optional<ColumnName> split_column_name(std::string_view name, const std::vector<std::string_view>& keys);

/// A cell as the unit parser reads it: a decimal comma becomes a point ("150,5 m" -> "150.5 m"),
/// and a bare number gets the column's unit. Throws Error(bad_number) naming `column` for a
/// comma that may be a thousands separator ("1,500") or a cell with both ',' and '.'.
std::string cell_value(std::string_view cell, const std::string& unit, std::string_view column);

/// A cell for output: quoted when it holds the separator, a quote or a line end.
std::string csv_cell(std::string_view text, char separator = ',');
/// csv_cell appended to `out`, without a string of its own.
void append_csv_cell(std::string& out, std::string_view text, char separator = ',');

/// A number for CSV output with `digits` significant digits (17: every double round-trips).
std::string csv_number(double value, int digits);
/// csv_number appended to `out`, without a string of its own (a batch writes ~10^6 of them).
void append_csv_number(std::string& out, double value, int digits);

/// The default significant digits of CSV numbers, and the range --digits accepts.
inline constexpr int default_csv_digits = 6;
int parse_digits(std::string_view text, std::string_view option);

}  // namespace trebuchet
