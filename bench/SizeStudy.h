#pragma once
// The garment-size study (paper §4: progressive meshes pay more the finer the garment):
// a scene's garment resampled to each size (sim/progressive/Resampling.h), draped whole
// and progressively from a decimated level, by the same method: steps and median wall
// time to rest of both, the speed-up, and the at-rest deviation between them.

#include <string>
#include <vector>

namespace figment::bench {

struct SizeStudyOptions {
  std::string scene = "scenes/dress.iv";  // its first ClothEngine's garment is resampled
  std::vector<int> sizes = {1000, 3000, 6000, 12000, 25000, 50000};  // sections
  std::string method = "implicit:0.05";
  double coarseShare = 0.25;  // the progressive drape begins at this share of the sections
  double splitTime = 1.0;     // s of simulated time over which every split is made
  int repeat = 1;
  std::string outDir = "bench-out";
  std::string plotScript;  // python script that charts the CSV; "" = no chart
};

// Writes DIR/sizes.csv (and DIR/sizes.png with the plot script) and prints a table.
// Returns the exit code.
int runSizeStudy(const SizeStudyOptions& options);

}  // namespace figment::bench
