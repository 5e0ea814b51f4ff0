// Outputs the user names (--series, --plot, --spreadsheet) are written whole or not at all: to a
// temporary name beside them, renamed into place once complete. A file given as input is never
// an output.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace trebuchet {

/// A file or folder being written under a temporary name beside `path` ("x.csv.part-XXXXXX",
/// unique), moved onto `path` by commit(). The folders `path` is to stand in are made when
/// missing (as mkdir -p). Destroyed without commit() (a failure), it removes what was written
/// and the folders it made, so a failed run leaves nothing behind. `option` names the output in
/// messages ("series": {{series}}). A symbolic link is written through; a device or a pipe
/// (/dev/null, a FIFO, /dev/stdout into a pipe) is written into directly, since a rename would
/// replace it; the file stdout or stderr is redirected into is refused. A folder's files may not
/// replace any of `inputs`.
class PendingOutput {
 public:
  PendingOutput(std::string path, std::string option, bool folder = false, std::vector<std::string> inputs = {});
  PendingOutput(const PendingOutput&) = delete;
  PendingOutput& operator=(const PendingOutput&) = delete;
  ~PendingOutput();
  /// Where to write meanwhile: a file's temporary name, or a temporary folder (made here).
  const std::string& temporary() const { return temporary_; }
  /// Moves the output into place: a file replaces `path`; a folder's files go into `path` (made
  /// if missing), each replacing its namesake, other files there kept. Error(usage) on failure,
  /// before any file moves when one would replace an input.
  void commit();

 private:
  std::string path_, shown_, option_, temporary_;  // shown_: the path as the user gave it
  std::string made_;  // the first of the folders made for it, none: empty
  std::vector<std::string> inputs_;
  bool folder_ = false, committed_ = false, direct_ = false;  // direct_: a device or pipe, written into
};

/// Refuses, before the work, a folder output (`option`, as PendingOutput names it) that is a file:
/// its commit would refuse it only at the end.
void refuse_file_as_folder(const std::string& folder, const std::string& option);

/// `text` written to `path` whole or not at all (PendingOutput).
void write_output_file(const std::string& path, std::string_view text, const std::string& option);

/// Refuses (Error(usage)) an output file that would overwrite one of `inputs`: the same file,
/// through any link, or for "-" the file stdin is redirected from.
void refuse_output_over_input(const std::string& output, const std::string& option, const std::vector<std::string>& inputs);

}  // namespace trebuchet
