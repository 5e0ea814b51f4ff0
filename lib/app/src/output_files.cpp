#include "trebuchet/app/output_files.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "trebuchet/error.hpp"

namespace trebuchet {
namespace fs = std::filesystem;

PendingOutput::PendingOutput(std::string path, std::string option, bool folder)
    : path_(std::move(path)), option_(std::move(option)), folder_(folder) {
  // Beside the output, never inside it: "pictures/" is drawn in "pictures.part-<pid>".
  std::string base = path_;
  while (base.size() > 1 && base.back() == '/') base.pop_back();
  temporary_ = base + ".part-" + std::to_string(::getpid());
  std::error_code ec;
  fs::remove_all(temporary_, ec);
  if (folder_ && !fs::create_directories(temporary_, ec))
    throw Error(ErrorKind::usage, "{{" + option_ + "}}: cannot make a folder beside '" + path_ + "'; give a folder you can write to");
}

PendingOutput::~PendingOutput() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(temporary_, ec);
}

void PendingOutput::commit() {
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
    if (input.empty() || input == "-" || !fs::exists(input, ec)) continue;
    bool over = fs::exists(output, ec) && fs::equivalent(output, input, ec);
    if (folder && !over && fs::is_directory(output, ec)) {  // the pictures would be written beside the input
      const fs::path folder_path = fs::canonical(output, ec), input_path = fs::canonical(input, ec);
      over = !ec && input_path.parent_path() == folder_path;
    }
    if (over)
      throw Error(ErrorKind::usage, "{{" + option + "}}: '" + output + (folder ? "' is the folder of the input '" : "' would overwrite the input '") +
                                        input + (folder ? "'; give another folder" : "'; give the output another name"));
  }
}

}  // namespace trebuchet
