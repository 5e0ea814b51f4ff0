#include "trebuchet/app/output_files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "trebuchet/error.hpp"

namespace trebuchet {
namespace fs = std::filesystem;

PendingOutput::PendingOutput(std::string path, std::string option, bool folder)
    : path_(std::move(path)), option_(std::move(option)), folder_(folder) {
  std::error_code ec;
  // A link is written through: the file it points at is the output, the link stays.
  if (fs::is_symlink(path_, ec)) path_ = fs::weakly_canonical(path_, ec).string();
  // A device or a pipe (/dev/null, a FIFO) is written straight into: renaming onto it would
  // replace it with a file, and it cannot hold half an output anyway.
  if (!folder_ && fs::exists(path_, ec) && !fs::is_regular_file(path_, ec) && !fs::is_directory(path_, ec)) {
    temporary_ = path_;
    direct_ = true;
    return;
  }
  // Beside the output, never inside it: "pictures/" is drawn in "pictures.part-<pid>".
  std::string base = path_;
  while (base.size() > 1 && base.back() == '/') base.pop_back();
  temporary_ = base + ".part-" + std::to_string(::getpid());
  fs::remove_all(temporary_, ec);
  if (folder_ && !fs::create_directories(temporary_, ec))
    throw Error(ErrorKind::usage, "{{" + option_ + "}}: cannot make a folder beside '" + path_ + "'; give a folder you can write to");
}

PendingOutput::~PendingOutput() {
  if (committed_ || direct_) return;
  std::error_code ec;
  fs::remove_all(temporary_, ec);
}

void PendingOutput::commit() {
  if (direct_) return;
  std::error_code ec;
  const std::string fail = "{{" + option_ + "}}: cannot write '" + path_ + "'";
  if (!folder_) {
    fs::rename(temporary_, path_, ec);
    if (ec) throw Error(ErrorKind::usage, fail + " (" + ec.message() + "); give a file you can write to");
  } else {
    fs::create_directories(path_, ec);
    if (!fs::is_directory(path_)) throw Error(ErrorKind::usage, fail + ": it is not a folder; give a folder you can write to");
    for (const fs::directory_entry& entry : fs::directory_iterator(temporary_, ec)) {
      fs::rename(entry.path(), fs::path(path_) / entry.path().filename(), ec);
      if (ec) throw Error(ErrorKind::usage, fail + " (" + ec.message() + "); give a folder you can write to");
    }
    fs::remove_all(temporary_, ec);
  }
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

void refuse_output_over_input(const std::string& output, const std::string& option, const std::vector<std::string>& inputs, bool folder) {
  std::error_code ec;
  for (const std::string& input : inputs) {
    if (input == "-") {  // stdin redirected from a file: that file is the input
      struct stat in {}, out {};
      if (fstat(STDIN_FILENO, &in) == 0 && S_ISREG(in.st_mode) && stat(output.c_str(), &out) == 0 && in.st_dev == out.st_dev &&
          in.st_ino == out.st_ino)
        throw Error(ErrorKind::usage, "{{" + option + "}}: '" + output + "' would overwrite the input, which stdin reads; give the output another name");
      continue;
    }
    if (input.empty() || !fs::exists(input, ec)) continue;
    const bool same = fs::exists(output, ec) && fs::equivalent(output, input, ec);
    if (same)
      throw Error(ErrorKind::usage, "{{" + option + "}}: '" + output + "' would overwrite the input '" + input + "'; give the output another name");
    if (!folder || !fs::is_directory(output, ec)) continue;
    // The pictures would be written beside the input.
    const fs::path folder_path = fs::canonical(output, ec), input_path = fs::canonical(input, ec);
    if (!ec && input_path.parent_path() == folder_path) throw Error(ErrorKind::usage, "{{" + option + "}}: '" + output + "' is the folder of the input '" + input + "'; give another folder");
  }
}

}  // namespace trebuchet
