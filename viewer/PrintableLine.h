#pragma once
// A message made safe to print as one line: a file name or field value taken from bad
// input may hold line breaks or terminal control bytes.

#include <string>

namespace figment::viewer {

// `text` with every control byte (below 0x20, and 0x7f) written as an escape: "\n",
// "\r", "\t", or "\xNN". Other bytes, UTF-8 included, are kept.
std::string printableLine(const std::string& text);

}  // namespace figment::viewer
