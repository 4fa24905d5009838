#pragma once
// How every study writes its CSV: complete or not at all.

#include <functional>
#include <ostream>
#include <string>

namespace figment::bench {

// Writes `path` through a temporary name: `fill` writes the rows and returns "" or what
// went wrong, as a line that names its file or scene. On success prints `path` to stdout
// and returns true; otherwise prints "figment-bench: <error>" to stderr, leaves no file
// and returns false.
bool writeCsv(const std::string& path, const std::function<std::string(std::ostream& csv)>& fill);

}  // namespace figment::bench
