// Errors the library reports to its callers. The programs map each kind to an exit code
// (cli/exit_codes.hpp), so that a script can tell a typo from an out-of-range request.
#pragma once

#include <stdexcept>
#include <string>

namespace trebuchet {

enum class ErrorKind {
  usage,         ///< unknown option, malformed command line or input file
  given_count,   ///< not exactly two givens, or a pair the calculator cannot take
  bad_number,    ///< not a number, not finite, or not positive
  unknown_unit,  ///< unit suffix unknown, or of the wrong dimension
  out_of_range,  ///< no segment of tab:CPNC covers the request, or no engine delivers the capacity
  data_file,     ///< constants table or sweep part missing, malformed or inconsistent
  batch_rows,    ///< a batch finished, but some of its rows failed
  numerical,     ///< the numerical method failed or lost accuracy (named in the message)
};

/// An error with a message that names the bad value and says how to fix it.
class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }

 private:
  ErrorKind kind_;
};

}  // namespace trebuchet
