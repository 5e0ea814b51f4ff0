// trebuchet-verify's options, each a row of a table: the engine's inputs (inputs.def) and the
// settings (settings.def). A subcommand takes the rows whose operations or doors name it; a
// row's flag, help and reading come from the row, and a setting that only the programs take
// (an output's format, a folder, a contest's limit) is read here, in one place.
#pragma once

#include <CLI/CLI.hpp>
#include <initializer_list>

#include "options.hpp"

namespace trebuchet::verify {

/// The table's inputs that `operation` takes, of the groups given; with `spreads`, each but a
/// capacity may be a range or a spread.
void input_options(CLI::App* app, Options& o, unsigned operation, std::initializer_list<FieldGroup> groups, bool spreads);
/// The material's rows that `operation` takes (with `beta2`, beta2 too: the subcommand sizes a beam),
/// over a design file's own.
void material_options(CLI::App* app, Options& o, unsigned operation, bool beta2);
/// The settings that the subcommand `door` takes (settings.def), in the table's order; with
/// `spreads`, the target level and the air's density and wind may be a range or a spread.
void setting_options(CLI::App* app, Options& o, Door door, bool spreads);

}  // namespace trebuchet::verify
