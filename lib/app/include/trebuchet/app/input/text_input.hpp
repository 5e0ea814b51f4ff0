// Reading what users give: a file or stdin, bounded in size, and JSON whose members can each be
// wrong without losing the others; and JSON written back.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace trebuchet {

/// The largest input file or stdin the programs read whole (a design, a table, a sweep part) [bytes].
inline constexpr std::size_t max_input_bytes = std::size_t{64} << 20;

/// The deepest nesting of arrays and objects a design, table or sweep part may have; theirs is
/// at most 4. Deeper input is refused before it is parsed, so no reader recurses without bound.
inline constexpr std::size_t max_json_depth = 32;

/// The deepest nesting of arrays and objects in JSON text, counted outside strings; the count
/// stops once it passes max_json_depth.
std::size_t json_depth(std::string_view text);

/// The first key given twice in one object of JSON text, if any (nlohmann would keep the last).
std::optional<std::string> duplicate_key(std::string_view text);

/// A JSON value for a message: its text, cut after 60 characters ("...").
std::string brief_json(const nlohmann::json& value);

/// Whether `text` is valid UTF-8 (no overlong forms, surrogates or code points past U+10FFFF).
bool is_utf8(std::string_view text);
/// `text` as UTF-8: unchanged when it is UTF-8, else read as Windows-1252 (Latin-1 with the
/// printable 0x80-0x9F of Windows), the encoding spreadsheets on Windows save "CSV" in.
std::string as_utf8(std::string_view text);

/// How messages name a path: "stdin" for "-", else 'path'.
std::string source_name(const std::string& path);

/// The whole text of the file at `path`, or of stdin for "-". Throws Error(usage) naming the
/// path, what it should hold (`expected`) and the fix: a file that cannot be opened, a
/// directory, or one larger than max_input_bytes (it is never read further, so an endless
/// device such as /dev/zero ends too).
std::string read_text(const std::string& path, std::string_view expected);

/// JSON as the programs print it: indented by 2, with a line end. Text that is not UTF-8 (a
/// path from the command line) is written with U+FFFD in its place instead of failing.
template <class Json>
std::string pretty_json(const Json& value) {
  return value.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

/// The members of a JSON array's text, each as written (a top-level '[', members split at its
/// own commas, then ']' and nothing but blanks); none where the text is no such array. Each
/// member is then parsed on its own, so that one that nests too deep is refused alone.
std::optional<std::vector<std::string_view>> array_members(std::string_view text);

/// Parses JSON text. Nesting deeper than max_json_depth and a key given twice in one object are refused. A number beyond the range of a double (1e400) becomes a string of its own
/// text, so that the reader of that one member reports it and the others are kept. Throws
/// Error(usage) naming `source` and what it should hold for text that is not JSON.
nlohmann::json parse_json(const std::string& text, const std::string& source, std::string_view expected);

}  // namespace trebuchet
