// The exit codes of both programs, in one table (docs/exit_codes.md). The calculator gives
// each error kind a code of its own; the verifier separates only what a script acts on: a
// capacity outside the tolerance, bad input, and a numerical failure.
#pragma once

#include "trebuchet/error.hpp"

namespace trebuchet {

enum class Program { calc, verify };

inline constexpr int exit_success = 0;
/// trebuchet-verify: a predicted capacity lies outside --tol.
inline constexpr int exit_outside_tolerance = 1;

/// The exit code of `program` for an error of this kind.
constexpr int exit_code(Program program, ErrorKind kind) {
  if (program == Program::verify) return kind == ErrorKind::numerical ? 3 : 2;
  switch (kind) {
    case ErrorKind::usage: return 2;
    case ErrorKind::given_count: return 3;
    case ErrorKind::bad_number: return 4;
    case ErrorKind::unknown_unit: return 5;
    case ErrorKind::out_of_range: return 6;
    case ErrorKind::data_file: return 7;
    case ErrorKind::batch_rows: return 8;
    case ErrorKind::numerical: return 9;
  }
  return 9;
}

}  // namespace trebuchet
