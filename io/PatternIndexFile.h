#pragma once
// A folder of graded sewing patterns' index (scenes/patterns/index.json): one entry per
// pattern file, naming its style, the size it was cut for and that size's body. What the
// garment catalogue's pattern styles are read from (io/GarmentCatalogue.h).
//
// FILE FORMAT (what is read; other keys are ignored)
//   {"patterns": [{"style": "tshirt", "sex": "female"|"male", "size": "M", "number": 38,
//                  "stature": 1.68, "bust": 0.88, "waist": 0.72, "hips": 0.96,
//                  "file": "tshirt/tshirt-f-38_specification.json"}, ...]}
// stature and girths in metres; file relative to the index's folder.

#include <string>
#include <vector>

#include "sim/garment/SizeChart.h"

namespace figment {

struct PatternIndexEntry {
  std::string style;  // the index's style: "tshirt"
  Sex sex = Sex::Female;
  std::string size;    // the letter code: "M"
  std::string number;  // "38"
  ChartSize body;      // the body it was cut for: stature, bust, waist, hip (m)
  std::string file;    // the pattern file, its path made from the index's folder
};

// Throws std::runtime_error("<path>: <reason>") for a file that cannot be read or is not
// JSON, or "<path>: patterns[i]: <reason>" for an entry missing a key, of a sex other
// than female or male, or a dimension that is not a positive number.
std::vector<PatternIndexEntry> readPatternIndex(const std::string& path);

}  // namespace figment
