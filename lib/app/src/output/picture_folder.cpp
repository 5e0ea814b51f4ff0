// The picture folder on disk: the files written, then gnuplot run on each script there.
#include "trebuchet/app/output/pictures.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "trebuchet/error.hpp"
#include "trebuchet/app/output/output_files.hpp"

namespace trebuchet {

namespace {

// Runs gnuplot on `script` inside `folder`; an error names what failed and how to fix it.
void run_gnuplot(const std::filesystem::path& folder, const std::string& script) {
  // What is printed so far must not be copied into the child, whose freopen would flush it again.
  std::cout.flush();
  std::fflush(stdout);
  const pid_t child = fork();
  if (child == 0) {
    if (chdir(folder.c_str()) == 0 && std::freopen("gnuplot.log", "a", stderr) && std::freopen("gnuplot.log", "a", stdout))
      execlp("gnuplot", "gnuplot", script.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    // The folder is removed with the failure, so gnuplot's last words go into the message.
    std::ifstream log(folder / "gnuplot.log");
    std::string said((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    if (said.size() > 400) said = "..." + said.substr(said.size() - 400);
    throw Error(ErrorKind::usage,
                "{{plot}}: gnuplot failed on " + script +
                    (child >= 0 && WIFEXITED(status) && WEXITSTATUS(status) == 127 ? " (gnuplot is not installed; apt-get install gnuplot-nox)"
                         : said.empty()                                            ? ""
                                                                                   : ": " + said));
  }
}

}  // namespace

void write_picture_folder(const std::string& dir, const std::vector<PictureFile>& files, const std::vector<std::string>& scripts,
                          const std::vector<std::string>& inputs) {
  // Drawn in a folder of its own beside `dir`, and moved in only when every picture is drawn.
  PendingOutput output(dir, "plot", true, inputs);
  const std::filesystem::path folder(output.temporary());
  for (const PictureFile& file : files) {
    std::ofstream out(folder / file.name);
    out << file.text;
    if (!out)
      throw Error(ErrorKind::usage,
                  "{{plot}}: cannot write " + (std::filesystem::path(dir) / file.name).string() + "; give a folder you can write to");
  }
  for (const std::string& script : scripts) run_gnuplot(folder, script);
  output.commit();
}

}  // namespace trebuchet
