#include "trebuchet/batch.hpp"

#include <optional>
#include <string>
#include <vector>

#include "trebuchet/request.hpp"
#include "trebuchet/units.hpp"

namespace trebuchet {
namespace {

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  text = text.substr(first, last - first + 1);
  if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = text.substr(1, text.size() - 2);
  return text;
}

std::vector<std::string_view> split_cells(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return cells;
    start = comma + 1;
  }
}

bool skipped(std::string_view line) {
  const std::string_view text = trim(line);
  return text.empty() || text.front() == '#';
}

enum class ColumnRole { given, theta, F, branch };

struct Header {
  std::vector<ColumnRole> roles;
  std::vector<std::string> names;
};

Header parse_header(std::string_view line) {
  Header header;
  int givens = 0;
  for (std::string_view name : split_cells(line)) {
    ColumnRole role = ColumnRole::given;
    if (name == "theta" || name == "theta_i_deg") role = ColumnRole::theta;
    else if (name == "F") role = ColumnRole::F;
    else if (name == "branch") role = ColumnRole::branch;
    else if (!quantity_from_name(name))
      throw Error(ErrorKind::usage, "batch header: unknown column '" + std::string(name) +
                                        "'; name two givens (R, T, L1, L2, L4, D, M, m, mb, Lb, l) and optionally theta, F, branch");
    for (const std::string& seen : header.names)
      if (seen == name) throw Error(ErrorKind::usage, "batch header: column '" + std::string(name) + "' appears twice");
    givens += role == ColumnRole::given;
    header.roles.push_back(role);
    header.names.emplace_back(name);
  }
  if (givens != 2)
    throw Error(ErrorKind::given_count, "batch header: found " + std::to_string(givens) +
                                            " given columns; name exactly two, e.g. 'R,m'");
  return header;
}

DesignRequest parse_row(const Header& header, std::string_view line, const DesignRequest& defaults) {
  const std::vector<std::string_view> cells = split_cells(line);
  if (cells.size() != header.roles.size())
    throw Error(ErrorKind::usage, "expected " + std::to_string(header.roles.size()) + " cells (" +
                                      std::to_string(header.roles.size() - 1) + " commas), found " + std::to_string(cells.size()));
  DesignRequest request = defaults;
  std::vector<Given> givens;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    switch (header.roles[k]) {
      case ColumnRole::given: givens.push_back(parse_given(header.names[k], cells[k])); break;
      case ColumnRole::theta: request.theta_i_deg = parse_theta(cells[k], "theta"); break;
      case ColumnRole::F: request.F = parse_positive(cells[k], UnitDimension::dimensionless, "F"); break;
      case ColumnRole::branch: request.branch = parse_branch_choice(cells[k]); break;
    }
  }
  request.first = givens[0];
  request.second = givens[1];
  return request;
}

// The longest line a batch may have: a row of every column with long units fits in far less.
constexpr std::size_t max_line_bytes = 1 << 16;

// The next line of `input` into `line`, without its '\n'; false at the end. A line longer
// than max_line_bytes is an error: an endless one (/dev/zero) is never read whole.
bool read_line(std::istream& input, std::string& line, int line_number) {
  line.clear();
  std::streambuf* buffer = input.rdbuf();
  int c = buffer->sbumpc();
  if (c == std::char_traits<char>::eof()) return false;
  for (; c != std::char_traits<char>::eof() && c != '\n'; c = buffer->sbumpc()) {
    if (line.size() == max_line_bytes)
      throw Error(ErrorKind::usage, "batch line " + std::to_string(line_number) + " is longer than " +
                                        std::to_string(max_line_bytes >> 10) + " KiB; give a CSV file of requests, one a line");
    line += static_cast<char>(c);
  }
  return true;
}

}  // namespace

int run_batch(std::istream& input, const ScalingTable& table, const DesignRequest& defaults,
              const BatchRowHandler& handle_row) {
  std::string line;
  int line_number = 0;
  std::optional<Header> header;
  int failures = 0;
  while (read_line(input, line, line_number + 1)) {
    ++line_number;
    // Excel's "CSV UTF-8" starts with a byte-order mark; it is not part of the first column's name.
    if (line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (skipped(line)) continue;
    if (!header) {
      header = parse_header(line);
      continue;
    }
    try {
      const OptimalEngine design = design_optimal_engine(table, parse_row(*header, line, defaults));
      handle_row(line_number, &design, nullptr);
    } catch (const Error& error) {
      ++failures;
      handle_row(line_number, nullptr, &error);
    }
  }
  if (!header) throw Error(ErrorKind::usage, "batch input is empty; its first line must name two givens, e.g. 'R,m'");
  return failures;
}

}  // namespace trebuchet
