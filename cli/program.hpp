// The shared frame of the command-line programs: parse with CLI11, run, and turn every error
// into a message on stderr and the program's exit code (exit_codes.hpp). Header-only and
// outside the library, so that only the programs depend on CLI11.
#pragma once

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <functional>
#include <algorithm>
#include <iostream>
#include <string>

#include "exit_codes.hpp"
#include "trebuchet/error.hpp"

namespace trebuchet {

/// The option that sets what the library calls `name` in its messages (error.hpp): "--rtol",
/// "--theta" for theta_i_deg, "--psi-i" for psi_i_deg, "--wood-density" for wood_density.
inline std::string option_word(std::string_view name) {
  if (name == "theta_i_deg") return "--theta";
  if (name == "psi_i_deg") return "--psi-i";
  std::string option = "--" + std::string(name);
  std::replace(option.begin(), option.end(), '_', '-');
  return option;
}

/// A progress bar on stderr, "[####    ] 3/8 X points", drawn only when stderr is a terminal
/// (pipes and logs stay clean); empty otherwise.
inline std::function<void(int, int)> progress_bar(std::string what) {
  if (!isatty(STDERR_FILENO)) return {};
  return [what](int done, int total) {
    const int width = 30, filled = width * done / total;
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] " << done << "/" << total << " " << what
              << (done == total ? "\n" : "") << std::flush;
  };
}

/// The first option of `app` or its parsed subcommands that was given an empty value
/// (`--R ''`), or nullptr: an empty value is a mistake, never "not given".
inline const CLI::Option* option_with_empty_value(const CLI::App& app) {
  for (const CLI::Option* option : app.get_options())
    for (const std::string& value : option->results())
      if (value.empty()) return option;
  for (const CLI::App* sub : app.get_subcommands())
    if (const CLI::Option* option = option_with_empty_value(*sub)) return option;
  return nullptr;
}

/// Parses argv into `app`, then returns run(); --help prints and exits 0. A parse error exits
/// with the code of ErrorKind::usage, an Error with that of its kind; both are printed as
/// "program: message".
template <class Run>
int run_program(CLI::App& app, Program program, int argc, char** argv, Run run) {
  const std::string name = app.get_name();
  // The programs write through std::cout and std::cerr only: unsynchronised with C's stdio,
  // they buffer output themselves (a large batch writes ~10^7 bytes).
  std::ios::sync_with_stdio(false);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return exit_success;
  } catch (const CLI::ParseError& e) {
    std::cerr << name << ": " << e.what() << "; see " << name << " --help\n";
    return exit_code(program, ErrorKind::usage);
  } catch (const Error& e) {  // an option's value, parsed as it is read
    std::cerr << name << ": " << e.message(option_word) << "\n";
    return exit_code(program, e.kind());
  }
  if (const CLI::Option* empty = option_with_empty_value(app)) {
    std::cerr << name << ": " << empty->get_name() << " was given an empty value; give a value after it, or leave it out\n";
    return exit_code(program, ErrorKind::usage);
  }
  try {
    return run();
  } catch (const Error& e) {
    std::cerr << name << ": " << e.message(option_word) << "\n";
    return exit_code(program, e.kind());
  }
}

}  // namespace trebuchet
