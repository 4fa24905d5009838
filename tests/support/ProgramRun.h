#pragma once
// Running one of FIGMENT's programs from a test, as a user's shell would: its exit status,
// what it printed, and its drape cache in a folder of the test's own.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace figment::test {

// `text` as one shell word (test paths hold no single quote).
inline std::string quote(const std::string& text) {
  return std::string("'").append(text).append("'");
}

struct ProgramResult {
  int status = -1;       // the exit status; -1 when the program did not exit (a signal)
  std::string out, err;  // what it printed on stdout and stderr
};

// Runs `executable` with `arguments` (shell words) through the shell, its drape cache in
// `cache` (XDG_CACHE_HOME); stdout and stderr go through stdout.txt and stderr.txt in
// `folder`.
inline ProgramResult runProgram(const std::string& executable, const std::string& arguments,
                                const std::filesystem::path& folder, const std::filesystem::path& cache) {
  const std::string out = (folder / "stdout.txt").string(), err = (folder / "stderr.txt").string();
  const std::string command = "XDG_CACHE_HOME=" + quote(cache.string()) + " " + quote(executable) + " " + arguments +
                              " > " + quote(out) + " 2> " + quote(err);
  const int raw = std::system(command.c_str());
  const auto contents = [](const std::string& path) {
    std::stringstream text;
    text << std::ifstream(path).rdbuf();
    return text.str();
  };
  return ProgramResult{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, contents(out), contents(err)};
}

}  // namespace figment::test
