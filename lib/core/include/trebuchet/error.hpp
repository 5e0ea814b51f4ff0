// Errors the library reports to its callers. The programs map each kind to an exit code
// (cli/exit_codes.hpp), so that a script can tell a typo from an out-of-range request.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace trebuchet {

enum class ErrorKind {
  usage,  ///< unknown option, malformed command line or input file
  given_count,  ///< not exactly two givens, or a pair the calculator cannot take
  bad_number,  ///< not a number, not finite, or not positive
  unknown_unit,  ///< unit suffix unknown, or of the wrong dimension
  out_of_range,  ///< no segment of tab:CPNC covers the request, or no engine delivers the capacity
  data_file,  ///< constants table or sweep part missing, malformed or inconsistent
  batch_rows,  ///< a batch finished, but some of its rows failed
  numerical,  ///< the numerical method failed or lost accuracy (named in the message)
};

/// `text` with each {{name}} in it written as word(name) (what Error::message does); for the
/// warnings of a result, which name settings the same way.
std::string with_words(std::string_view text, const std::function<std::string(std::string_view name)>& word);

/// An error with a message that names the bad value and says how to fix it. The core names the
/// inputs and settings it speaks of by their names in the API, in double braces: "{{L4}} = -1:
/// the sling length must be positive", "tighten {{rtol}}". what() writes each bare ("L4",
/// "rtol"); a program writes its own word for it with message(word): a flag, a CSV column, a
/// JSON key. Double braces, because text a user typed and a message quotes ('{dir}/x.json') holds
/// single braces.
class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message);
  ErrorKind kind() const { return kind_; }
  /// The message with each {{name}} written as word(name).
  std::string message(const std::function<std::string(std::string_view name)>& word) const;
  /// The message with its {{name}} references as they are: to build another message from.
  const std::string& named_message() const { return text_; }
  /// The names the message speaks of, in order.
  std::vector<std::string> names() const;

 private:
  ErrorKind kind_;
  std::string text_;
};

/// Refuses, as Error(bad_number), a value outside [lowest, highest] in `unit`: "{{g}} = 1e+308
/// m/s2 is not of ordinary size for the gravitational acceleration; give one from 1e-06 to 1e+06
/// m/s2". The windows are wide; they keep every product of inputs the physics forms finite.
void check_ordinary(double value, double lowest, double highest, std::string_view key, std::string_view unit, std::string_view what);

}  // namespace trebuchet
