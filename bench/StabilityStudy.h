#pragma once
// The stability study (paper §2): for each integrator, with and without strain
// clamping and with each acceleration limiter, over a range of time steps, drape the
// scene's garment and record whether the run stays stable, how long it takes, and how
// far its rest shape lies from a converged small-step reference.

#include <string>
#include <vector>

namespace figment::bench {

struct StabilityStudyOptions {
  std::string scene = "scenes/dress.iv";
  std::string outDir = "bench-out";
  bool quick = false;                    // a few configurations and steps, short runs: < 1 minute
  double strainLimit = 0.1;              // Green strain, when clamping is on
  double accelerationLimit = 30;         // multiples of |g|, when a limiter is on (the default scene's cap)
  std::vector<double> timeSteps;         // s, ascending; empty = the study's own list
  std::vector<std::string> integrators;  // euler, symplectic, heun; empty = all three
  std::string plotScript;                // python script that charts the CSV; "" = no chart
};

// Writes DIR/stability.csv (and DIR/stability.png when the chart can be drawn) and
// prints a summary: the largest stable step per configuration and its deviation.
// Returns the process exit code.
int runStabilityStudy(const StabilityStudyOptions& options);

}  // namespace figment::bench
