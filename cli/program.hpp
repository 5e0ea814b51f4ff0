// The shared frame of the command-line programs: parse with CLI11, run, and turn every error
// into a message on stderr and the program's exit code (exit_codes.hpp). Header-only and
// outside the library, so that only the programs depend on CLI11.
#pragma once

#include <CLI/CLI.hpp>
#include <cctype>
#include <string_view>
#include <vector>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "exit_codes.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/input/units.hpp"
#include "version.hpp"
#include "trebuchet/error.hpp"

namespace trebuchet {

/// The option that sets what the library calls `name` in its messages (error.hpp): "--rtol",
/// "--theta" for theta_i_deg, "--psi-i" for psi_i_deg, "--wood-density" for wood_density.
inline std::string option_word(std::string_view name) {
  if (const InputField* field = find_field(name)) return field->flag;  // an input's flag: --theta for theta_i_deg
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
  const std::string version = build_version(), commit = build_commit();
  return program + " " + version + " (commit " + commit +
      ")\n"
      "To cite: E. Horsdal, \"The swinging counterweight trebuchet - on scaling and optimization\"; computed with trebuchet " +
      version + ", commit " + commit + ".";
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

/// " (did you mean --plot?)" for a word near a name of `app`: a word written as an option
/// (`--plto`) near an option of `app` or of the subcommands given, a bare word (`optimise`,
/// `plot`) near a subcommand or, failing that, an option. Near is the same but for the case for
/// names of one or two letters (`--r`: `--R`), one edit for names of up to 4 letters, two for
/// longer ones; empty when none is near.
inline std::string did_you_mean(const CLI::App& app, std::string_view word) {
  const bool as_option = word.rfind("--", 0) == 0;
  std::string bare(word);
  bare.erase(0, bare.find_first_not_of('-'));
  // A value ("150m", "x") is not taken for a misspelt name.
  const bool letters = std::all_of(bare.begin(), bare.end(),
                                   [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '-' || c == '_'; });
  if (bare.empty() || !letters || (!as_option && bare.size() < 3)) return "";
  std::vector<std::string> subcommands, options;
  std::vector<const CLI::App*> apps{&app};
  for (const CLI::App* sub : app.get_subcommands({})) {
    subcommands.push_back(sub->get_name());
    if (sub->parsed()) apps.push_back(sub);
  }
  for (const CLI::App* a : apps)
    for (const CLI::Option* option : a->get_options())
      for (const std::string& name : option->get_lnames()) options.push_back("--" + name);
  auto nearest = [&](const std::vector<std::string>& names) {
    std::string best;
    std::size_t best_distance = 0;
    for (const std::string& name : names) {
      std::string name_bare = name;
      name_bare.erase(0, name_bare.find_first_not_of('-'));
      const std::size_t distance = edit_distance(bare, name_bare);
      if (near_name(bare, name_bare) && (best.empty() || distance < best_distance)) best = name, best_distance = distance;
    }
    return best;
  };
  std::string best = as_option ? nearest(options) : nearest(subcommands);
  if (best.empty() && !as_option) best = nearest(options);
  return best.empty() || best == word ? "" : " (did you mean " + best + "?)";
}

/// The arguments with a unit written apart from its number joined to it: `--M 3.11 tonnes`
/// reads as `--M '3.11 tonnes'`, and `--R=400 m` as `--R='400 m'`, where the unit would
/// otherwise be taken for a file name. Nothing after a bare `--` is joined.
inline std::vector<std::string> with_units_joined(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  auto is_number = [](std::string_view text) {
    return !text.empty() &&
        (std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '.' ||
         ((text[0] == '-' || text[0] == '+') && text.size() > 1 && std::isdigit(static_cast<unsigned char>(text[1]))));
  };
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i - 1] == "--") break;
    if (!is_unit_word(args[i])) continue;
    const std::string& before = args[i - 1];
    const auto equals = before.find('=');
    const bool option_equals_number = before.rfind("--", 0) == 0 && equals != std::string::npos &&
        is_number(std::string_view(before).substr(equals + 1));
    const bool option_then_number = i >= 2 && is_number(before) && args[i - 2].rfind("--", 0) == 0 && args[i - 2] != "--" &&
        args[i - 2].find('=') == std::string::npos;
    if (option_equals_number || option_then_number) {
      args[i - 1] += " " + args[i];
      args.erase(args.begin() + static_cast<std::ptrdiff_t>(i));
      --i;
    }
  }
  return args;
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
    std::vector<std::string> args = with_units_joined(argc, argv);
    std::reverse(args.begin(), args.end());  // CLI11 takes them last first
    app.parse(std::move(args));
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
  } catch (const CLI::ExtrasError& e) {
    // "The following arguments were not expected: --plto": each with the nearest name.
    // CLI11 lists them last first (it was given the arguments reversed): put back in order.
    std::string text = e.what();
    if (const auto colon = text.find(": "); colon != std::string::npos) {
      std::vector<std::string> words;
      std::istringstream listed(text.substr(colon + 2));
      for (std::string word; listed >> word;) words.push_back(word);
      std::string said = text.substr(0, colon + 2);
      for (auto word = words.rbegin(); word != words.rend(); ++word) said += (word == words.rbegin() ? "" : " ") + *word + did_you_mean(app, *word);
      text = said;
    }
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
