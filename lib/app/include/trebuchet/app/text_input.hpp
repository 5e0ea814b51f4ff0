// Reading what users give: a file or stdin, bounded in size, and JSON whose members can each be
// wrong without losing the others.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace trebuchet {

/// The largest input file or stdin the programs read whole (a design, a table, a sweep part) [bytes].
inline constexpr std::size_t max_input_bytes = std::size_t{64} << 20;

/// How messages name a path: "stdin" for "-", else 'path'.
std::string source_name(const std::string& path);

/// The whole text of the file at `path`, or of stdin for "-". Throws Error(usage) naming the
/// path, what it should hold (`expected`) and the fix: a file that cannot be opened, a
/// directory, or one larger than max_input_bytes (it is never read further, so an endless
/// device such as /dev/zero ends too).
std::string read_text(const std::string& path, std::string_view expected);

/// Parses JSON text. A number beyond the range of a double (1e400) becomes a string of its own
/// text, so that the reader of that one member reports it and the others are kept. Throws
/// Error(usage) naming `source` and what it should hold for text that is not JSON.
nlohmann::json parse_json(const std::string& text, const std::string& source, std::string_view expected);

}  // namespace trebuchet
