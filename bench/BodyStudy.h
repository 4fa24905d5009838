#pragma once
// The made-body study (issue 30's "ready fast"): MakeHuman bodies across the macro range,
// each made (sim/body/HumanModel.h) and measured (sim/body/BodyMeasurements.h); the wall
// time of each, medians over the bodies. The targets are read once before timing (a
// service keeps them loaded), and that load is reported apart.

#include <string>

namespace figment::bench {

struct BodyStudyOptions {
  int repeat = 3;  // timings per body (the median is kept)
  std::string outDir = "bench-out";
};

// Writes DIR/bodies.csv and prints the medians. Returns the exit code.
int runBodyStudy(const BodyStudyOptions& options);

}  // namespace figment::bench
