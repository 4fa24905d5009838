#include "CsvFile.h"

#include "io/AtomicFile.h"

#include <fstream>
#include <iostream>

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

}  // namespace figment::bench
