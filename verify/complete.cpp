// complete: the best engine that keeps what a source attests (completion.hpp).
#include <iostream>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/app/report.hpp"

namespace trebuchet::verify {

int run_complete(const Options& o) {
  if (!o.plot.empty())
    throw Error(ErrorKind::usage, "--plot draws the histogram of a Monte Carlo run; give a value as a range or a spread, or drop --plot");
  const CompletionRequest request = completion_request(o);
  Completion completion = complete_engine(request);
  completion.calculator_note = with_words(completion.calculator_note, option_word);
  if (o.format == Format::json) std::cout << completion_json(completion, request.settings).dump(2) << "\n";
  else std::cout << completion_table(completion, request.settings);
  return exit_success;
}

}  // namespace trebuchet::verify
