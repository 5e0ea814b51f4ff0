#include "trebuchet/app/input/text_input.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <vector>

#include "trebuchet/error.hpp"

namespace trebuchet {
namespace {

// Reads at most max_input_bytes + 1 bytes: one more than allowed tells that the input is too large.
std::string read_bounded(std::istream& in) {
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= max_input_bytes && in.read(chunk, sizeof chunk).gcount() > 0) text.append(chunk, static_cast<std::size_t>(in.gcount()));
  return text;
}

// Where a JSON number token starts at text[i] (outside strings): its end, by the JSON grammar.
std::size_t number_end(const std::string& text, std::size_t i) {
  auto digits = [&](std::size_t k) {
    while (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) ++k;
    return k;
  };
  if (text[i] == '-') ++i;
  i = digits(i);
  if (i < text.size() && text[i] == '.') i = digits(i + 1);
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    i = digits(i);
  }
  return i;
}

// The text with every number literal that overflows a double quoted, so that it parses.
std::string quote_huge_numbers(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  bool in_string = false;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < text.size())
        out += text[++i];
      else if (c == '"')
        in_string = false;
      ++i;
    } else if (c == '"') {
      in_string = true;
      out += c;
      ++i;
    } else if (c == '-' || std::isdigit(static_cast<unsigned char>(c))) {
      const std::size_t end = number_end(text, i);
      const std::string token = text.substr(i, end - i);
      const bool huge = end > i + 1 && std::isinf(std::strtod(token.c_str(), nullptr));
      out += huge ? "\"" + token + "\"" : token;
      i = std::max(end, i + 1);
    } else {
      out += c;
      ++i;
    }
  }
  return out;
}

// Walks `text` from `from`, outside its strings: calls at(i, c, depth) for each bracket and comma
// c, with `depth` the brackets open before it is read (a closing one counts its own), and stops
// where at returns false.
template <class At>
void walk_structure(std::string_view text, std::size_t from, At at) {
  std::size_t depth = 0;
  bool in_string = false;
  for (std::size_t i = from; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{' || c == ']' || c == '}' || c == ',') {
      if (!at(i, c, depth)) return;
      if (c == '[' || c == '{')
        ++depth;
      else if (c != ',' && depth > 0)
        --depth;
    }
  }
}

}  // namespace

std::size_t json_depth(std::string_view text) {
  std::size_t deepest = 0;
  walk_structure(text, 0, [&](std::size_t, char c, std::size_t depth) {
    if (c == '[' || c == '{') deepest = std::max(deepest, depth + 1);
    return deepest <= max_json_depth;  // past it, enough to refuse; the rest is not read
  });
  return deepest;
}

std::optional<std::vector<std::string_view>> array_members(std::string_view text) {
  const std::size_t open = text.find_first_not_of(" \t\r\n", text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0);
  if (open == std::string_view::npos || text[open] != '[') return std::nullopt;
  std::vector<std::string_view> members;
  std::size_t begin = open + 1;
  std::optional<std::vector<std::string_view>> out;
  walk_structure(text, open + 1, [&](std::size_t i, char c, std::size_t depth) {
    if (depth > 0 || c == '[' || c == '{' || c == '}') return true;  // inside a member
    const std::string_view member = text.substr(begin, i - begin);
    if (member.find_first_not_of(" \t\r\n") != std::string_view::npos)
      members.push_back(member);
    else if (c == ',' || !members.empty())
      return false;  // an empty member, or a trailing comma
    if (c == ']') {
      if (text.find_first_not_of(" \t\r\n", i + 1) == std::string_view::npos) out = members;
      return false;
    }
    begin = i + 1;
    return true;
  });
  return out;
}

