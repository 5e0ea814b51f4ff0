#include "trebuchet/app/text_input.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "trebuchet/error.hpp"

namespace trebuchet {
namespace {

// Reads at most max_input_bytes + 1 bytes: one more than allowed tells that the input is too large.
std::string read_bounded(std::istream& in) {
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= max_input_bytes && in.read(chunk, sizeof chunk).gcount() > 0)
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
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
      if (c == '\\' && i + 1 < text.size()) out += text[++i];
      else if (c == '"') in_string = false;
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

}  // namespace

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
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw Error(ErrorKind::usage, source + " is empty; give " + std::string(expected));
  try {
    return nlohmann::json::parse(quote_huge_numbers(text));
  } catch (const nlohmann::json::exception& e) {
    throw Error(ErrorKind::usage, source + " is not valid JSON (" + e.what() + "); give " + std::string(expected));
  }
}

}  // namespace trebuchet
