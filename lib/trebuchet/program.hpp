// The shared frame of the command-line programs: parse with CLI11, run, and turn every error
// into a message on stderr and the program's exit code. Header-only, so that only the
// programs, not the library, depend on CLI11.
#pragma once

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "trebuchet/error.hpp"

namespace trebuchet {

/// Parses argv into `app`, then returns run(); --help prints and exits 0. A parse error exits
/// with `usage_code`, an Error with exit_for(error); both are printed as "program: message".
template <class Run, class ExitFor>
int run_program(CLI::App& app, int argc, char** argv, int usage_code, Run run, ExitFor exit_for) {
  const std::string name = app.get_name();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::ParseError& e) {
    std::cerr << name << ": " << e.what() << "; see " << name << " --help\n";
    return usage_code;
  }
  try {
    return run();
  } catch (const Error& e) {
    std::cerr << name << ": " << e.what() << "\n";
    return exit_for(e);
  }
}

}  // namespace trebuchet
