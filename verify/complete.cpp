// complete: the best engine that keeps what a source attests (completion.hpp).
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/app/output/report.hpp"

namespace trebuchet::verify {

int run_complete(const Options& o) {
  if (!o.plot.empty())
    throw Error(ErrorKind::usage, "--plot draws the histogram of a Monte Carlo run; give a value as a range or a spread, or drop --plot");
  const CompletionRequest request = completion_request(o.design, settings_of(o));
  // "Could it reach that far?" wants the longest range beside the best-balanced engine.
  CompletionReport report = complete_with_longest(request, option_word);
  Completion& completion = report.completion;
  // The calculator's note and warnings speak of its options; those only it has are said to be its.
  const auto in_calculator_words = [](std::string& text) {
    std::vector<std::string> only_calculator;
    for (const char* name : {"scale", "extrapolate", "branch"})
      if (text.find("{{" + std::string(name) + "}}") != std::string::npos) only_calculator.push_back(option_word(name));
    text = with_words(text, option_word);
    if (!only_calculator.empty())
      text += " (" + join(only_calculator, " and ") + (only_calculator.size() > 1 ? " are options" : " is an option") + " of trebuchet-calc)";
  };
  in_calculator_words(completion.calculator_note);
  if (completion.calculator)
    for (std::string& warning : completion.calculator->warnings) in_calculator_words(warning);
  const Completion* alternative = report.longest ? &*report.longest : nullptr;
  const std::string& longest_note = report.longest_note;
  if (o.format == Format::json)
    std::cout << pretty_json(completion_json(completion, request.settings, alternative, longest_note));
  else
    std::cout << completion_table(completion, request.settings, o.units, alternative, longest_note);
  return exit_success;
}

}  // namespace trebuchet::verify
