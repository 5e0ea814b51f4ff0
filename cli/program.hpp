// The shared frame of the command-line programs: parse with CLI11, run, and turn every error
// into a message on stderr and the program's exit code (exit_codes.hpp). Header-only and
// outside the library, so that only the programs depend on CLI11.
#pragma once

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <string>

#include "exit_codes.hpp"
#include "trebuchet_version.hpp"
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

/// Progress of long work on stderr: "[#########      ] 412/1000 samples, 130/s, 5 s left", or
/// without a total (0) "41200 rows, 30000/s". Drawn only when stderr is a terminal (pipes and
/// logs stay clean), once the work has run for half a second, at most five times a second;
/// empty otherwise. Callable from any thread, one at a time (for_each_index's progress).
inline std::function<void(std::size_t, std::size_t)> progress_bar(std::string what) {
  if (!isatty(STDERR_FILENO)) return {};
  using Clock = std::chrono::steady_clock;
  struct State {
    Clock::time_point start = Clock::now(), last{};
    bool drawn = false;
  };
  auto state = std::make_shared<State>();
  return [what, state](std::size_t done, std::size_t total) {
    const Clock::time_point now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - state->start).count();
    const bool finished = total > 0 && done == total;
    if (finished ? !state->drawn : (elapsed < 0.5 || now - state->last < std::chrono::milliseconds(200))) return;
    state->last = now, state->drawn = true;
    const double rate = done / std::max(elapsed, 1e-9);
    char speed[64];
    std::snprintf(speed, sizeof speed, "%.*f/s", rate >= 10 ? 0 : 1, rate);
    std::string line = "\r";
    if (total > 0) {
      const std::size_t width = 30, filled = width * done / total;
      line += "[" + std::string(filled, '#') + std::string(width - filled, ' ') + "] " + std::to_string(done) + "/" + std::to_string(total);
    } else {
      line += std::to_string(done);
    }
    line += " " + what + ", " + speed;
    if (total > 0 && !finished && rate > 0) line += ", " + std::to_string(static_cast<long>((total - done) / rate + 0.5)) + " s left";
    line += finished ? "\n" : "   ";
    std::cerr << line << std::flush;
  };
}

/// What precedes a message on stderr: on a terminal, a clearing of the line, where a progress
/// bar may stand unfinished.
inline const char* message_start() { return isatty(STDERR_FILENO) ? "\r\033[K" : ""; }

/// What --version prints: the program, its version and the commit it is built from, and how
/// to cite it with the paper whose physics and tables it implements.
inline std::string version_text(const std::string& program) {
  return program + " " TREBUCHET_VERSION " (commit " TREBUCHET_COMMIT ")\n"
         "To cite: E. Horsdal, \"The swinging counterweight trebuchet - on scaling and optimization\"; computed with trebuchet " TREBUCHET_VERSION
         ", commit " TREBUCHET_COMMIT ".";
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
  } catch (const CLI::CallForVersion& version) {
    std::cout << version.what() << "\n";
    return exit_success;
  } catch (const CLI::ArgumentMismatch& e) {
    // CLI11 says "--R: At Most 1 required but received 2" for a flag given twice.
    const std::string text = e.what(), twice = ": At Most 1 required but received ";
    if (const auto at = text.find(twice); at != std::string::npos)
      std::cerr << name << ": " << text.substr(0, at) << " was given " << text.substr(at + twice.size()) << " times; give it once\n";
    else
      std::cerr << name << ": " << text << "; see " << name << " --help\n";
    return exit_code(program, ErrorKind::usage);
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
    std::cerr << message_start() << name << ": " << e.message(option_word) << "\n";
    return exit_code(program, e.kind());
  }
}

}  // namespace trebuchet
