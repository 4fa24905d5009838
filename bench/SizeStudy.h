#pragma once
// The garment-size study (paper §4: progressive meshes pay more the finer the garment):
// a scene's garment resampled to each size (sim/progressive/Resampling.h), draped whole
// and progressively from a decimated level, by the same method: steps and median wall
// time to rest of both, the speed-up, and the at-rest deviation between them.
//
// A drape's rest state and its time to rest are chaotic (which way a fold falls, when the
// last node slows under the rest speed): a 1 % longer step moves the default dress's rest
// state by 0.35 % of its height. So each size is draped at several time steps a little
// apart, medians are reported, and the floor: how far the whole garment's own drapes at
// those steps lie from each other. A progressive drape cannot be told apart from the
// whole garment's more closely than that.

#include <string>
#include <vector>

namespace figment::bench {

struct SizeStudyOptions {
  std::string scene = "scenes/dress.iv";                             // its first ClothEngine's garment is resampled
  std::vector<int> sizes = {1000, 3000, 6000, 12000, 25000, 50000};  // sections
  std::string method = "implicit:0.05";
  double coarseShare = 0.25;  // the progressive drape begins at this share of the sections
  double splitTime = 0.5;     // s of simulated time over which every split is made (the scene's: 617 at 1,200/s)
  double maxTime = 10.0;      // s of simulated time a drape may take (the scene's is for its own garment)
  std::vector<double> stepFactors = {0.99, 1.0, 1.01};  // the method's time step times each
  std::string outDir = "bench-out";
  std::string plotScript;  // python script that charts the CSV; "" = no chart
};

// Writes DIR/sizes.csv (and DIR/sizes.png with the plot script) and prints a table.
// Returns the exit code.
int runSizeStudy(const SizeStudyOptions& options);

}  // namespace figment::bench
