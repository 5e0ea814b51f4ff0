#include "trebuchet/app/input/csv.hpp"

#include <fmt/compile.h>

#include <iterator>

#include <algorithm>
#include <cctype>
#include <charconv>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/app/input/text_input.hpp"

namespace trebuchet {
namespace {

constexpr std::size_t max_line_bytes = 1 << 16;

std::string_view trim_blanks(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

bool skipped(std::string_view line) {
  const std::string_view text = trim_blanks(line);
  return text.empty() || text.front() == '#';
}

// The separator of a file, from its header: ';' or tab when the header has one outside quotes
// and no comma there (spreadsheets in locales with a decimal comma write ';'), else ','.
char separator_of(std::string_view header) {
  bool quoted = false, comma = false, semicolon = false, tab = false;
  for (char c : header) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    comma |= c == ',', semicolon |= c == ';', tab |= c == '\t';
  }
  if (comma) return ',';
  if (semicolon) return ';';
  return tab ? '\t' : ',';
}

// RFC 4180 cells: a cell in double quotes may hold the separator, and "" is one quote; blanks
// around a cell are dropped. Throws for an unclosed quote.
std::vector<std::string> split(std::string_view line, char separator, const std::string& where) {
  std::vector<std::string> cells;
  std::size_t k = 0;
  while (true) {
    while (k < line.size() && (line[k] == ' ' || (line[k] == '\t' && separator != '\t'))) ++k;
    std::string cell;
    if (k < line.size() && line[k] == '"') {
      ++k;
      while (true) {
        if (k >= line.size())
          throw Error(ErrorKind::usage, where + ": a quote is not closed; close it, or write a quote inside a quoted cell as \"\"");
        if (line[k] == '"') {
          if (k + 1 < line.size() && line[k + 1] == '"') {
            cell += '"', k += 2;
            continue;
          }
          ++k;
          break;
        }
        cell += line[k++];
      }
      while (k < line.size() && line[k] != separator) {
        if (line[k] != ' ' && line[k] != '\t' && line[k] != '\r')
          throw Error(ErrorKind::usage, where + ": text after a quoted cell; put the whole cell in quotes");
        ++k;
      }
    } else {
      const std::size_t end = std::min(line.find(separator, k), line.size());
      cell = std::string(trim_blanks(line.substr(k, end - k)));
      k = end;
    }
    cells.push_back(std::move(cell));
    if (k >= line.size()) return cells;
    ++k;  // the separator
  }
}

}  // namespace

CsvReader::CsvReader(std::istream& input, std::string source) : input_(input), source_(std::move(source)) {
  std::string line;
  while (read_line(line)) {
    // Excel's "CSV UTF-8" starts with a byte-order mark; it is not part of the first column's name.
    if (line_number_ == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (skipped(line)) continue;
    separator_ = separator_of(line);
    header_ = split(line, separator_, source_ + " line " + std::to_string(line_number_));
    return;
  }
  throw Error(ErrorKind::usage, source_ + " is empty; its first line must name the columns, e.g. 'R,m'");
}

// A line ends at LF, CRLF or a lone CR (as old Mac files end them).
bool CsvReader::read_line(std::string& line) {
  line.clear();
  std::streambuf* buffer = input_.rdbuf();
  constexpr int eof = std::char_traits<char>::eof();
  if (ended_) return false;
  int c = buffer->sbumpc();
  if (c == eof) return false;
  ++line_number_;
  std::size_t length = 0;
  bool nul = false;
  // A line too long is read to its end, so that the next starts where it should; but no
  // further than an input may be long (/dev/zero has no end), and then the input ends here.
  for (; c != eof && c != '\n' && c != '\r'; c = buffer->sbumpc()) {
    nul |= c == 0;
    if (++length <= max_line_bytes)
      line += static_cast<char>(c);
    else if (length > max_input_bytes)
      break;
  }
  if (c == '\r' && buffer->sgetc() == '\n') buffer->sbumpc();
  const std::string where = source_ + " line " + std::to_string(line_number_);
  // UTF-16, as "Unicode text" from a spreadsheet, is told by its byte-order mark.
  if (line_number_ == 1 && (line.rfind("\xFF\xFE", 0) == 0 || line.rfind("\xFE\xFF", 0) == 0))
    throw Error(ErrorKind::usage, source_ + " is UTF-16 (Unicode text); save it as CSV UTF-8, or CSV, and give that");
  if (length > max_input_bytes) {
    ended_ = true;
    throw Error(ErrorKind::usage, where + " has no end within " + std::to_string(max_input_bytes >> 20) + " MiB; give a CSV file, one row a line");
  }
  if (length > max_line_bytes)
    throw Error(ErrorKind::usage, where + " is longer than " + std::to_string(max_line_bytes >> 10) + " KiB; give a CSV file, one row a line");
  if (nul) throw Error(ErrorKind::usage, where + " holds a NUL byte; give text, saved as UTF-8 (\"CSV UTF-8\")");
  line = as_utf8(line);  // a line saved as Windows-1252 ("Sa\xf4ne") is read as it was meant: UTF-8 from here on
  return true;
}

bool CsvReader::next(CsvRow& row) {
  std::string line;
  while (true) {
    try {
      if (!read_line(line)) break;
    } catch (const Error&) {
      row.line = line_number_;  // the caller reports the row in its place, and reads on
      throw;
    }
    if (skipped(line)) continue;
    row.line = line_number_;
    const std::string where = source_ + " line " + std::to_string(line_number_);
    row.cells = split(line, separator_, where);
    if (row.cells.size() != header_.size())
      throw Error(ErrorKind::usage,
                  where + ": expected " + std::to_string(header_.size()) + " cells as in the header, found " + std::to_string(row.cells.size()) +
                      "; quote a cell that holds '" + std::string(1, separator_) + "'");
    return true;
  }
  return false;
}

std::optional<ColumnName> split_column_name(std::string_view name, const std::vector<std::string_view>& keys) {
  std::optional<ColumnName> best;
  for (std::string_view key : keys) {
    if (name == key) return ColumnName{std::string(key), ""};
    // The longest key that prefixes the name with an underscore: "mb_kg" is mb, not m.
    if (name.size() > key.size() + 1 && name.substr(0, key.size()) == key && name[key.size()] == '_' && (!best || key.size() > best->key.size())) {
      std::string unit(name.substr(key.size() + 1));
      if (const auto under = unit.find('_'); under != std::string::npos) unit[under] = '/';  // kg_m3 -> kg/m3
      best = ColumnName{std::string(key), unit};
    }
  }
  return best;
}

std::string cell_value(std::string_view cell, const std::string& unit, std::string_view column) {
  std::string text(cell);
  if (const auto comma = text.find(','); comma != std::string::npos) {
    const std::string what = std::string(column) + ": '" + text + "'";
    if (text.find('.') != std::string::npos || text.find(',', comma + 1) != std::string::npos)
      throw Error(ErrorKind::bad_number,
                  what + " mixes ',' and '.' or has two commas; write one decimal separator and no thousands separators, e.g. 1500.5");
    // "1,500" may be one and a half or fifteen hundred: refused. "0,500" and "1,5" are not in doubt.
    std::size_t digits_after = 0;
    while (comma + 1 + digits_after < text.size() && std::isdigit(static_cast<unsigned char>(text[comma + 1 + digits_after]))) ++digits_after;
    std::size_t integer_start = comma;
    while (integer_start > 0 && std::isdigit(static_cast<unsigned char>(text[integer_start - 1]))) --integer_start;
    const std::size_t digits_before = comma - integer_start;
    if (digits_after == 3 && digits_before >= 1 && digits_before <= 3 && text[integer_start] != '0')
      throw Error(ErrorKind::bad_number,
                  what + " could be a decimal comma or a thousands separator; write it without the comma (" + text.substr(0, comma) +
                      text.substr(comma + 1) + ") or with a point (" + text.substr(0, comma) + "." + text.substr(comma + 1) + ")");
    text[comma] = '.';
  }
  if (unit.empty() || text.empty()) return text;
  // A bare number (digits, sign, point, exponent, fraction bar) takes the column's unit.
  const bool bare = std::all_of(text.begin(), text.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E' || c == '/';
  });
  return bare ? text + unit : text;
}

void append_csv_cell(std::string& out, std::string_view text, char separator) {
  const char special[] = {separator, '"', '\n', '\r'};
  if (text.find_first_of(std::string_view(special, sizeof special)) == std::string_view::npos) {
    out += text;
    return;
  }
  out += '"';
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

std::string csv_cell(std::string_view text, char separator) {
  std::string out;
  append_csv_cell(out, text, separator);
  return out;
}

// With {fmt}: printf's %.*g, and the shortest text that reads back (as std::to_chars gives it),
// at a fraction of snprintf's cost, which was half a large batch's time.
void append_csv_number(std::string& out, double value, int digits) {
  if (digits >= 17)
    fmt::format_to(std::back_inserter(out), FMT_COMPILE("{}"), value);
  else
    fmt::format_to(std::back_inserter(out), FMT_COMPILE("{:.{}g}"), value, digits);
}

std::string csv_number(double value, int digits) {
  std::string out;
  append_csv_number(out, value, digits);
  return out;
}

int parse_digits(std::string_view text, std::string_view option) {
  int digits = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), digits);
  if (ec != std::errc() || end != text.data() + text.size() || digits < 1 || digits > 17)
    throw Error(ErrorKind::usage,
                std::string(option) + ": '" + std::string(text) + "' is not a number of significant digits; give 1 to 17 (17: every value exactly)");
  return digits;
}

}  // namespace trebuchet
