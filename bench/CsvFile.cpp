#include "CsvFile.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <system_error>

#include "io/AtomicFile.h"

namespace figment::bench {

bool writeCsv(const std::string& path, const std::function<std::string(std::ostream& csv)>& fill) {
  const std::string error = writeAtomically(path, [&](const std::string& temporary) -> std::string {
    std::ofstream csv(temporary);
    const std::string fillError = fill(csv);
    if (!fillError.empty()) return fillError;
    csv.close();
    return csv ? "" : path + ": cannot write the file";
  });
  if (!error.empty()) {
    std::cerr << "figment-bench: " << error << "\n";
    return false;
  }
  std::cout << path << "\n";
  return true;
}

std::string makeOutFolder(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (!error && std::filesystem::is_directory(dir, error)) return "";
  return "--out " + dir + ": not a folder, and none can be made there" + (error ? " (" + error.message() + ")" : "");
}

void chartCsv(const std::string& plotScript, const std::string& csvPath, const std::string& pngPath) {
  if (plotScript.empty() || !std::filesystem::exists(plotScript)) return;
  const std::string command = "/usr/bin/python3 '" + plotScript + "' '" + csvPath + "' '" + pngPath + "'";
  if (std::system(command.c_str()) == 0)
    std::printf("%s\n", pngPath.c_str());
  else
    std::fprintf(stderr, "figment-bench: no chart of %s (needs /usr/bin/python3 with matplotlib)\n", csvPath.c_str());
}

}  // namespace figment::bench
