#include "trebuchet/app/table_json.hpp"
#include "paper_rounding.hpp"
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
#include <cmath>
#include "trebuchet/app/table_json.hpp"
#include <map>
#include "trebuchet/app/table_json.hpp"
#include <nlohmann/json.hpp>
#include "trebuchet/app/table_json.hpp"
#include <regex>
#include "trebuchet/app/table_json.hpp"
#include <stdexcept>
#include "trebuchet/app/table_json.hpp"
#include <vector>
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
namespace trebuchet::testing {
#include "trebuchet/app/table_json.hpp"
namespace {
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
double half_unit_of(const std::string& number_text) {
#include "trebuchet/app/table_json.hpp"
  const std::string mantissa = number_text.substr(0, number_text.find_first_of("eE"));
#include "trebuchet/app/table_json.hpp"
  const auto dot = mantissa.find('.');
#include "trebuchet/app/table_json.hpp"
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
#include "trebuchet/app/table_json.hpp"
  int exponent = 0;
#include "trebuchet/app/table_json.hpp"
  if (const auto e = number_text.find_first_of("eE"); e != std::string::npos) exponent = std::stoi(number_text.substr(e + 1));
#include "trebuchet/app/table_json.hpp"
  return 0.5 * std::pow(10.0, exponent - decimals);
#include "trebuchet/app/table_json.hpp"
}
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
void collect_number_paths(const nlohmann::ordered_json& node, const std::string& pointer, std::vector<std::string>& paths) {
#include "trebuchet/app/table_json.hpp"
  if (node.is_object())
#include "trebuchet/app/table_json.hpp"
    for (const auto& [key, value] : node.items()) collect_number_paths(value, pointer + "/" + key, paths);
#include "trebuchet/app/table_json.hpp"
  else if (node.is_array())
#include "trebuchet/app/table_json.hpp"
    for (std::size_t i = 0; i < node.size(); ++i) collect_number_paths(node[i], pointer + "/" + std::to_string(i), paths);
#include "trebuchet/app/table_json.hpp"
  else if (node.is_number())
#include "trebuchet/app/table_json.hpp"
    paths.push_back(pointer);
#include "trebuchet/app/table_json.hpp"
}
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
// JSON pointer of every number in data/cpnc.json -> half a unit of its last printed digit.
#include "trebuchet/app/table_json.hpp"
// Numbers are matched to their text in document order (ordered_json keeps that order),
#include "trebuchet/app/table_json.hpp"
// after the strings are blanked out so that digits inside them do not count.
#include "trebuchet/app/table_json.hpp"
const std::map<std::string, double>& half_units() {
#include "trebuchet/app/table_json.hpp"
  static const std::map<std::string, double> table = [] {
#include "trebuchet/app/table_json.hpp"
    const std::string text(builtin_scaling_table_json());
#include "trebuchet/app/table_json.hpp"
    std::vector<std::string> paths;
#include "trebuchet/app/table_json.hpp"
    collect_number_paths(nlohmann::ordered_json::parse(text), "", paths);
#include "trebuchet/app/table_json.hpp"
    const std::string without_strings = std::regex_replace(text, std::regex(R"("([^"\\]|\\.)*")"), "\"\"");
#include "trebuchet/app/table_json.hpp"
    const std::regex number(R"(-?\d+(\.\d+)?([eE][+-]?\d+)?)");
#include "trebuchet/app/table_json.hpp"
    std::map<std::string, double> result;
#include "trebuchet/app/table_json.hpp"
    std::size_t k = 0;
#include "trebuchet/app/table_json.hpp"
    for (auto it = std::sregex_iterator(without_strings.begin(), without_strings.end(), number);
#include "trebuchet/app/table_json.hpp"
         it != std::sregex_iterator(); ++it, ++k)
#include "trebuchet/app/table_json.hpp"
      result[paths.at(k)] = half_unit_of(it->str());
#include "trebuchet/app/table_json.hpp"
    if (k != paths.size()) throw std::logic_error("number count mismatch in data/cpnc.json");
#include "trebuchet/app/table_json.hpp"
    return result;
#include "trebuchet/app/table_json.hpp"
  }();
#include "trebuchet/app/table_json.hpp"
  return table;
#include "trebuchet/app/table_json.hpp"
}
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
}  // namespace
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
Printed printed(const std::string& text) { return {std::stod(text), half_unit_of(text)}; }
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
double constant_half_unit(const std::string& json_pointer) { return half_units().at(json_pointer); }
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
double table_rounding_effect(double theta_i_deg, double F, const std::function<double(const ScalingTable&)>& result) {
#include "trebuchet/app/table_json.hpp"
  const ScalingTable& nominal = builtin_scaling_table();
#include "trebuchet/app/table_json.hpp"
  const double base = result(nominal);
#include "trebuchet/app/table_json.hpp"
  std::size_t b = 0;
#include "trebuchet/app/table_json.hpp"
  while (b < nominal.blocks.size() && nominal.find_block(theta_i_deg, F) != &nominal.blocks[b]) ++b;
#include "trebuchet/app/table_json.hpp"
  const std::string block_pointer = "/blocks/" + std::to_string(b);
#include "trebuchet/app/table_json.hpp"
  double effect = 0;
#include "trebuchet/app/table_json.hpp"
  for (Param param : all_params) {
#include "trebuchet/app/table_json.hpp"
    const std::string name(param_name(param));
#include "trebuchet/app/table_json.hpp"
    {
#include "trebuchet/app/table_json.hpp"
      ScalingTable table = nominal;
#include "trebuchet/app/table_json.hpp"
      table.blocks[b].Z0[index(param)] += constant_half_unit(block_pointer + "/Z0/" + name);
#include "trebuchet/app/table_json.hpp"
      effect += std::abs(result(table) - base);
#include "trebuchet/app/table_json.hpp"
    }
#include "trebuchet/app/table_json.hpp"
    for (std::size_t s = 0; s < nominal.blocks[b].segments.size(); ++s) {
#include "trebuchet/app/table_json.hpp"
      // Segments are sorted by X_min on loading, as they are written in the file.
#include "trebuchet/app/table_json.hpp"
      const std::string segment_pointer = block_pointer + "/segments/" + std::to_string(s) + "/";
#include "trebuchet/app/table_json.hpp"
      for (char which : {'a', 'p', 'q'}) {
#include "trebuchet/app/table_json.hpp"
        ScalingTable table = nominal;
#include "trebuchet/app/table_json.hpp"
        Segment& segment = table.blocks[b].segments[s];
#include "trebuchet/app/table_json.hpp"
        double& constant = which == 'a' ? segment.a[index(param)] : segment.exponents(index(param), which == 'p' ? 0 : 1);
#include "trebuchet/app/table_json.hpp"
        constant += constant_half_unit(segment_pointer + which + "/" + name);
#include "trebuchet/app/table_json.hpp"
        effect += std::abs(result(table) - base);
#include "trebuchet/app/table_json.hpp"
      }
#include "trebuchet/app/table_json.hpp"
    }
#include "trebuchet/app/table_json.hpp"
  }
#include "trebuchet/app/table_json.hpp"
  return effect;
#include "trebuchet/app/table_json.hpp"
}
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
}  // namespace trebuchet::testing
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
#include <catch2/catch.hpp>
#include "trebuchet/app/table_json.hpp"
#include <cstdio>
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
namespace trebuchet::testing {
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
void check_printed(const std::string& label, double ours, const std::string& paper_text, double extra, double scale) {
#include "trebuchet/app/table_json.hpp"
  const Printed paper = printed(paper_text);
#include "trebuchet/app/table_json.hpp"
  const double value = ours * scale;
#include "trebuchet/app/table_json.hpp"
  const double tolerance = paper.half_unit + extra * scale;
#include "trebuchet/app/table_json.hpp"
  const double difference = value - paper.value;
#include "trebuchet/app/table_json.hpp"
  std::printf("  %-34s ours %-11.5g paper %-7s diff %+9.2e  tol %8.2e (%3.0f%% used)\n", label.c_str(), value,
#include "trebuchet/app/table_json.hpp"
              paper_text.c_str(), difference, tolerance, 100 * std::abs(difference) / tolerance);
#include "trebuchet/app/table_json.hpp"
  INFO(label << ": ours " << value << ", paper " << paper_text << ", tolerance " << tolerance);
#include "trebuchet/app/table_json.hpp"
  CHECK(std::abs(difference) <= tolerance);
#include "trebuchet/app/table_json.hpp"
}
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
}  // namespace trebuchet::testing
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
namespace trebuchet::testing {
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
double input_rounding_effect(const std::vector<std::string>& printed_inputs,
#include "trebuchet/app/table_json.hpp"
                             const std::function<Engine(const std::vector<double>&)>& build,
#include "trebuchet/app/table_json.hpp"
                             const std::function<double(const Engine&)>& result) {
#include "trebuchet/app/table_json.hpp"
  std::vector<double> values;
#include "trebuchet/app/table_json.hpp"
  for (const std::string& text : printed_inputs) values.push_back(printed(text).value);
#include "trebuchet/app/table_json.hpp"
  const double base = result(build(values));
#include "trebuchet/app/table_json.hpp"
  double effect = 0;
#include "trebuchet/app/table_json.hpp"
  for (std::size_t k = 0; k < values.size(); ++k) {
#include "trebuchet/app/table_json.hpp"
    std::vector<double> moved = values;
#include "trebuchet/app/table_json.hpp"
    moved[k] += printed(printed_inputs[k]).half_unit;
#include "trebuchet/app/table_json.hpp"
    effect += std::abs(result(build(moved)) - base);
#include "trebuchet/app/table_json.hpp"
  }
#include "trebuchet/app/table_json.hpp"
  return effect;
#include "trebuchet/app/table_json.hpp"
}
#include "trebuchet/app/table_json.hpp"

#include "trebuchet/app/table_json.hpp"
}  // namespace trebuchet::testing
