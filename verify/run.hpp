// trebuchet-verify's subcommands, one file each: each takes the parsed options, calls the
// library and prints; it returns the exit code (docs/exit_codes.md) or throws Error.
#pragma once

#include "options.hpp"

namespace trebuchet::verify {

int run_shot(const Options& options, bool fit);  // shot.cpp: shot and fit
int run_monte_carlo(const Options& options, bool complete);  // monte_carlo.cpp: a value given as a range or a spread
int run_complete(const Options& options);  // complete.cpp
int run_calibrate(const Options& options);  // calibrate.cpp
int run_optimize(const Options& options);  // tables.cpp
int run_derive_table(const Options& options);  // tables.cpp
int run_merge(const Options& options);  // tables.cpp
int run_compare(const Options& options);  // compare.cpp
int run_contest(const Options& options);  // contest.cpp

/// Whether the flags give an engine's value or part, which a design file gives instead (shot.cpp);
/// the material, the capacity and the release are settings of a file's designs too.
bool has_engine_flags(const DesignValues& design);

}  // namespace trebuchet::verify
