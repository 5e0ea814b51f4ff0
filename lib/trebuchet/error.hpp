// Errors the library reports to its callers. Each kind maps to one exit code of the
// command-line programs, so a script can tell a typo from an out-of-range request.
#pragma once

#include <stdexcept>
#include <string>

namespace trebuchet {

enum class ErrorKind {
  usage = 2,         ///< unknown option, malformed command line
  given_count = 3,   ///< not exactly two givens, or a pair the calculator cannot take
  bad_number = 4,    ///< not a number, not finite, or not positive
  unknown_unit = 5,  ///< unit suffix unknown, or of the wrong dimension
  out_of_range = 6,  ///< no segment of tab:CPNC covers the request (X outside, no meaningful capacity)
  data_file = 7,     ///< constants table missing, malformed or inconsistent
  batch_rows = 8,    ///< a batch finished, but some of its rows failed
  numerical = 9,     ///< the numerical method failed or lost accuracy (named in the message)
};

/// Exit code of the command-line programs for an error kind.
constexpr int exit_code(ErrorKind kind) { return static_cast<int>(kind); }

/// An error with a message that names the bad value and says how to fix it.
class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }

 private:
  ErrorKind kind_;
};

}  // namespace trebuchet
