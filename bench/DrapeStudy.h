#pragma once
// The drape study: how long the default scene's garments take to come to rest.

#include <string>

namespace figment::bench {

struct DrapeStudyOptions {
  std::string scene = "scenes/dress.iv";
  int repeat = 3;
  std::string outDir = "bench-out";
};

// Reads the scene, re-runs every ClothEngine `repeat` times, writes DIR/drape.csv and
// prints the medians. Returns the process exit code.
int runDrapeStudy(const DrapeStudyOptions& options);

}  // namespace figment::bench
