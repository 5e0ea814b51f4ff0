#include "paper_rounding.hpp"

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <stdexcept>
#include <vector>

#include "trebuchet/app/records/table_json.hpp"

namespace trebuchet::testing {
namespace {

double half_unit_of(const std::string& number_text) {
  const std::string mantissa = number_text.substr(0, number_text.find_first_of("eE"));
  const auto dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  int exponent = 0;
  if (const auto e = number_text.find_first_of("eE"); e != std::string::npos) exponent = std::stoi(number_text.substr(e + 1));
  return 0.5 * std::pow(10.0, exponent - decimals);
}

void collect_number_paths(const nlohmann::ordered_json& node, const std::string& pointer, std::vector<std::string>& paths) {
  if (node.is_object())
    for (const auto& [key, value] : node.items()) collect_number_paths(value, pointer + "/" + key, paths);
  else if (node.is_array())
    for (std::size_t i = 0; i < node.size(); ++i) collect_number_paths(node[i], pointer + "/" + std::to_string(i), paths);
  else if (node.is_number())
    paths.push_back(pointer);
}

// JSON pointer of every number in data/cpnc.json -> half a unit of its last printed digit.
// Numbers are matched to their text in document order (ordered_json keeps that order),
// after the strings are blanked out so that digits inside them do not count.
const std::map<std::string, double>& half_units() {
  static const std::map<std::string, double> table = [] {
    const std::string text(builtin_scaling_table_json());
    std::vector<std::string> paths;
    collect_number_paths(nlohmann::ordered_json::parse(text), "", paths);
    const std::string without_strings = std::regex_replace(text, std::regex(R"("([^"\\]|\\.)*")"), "\"\"");
    const std::regex number(R"(-?\d+(\.\d+)?([eE][+-]?\d+)?)");
    std::map<std::string, double> result;
    std::size_t k = 0;
    for (auto it = std::sregex_iterator(without_strings.begin(), without_strings.end(), number); it != std::sregex_iterator(); ++it, ++k)
      result[paths.at(k)] = half_unit_of(it->str());
    if (k != paths.size()) throw std::logic_error("number count mismatch in data/cpnc.json");
    return result;
  }();
  return table;
}

}  // namespace

Printed printed(const std::string& text) { return {std::stod(text), half_unit_of(text)}; }

double constant_half_unit(const std::string& json_pointer) { return half_units().at(json_pointer); }

double table_rounding_effect(double theta_i_deg, double F, const std::function<double(const ScalingTable&)>& result) {
  const ScalingTable& nominal = builtin_scaling_table();
  const double base = result(nominal);
  std::size_t b = 0;
  while (b < nominal.blocks.size() && nominal.find_block(theta_i_deg, F) != &nominal.blocks[b]) ++b;
  const std::string block_pointer = "/blocks/" + std::to_string(b);
  double effect = 0;
  for (Param param : all_params) {
    const std::string name(param_name(param));
    {
      ScalingTable table = nominal;
      table.blocks[b].Z0[index(param)] += constant_half_unit(block_pointer + "/Z0/" + name);
      effect += std::abs(result(table) - base);
    }
    for (std::size_t s = 0; s < nominal.blocks[b].segments.size(); ++s) {
      // Segments are sorted by X_min on loading, as they are written in the file.
      const std::string segment_pointer = block_pointer + "/segments/" + std::to_string(s) + "/";
      for (char which : {'a', 'p', 'q'}) {
        ScalingTable table = nominal;
        Segment& segment = table.blocks[b].segments[s];
        double& constant = which == 'a' ? segment.a[index(param)] : segment.exponents(index(param), which == 'p' ? 0 : 1);
        constant += constant_half_unit(segment_pointer + which + "/" + name);
        effect += std::abs(result(table) - base);
      }
    }
  }
  return effect;
}

}  // namespace trebuchet::testing

#include <catch2/catch.hpp>
#include <cstdio>

namespace trebuchet::testing {

void check_printed(const std::string& label, double ours, const std::string& paper_text, double extra, double scale) {
  const Printed paper = printed(paper_text);
  const double value = ours * scale;
  const double tolerance = paper.half_unit + extra * scale;
  const double difference = value - paper.value;
  std::printf("  %-34s ours %-11.5g paper %-7s diff %+9.2e  tol %8.2e (%3.0f%% used)\n", label.c_str(), value, paper_text.c_str(), difference,
              tolerance, 100 * std::abs(difference) / tolerance);
  INFO(label << ": ours " << value << ", paper " << paper_text << ", tolerance " << tolerance);
  CHECK(std::abs(difference) <= tolerance);
}

}  // namespace trebuchet::testing

namespace trebuchet::testing {

double input_rounding_effect(const std::vector<std::string>& printed_inputs, const std::function<Engine(const std::vector<double>&)>& build,
                             const std::function<double(const Engine&)>& result) {
  std::vector<double> values;
  for (const std::string& text : printed_inputs) values.push_back(printed(text).value);
  const double base = result(build(values));
  double effect = 0;
  for (std::size_t k = 0; k < values.size(); ++k) {
    std::vector<double> moved = values;
    moved[k] += printed(printed_inputs[k]).half_unit;
    effect += std::abs(result(build(moved)) - base);
  }
  return effect;
}

}  // namespace trebuchet::testing
