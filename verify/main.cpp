// trebuchet-verify: the ab-initio shot of an engine (appendix A), its capacity, efficiency,
// forces and quality at the best release, checked against a predicted capacity; and, as
// subcommands, the capacity fit, the ab-initio optimum, the completion of an attested engine
// and the re-derivation of tab:CPNC. The options are declared and parsed in options.cpp, each
// subcommand runs in a file of its own (run.hpp). Exit codes: cli/exit_codes.hpp, docs/exit_codes.md.
#include <algorithm>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/output/output_files.hpp"

namespace {

const char* const subcommand_names[] = {"shot", "fit", "optimize", "derive-table", "merge", "complete", "calibrate", "compare", "contest", "sweep"};

// `trebuchet-verify design.json` means `trebuchet-verify shot design.json`: the subcommand
// `shot` is inserted unless argv names a subcommand or asks for the overall help or the version.
std::vector<char*> with_default_subcommand(int argc, char** argv) {
  std::vector<char*> args(argv, argv + argc);
  static char shot[] = "shot";
  const std::string first = argc > 1 ? argv[1] : "";
  const bool named = std::find(std::begin(subcommand_names), std::end(subcommand_names), first) != std::end(subcommand_names);
  if (!named && first != "--help" && first != "-h" && first != "--version") args.insert(args.begin() + 1, shot);
  return args;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace trebuchet;
  using namespace trebuchet::verify;
  CLI::App app{
      "trebuchet-verify: the ab-initio physics of a swinging-counterweight trebuchet (Horsdal, appendix A).\n"
      "Values take unit suffixes (6.13m, 14.3t, 224kJ, 20ft, 220lb). Exit codes: 0 pass, 1 outside --tol, 2 bad input,\n"
      "3 numerical failure (docs/exit_codes.md). Without a subcommand, shot is meant.",
      "trebuchet-verify"};
  app.set_version_flag("--version", version_text("trebuchet-verify"));
  app.require_subcommand(1);
  Options options;
  const Subcommands sub = declare_subcommands(app, options);
  // A first word that is no subcommand, option or file but near a subcommand was meant as it
  // (`complet --Lb 10m`), not as a design file for shot.
  std::error_code unreadable;  // a name too long or a loop of links is no file either, never an abort
  if (argc > 1 && argv[1][0] != '-' && !std::filesystem::exists(argv[1], unreadable) &&
      std::find(std::begin(subcommand_names), std::end(subcommand_names), std::string(argv[1])) == std::end(subcommand_names))
    if (const std::string hint = did_you_mean(app, argv[1]); !hint.empty()) {
      std::cerr << "trebuchet-verify: '" << argv[1] << "' is no subcommand and no file" << hint << "\n";
      return exit_code(Program::verify, ErrorKind::usage);
    }
  std::vector<char*> args = with_default_subcommand(argc, argv);
  return run_program(app, Program::verify, static_cast<int>(args.size()), args.data(), [&] {
    // A word that is no file but near an option or a subcommand was meant as one: `plot`, `optimise`.
    std::error_code unreadable_input;
    if (!options.input.empty() && options.input != "-" && !std::filesystem::exists(options.input, unreadable_input))
      if (const std::string hint = did_you_mean(app, options.input); !hint.empty())
        throw Error(ErrorKind::usage, "there is no file '" + options.input + "' to read" + hint);
    // --samples and --seed set a Monte Carlo run, --claim and --draws report one: only a run with a
    // range or a spread has them (a design file's, which shot reads, or a flag's).
    if ((sub.shot->parsed() && options.input.empty()) || sub.complete->parsed())
      if (options.spreads.empty()) refuse_monte_carlo_settings(options);
    // A picture folder that is a file is refused before the shots it would draw.
    if (!options.plot.empty()) refuse_file_as_folder(options.plot, "plot");
    if (options.all_machines && !sub.contest->parsed())
      throw Error(ErrorKind::usage, "--machine all is contest's (each machine's best side by side); name one machine: " + machine_names());
    if (sub.shot->parsed()) return options.spreads.empty() || !options.input.empty() ? run_shot(options, false) : run_monte_carlo(options, false);
    if (sub.fit->parsed()) return run_shot(options, true);
    if (sub.optimize->parsed()) return run_optimize(options);
    if (sub.derive_table->parsed()) return run_derive_table(options);
    if (sub.complete->parsed()) return options.spreads.empty() ? run_complete(options) : run_monte_carlo(options, true);
    if (sub.calibrate->parsed()) return run_calibrate(options);
    if (sub.compare->parsed()) return run_compare(options);
    if (sub.contest->parsed()) return run_contest(options);
    if (sub.sweep->parsed()) return run_sweep(options);
    return run_merge(options);
  });
}
