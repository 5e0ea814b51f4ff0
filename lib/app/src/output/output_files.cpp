#include "trebuchet/app/output/output_files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "trebuchet/error.hpp"

namespace trebuchet {
namespace fs = std::filesystem;

namespace {

// Whether the open file `fd` is the file at `path` (through any link).
bool same_file(int fd, const std::string& path) {
  struct stat open {
  }, named{};
  return fstat(fd, &open) == 0 && stat(path.c_str(), &named) == 0 && open.st_dev == named.st_dev && open.st_ino == named.st_ino;
}

std::string not_a_folder(const std::string& option, const std::string& shown) {
  return "{{" + option + "}}: cannot write '" + shown + "': it is not a folder; give a folder you can write to";
}

}  // namespace

void refuse_file_as_folder(const std::string& folder, const std::string& option) {
  std::error_code ec;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) throw Error(ErrorKind::usage, not_a_folder(option, folder));
}

PendingOutput::PendingOutput(std::string path, std::string option, bool folder, std::vector<std::string> inputs)
    : path_(std::move(path)), shown_(path_), option_(std::move(option)), inputs_(std::move(inputs)), folder_(folder) {
  const std::string fail = "{{" + option_ + "}}: cannot write '" + shown_ + "'";
  struct stat target {};
  const bool exists = stat(path_.c_str(), &target) == 0;  // follows links
  // A device or a pipe (/dev/null, a FIFO, /dev/stdout into a pipe) is written straight into:
  // renaming onto it would replace it with a file, and it cannot hold half an output anyway.
  if (!folder_ && exists && !S_ISREG(target.st_mode) && !S_ISDIR(target.st_mode)) {
    temporary_ = path_;
    direct_ = true;
    return;
  }
  if (!folder_ && exists && (same_file(STDOUT_FILENO, path_) || same_file(STDERR_FILENO, path_)))
    throw Error(ErrorKind::usage, "{{" + option_ + "}}: '" + shown_ + "' is the file the program prints to; give the output a file of its own");
  // A link is written through: the file it points at is the output, the link stays.
  if (char* resolved = exists ? realpath(path_.c_str(), nullptr) : nullptr) {
    path_ = resolved;
    std::free(resolved);
  }
  // Beside the output, never inside it ("pictures/" is drawn in "pictures.part-XXXXXX"), under a
  // name no other run can hold.
  std::string base = path_;
  while (base.size() > 1 && base.back() == '/') base.pop_back();
  // The folders it is to stand in are made, as mkdir -p makes them, and taken away again if the
  // run fails: the first missing one, with all it holds.
  const fs::path parent = fs::path(base).parent_path();
  std::error_code ec;
  if (!parent.empty() && fs::exists(parent, ec) && !fs::is_directory(parent, ec))
    throw Error(ErrorKind::usage, fail + ": '" + parent.string() + "' is a file, not a folder; give a folder you can write to");
  if (!parent.empty() && !fs::exists(parent, ec)) {
    fs::path first_missing = parent;
    while (first_missing.has_parent_path() && first_missing.parent_path() != first_missing && !fs::exists(first_missing.parent_path(), ec))
      first_missing = first_missing.parent_path();
    if (!fs::create_directories(parent, ec) || ec)
      throw Error(ErrorKind::usage,
                  fail + ": cannot make the folder '" + parent.string() + "' (" + ec.message() + "); give a folder you can write to");
    made_ = first_missing.string();
  }
  std::string name = base + ".part-XXXXXX";
  // A constructor that throws has no destructor: the folders it made go here.
  const auto refuse = [&](const std::string& message) {
    if (!made_.empty()) fs::remove_all(made_, ec);
    throw Error(ErrorKind::usage, message);
  };
  if (folder_) {
    if (!mkdtemp(name.data())) refuse(fail + ": cannot make a folder beside it; give a folder you can write to");
  } else {
    const int fd = mkstemp(name.data());
    if (fd < 0) refuse(fail + "; give a file you can write to");
    // mkstemp makes it private (0600); the output gets the mode a new file would get, or the
    // mode of the file it replaces.
    const mode_t mask = umask(0);
    umask(mask);
    struct stat replaced {};
    fchmod(fd, exists && stat(path_.c_str(), &replaced) == 0 ? (replaced.st_mode & 07777) : (0666 & ~mask));
    close(fd);
  }
  temporary_ = name;
}

PendingOutput::~PendingOutput() {
  if (committed_ || direct_) return;
  std::error_code ec;
  fs::remove_all(temporary_, ec);
  if (!made_.empty()) fs::remove_all(made_, ec);
}

void PendingOutput::commit() {
  if (direct_) return;
  std::error_code ec;
  const std::string fail = "{{" + option_ + "}}: cannot write '" + shown_ + "'";
  if (!folder_) {
    fs::rename(temporary_, path_, ec);
    if (ec) throw Error(ErrorKind::usage, fail + " (" + ec.message() + "); give a file you can write to");
    committed_ = true;
    return;
  }
  fs::create_directories(path_, ec);
  if (!fs::is_directory(path_, ec)) throw Error(ErrorKind::usage, not_a_folder(option_, shown_));
  // Every file is checked before any moves: one that would replace an input stops them all.
  std::vector<fs::path> names;
  for (fs::directory_iterator it(temporary_, ec), end; !ec && it != end; it.increment(ec)) names.push_back(it->path().filename());
  if (ec) throw Error(ErrorKind::usage, fail + " (" + ec.message() + "); give a folder you can write to");
  for (const fs::path& name : names)
    for (const std::string& input : inputs_)
      if (input != "-" && !input.empty() && fs::exists(fs::path(path_) / name, ec) && fs::equivalent(fs::path(path_) / name, input, ec))
        throw Error(
            ErrorKind::usage,
            "{{" + option_ + "}}: '" + (fs::path(shown_) / name).string() + "' would overwrite the input '" + input + "'; give another folder");
  for (const fs::path& name : names) {
    fs::rename(fs::path(temporary_) / name, fs::path(path_) / name, ec);
    if (ec) throw Error(ErrorKind::usage, fail + " (" + ec.message() + "); give a folder you can write to");
  }
  fs::remove_all(temporary_, ec);
  committed_ = true;
}

void write_output_file(const std::string& path, std::string_view text, const std::string& option) {
  PendingOutput output(path, option);
  std::ofstream file(output.temporary(), std::ios::binary);
  file.write(text.data(), static_cast<std::streamsize>(text.size()));
  file.close();
  if (!file) throw Error(ErrorKind::usage, "{{" + option + "}}: cannot write '" + path + "'; give a file you can write to");
  output.commit();
}

void refuse_output_over_input(const std::string& output, const std::string& option, const std::vector<std::string>& inputs) {
  std::error_code ec;
  for (const std::string& input : inputs) {
    if (input == "-") {  // stdin redirected from a file: that file is the input
      if (same_file(STDIN_FILENO, output))
        throw Error(ErrorKind::usage,
                    "{{" + option + "}}: '" + output + "' would overwrite the input, which stdin reads; give the output another name");
      continue;
    }
    if (!input.empty() && fs::exists(input, ec) && fs::exists(output, ec) && fs::equivalent(output, input, ec))
      throw Error(ErrorKind::usage, "{{" + option + "}}: '" + output + "' would overwrite the input '" + input + "'; give the output another name");
  }
}

}  // namespace trebuchet