namespace {

// A SAX reader that finds the first key given twice in one object: nlohmann keeps the last
// silently, and a design's "L1" given twice is a mistake to name, not to guess at.
class DuplicateKeys : public nlohmann::json_sax<nlohmann::json> {
 public:
  std::optional<std::string> found;
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override {
    keys_.emplace_back();
    return true;
  }
  bool key(string_t& key) override {
    if (!keys_.back().insert(key).second) found = key;
    return !found;  // stop at the first
  }
  bool end_object() override {
    keys_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  std::vector<std::set<std::string>> keys_;
};

}  // namespace

std::optional<std::string> duplicate_key(std::string_view text) {
  DuplicateKeys reader;
  nlohmann::json::sax_parse(text, &reader, nlohmann::json::input_format_t::json, false);
  return reader.found;
}

std::string brief_json(const nlohmann::json& value) {
  constexpr std::size_t shown = 60;
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() > shown) text = text.substr(0, shown) + "...";
  return text;
}

bool is_utf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    // The length of the sequence a lead byte starts, and the lowest code point it may encode
    // (an overlong form is invalid); 0: not a lead byte.
    const std::size_t length = byte < 0x80 ? 1 : (byte >> 5) == 0x6 ? 2 : (byte >> 4) == 0xE ? 3 : (byte >> 3) == 0x1E ? 4 : 0;
    if (length == 0 || i + length > text.size()) return false;
    char32_t code = length == 1 ? byte : length == 2 ? byte & 0x1F : length == 3 ? byte & 0x0F : byte & 0x07;
    for (std::size_t k = 1; k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      if ((next >> 6) != 0x2) return false;
      code = (code << 6) | (next & 0x3F);
    }
    const char32_t lowest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < lowest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
    i += length;
  }
  return true;
}

std::string as_utf8(std::string_view text) {
  if (is_utf8(text)) return std::string(text);
  // Windows-1252 where it differs from Latin-1 (0x80 to 0x9F); its five unused bytes become U+FFFD.
  static const char16_t windows_1252[32] = {0x20AC, 0xFFFD, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
                                            0x2039, 0x0152, 0xFFFD, 0x017D, 0xFFFD, 0xFFFD, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
                                            0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0xFFFD, 0x017E, 0x0178};
  std::string out;
  out.reserve(text.size() + text.size() / 4);
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    const char32_t code = byte >= 0x80 && byte < 0xA0 ? windows_1252[byte - 0x80] : byte;
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }
  return out;
}

std::string source_name(const std::string& path) { return path == "-" ? std::string("stdin") : "'" + path + "'"; }

std::string read_text(const std::string& path, std::string_view expected) {
  const std::string fix = "; give " + std::string(expected);
  std::string text;
  if (path == "-") {
    text = read_bounded(std::cin);
  } else {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw Error(ErrorKind::usage, source_name(path) + " is a directory" + fix);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error(ErrorKind::usage, "cannot read " + source_name(path) + fix);
    text = read_bounded(file);
  }
  if (text.size() > max_input_bytes)
    throw Error(ErrorKind::usage, source_name(path) + " is larger than " + std::to_string(max_input_bytes >> 20) + " MiB" + fix);
  return text;
}

nlohmann::json parse_json(const std::string& text, const std::string& source, std::string_view expected) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw Error(ErrorKind::usage, source + " is empty; give " + std::string(expected));
  if (json_depth(text) > max_json_depth)
    throw Error(ErrorKind::usage,
                source + " nests arrays or objects more than " + std::to_string(max_json_depth) + " levels deep; give " + std::string(expected));
  const std::string quoted = quote_huge_numbers(text);  // so that no number stops the search for keys either
  if (const auto key = duplicate_key(quoted)) throw Error(ErrorKind::usage, source + " gives the key \"" + *key + "\" twice in one object; keep one");
  try {
    return nlohmann::json::parse(quoted);
  } catch (const nlohmann::json::exception& e) {
    throw Error(ErrorKind::usage, source + " is not valid JSON (" + e.what() + "); give " + std::string(expected));
  }
}

}  // namespace trebuchet
