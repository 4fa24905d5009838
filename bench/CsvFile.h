#pragma once
// How every study writes its CSV (complete or not at all) and charts it.

#include <functional>
#include <ostream>
#include <string>

namespace figment::bench {

// Writes `path` through a temporary name: `fill` writes the rows and returns "" or what
// went wrong, as a line that names its file or scene. On success prints `path` to stdout
// and returns true; otherwise prints "figment-bench: <error>" to stderr, leaves no file
// and returns false.
bool writeCsv(const std::string& path, const std::function<std::string(std::ostream& csv)>& fill);

// Makes the study's output folder `dir` (and its parents) before the study runs, which may
// take hours: "" when it is a folder, else one line naming --out, the path and why.
std::string makeOutFolder(const std::string& dir);

// Charts `csvPath` into `pngPath` with the study's matplotlib script, when there is one
// ("" or missing: nothing happens): prints the PNG's path, or on stderr that there is no
// chart (python3 or matplotlib missing).
void chartCsv(const std::string& plotScript, const std::string& csvPath, const std::string& pngPath);

}  // namespace figment::bench
