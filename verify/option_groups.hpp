// trebuchet-verify's options in groups, each declared once and added to the subcommands that
// take it (options.cpp): the table's inputs, the release, the integrator, the output, the
// material, the air and the Monte Carlo run. Each parses its text as CLI11 reads it.
#pragma once

#include <CLI/CLI.hpp>
#include <initializer_list>
#include <string>

#include "options.hpp"

namespace trebuchet::verify {

/// The table's inputs that `operation` takes, of the groups given; with `spreads`, each but a
/// capacity may be a range or a spread.
void input_options(CLI::App* app, Options& o, unsigned operation, std::initializer_list<FieldGroup> groups, bool spreads);
/// The design file, the engine and its capacity (input_options), --tol, --series, --series-dt, --plot.
void engine_options(CLI::App* app, Options& o, bool spreads);
/// --machine (design.hpp, MachineKind).
void machine_option(CLI::App* app, Options& o);
void target_level_option(CLI::App* app, Options& o, bool spreads);
/// --quality and --n.
void release_options(CLI::App* app, Options& o);
/// --stepper, --rtol, --atol.
void integrator_options(CLI::App* app, Options& o);
/// --units, --format (csv_too: and csv, with --digits).
void format_option(CLI::App* app, Options& o, bool csv_too);
/// --g, --youngs-modulus, --wood-density, --rupture, and with `beta2` --beta2 (sizing `what`).
void material_options(CLI::App* app, Options& o, const std::string& what, bool beta2);
/// optimize's and derive-table's --theta and --F (a block of the table).
void block_options(CLI::App* app, Options& o);
void threads_option(CLI::App* app, Options& o, const std::string& help);
/// --air and what describes it, --drag-in-sling, --range-from.
void air_options(CLI::App* app, Options& o);
/// --samples, --seed and the air: shot's and complete's.
void air_and_sampling_options(CLI::App* app, Options& o);

}  // namespace trebuchet::verify
