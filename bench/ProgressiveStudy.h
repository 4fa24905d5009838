#pragma once
// The progressive study (paper §4): a scene's garment draped with its progressive mesh
// from several begin levels at several split rates, against the same method on the
// full garment: steps and median wall time to rest of both, the speed-up, and the
// at-rest mean and largest deviation between them (% of the garment's height). Each
// drape is run at several time steps a little apart (rest states and times to rest are
// chaotic: SizeStudy.h) and medians are reported, with the floor: how far the full
// garment's own drapes at those steps lie from each other. A scene with no script gets
// one made on the fly (its garment decimated to coarseShare of its sections).

#include <string>
#include <vector>

namespace figment::bench {

struct ProgressiveStudyOptions {
  std::string scene = "scenes/dress-progressive.iv";  // its first engine has a progressiveScript
  std::vector<std::string> methods = {"implicit:0.05", "heun:1.5e-4:clamp:30"};
  // Each "BEGIN_SHARE:RATE": the begin level as a share of the levels (0: the coarsest),
  // and splits per second of simulated time (0: all once the begin level rests).
  std::vector<std::string> schedules = {"0:300", "0:1200", "0:3000", "0.5:1200"};
  std::vector<double> stepFactors = {0.99, 1.0, 1.01};  // the method's time step times each
  double coarseShare = 0.25;                            // for a script made on the fly
  std::string outDir = "bench-out";
  std::string plotScript;  // python script that charts the CSV; "" = no chart
};

// Writes DIR/progressive.csv (and DIR/progressive.png with the plot script) and prints a
// table. Returns the exit code.
int runProgressiveStudy(const ProgressiveStudyOptions& options);

}  // namespace figment::bench
