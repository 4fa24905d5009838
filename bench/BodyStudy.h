#pragma once
// The made-body study (issue 30's "ready fast" and its 60 measurement sets): for each set of
// sim/garment/SizeGrading.h's bodyCheckSets over the shipped size chart (its sizes, two graded
// beyond each end, each at its stature and 8 cm shorter and taller), the body made to its
// stature, bust, waist and hip (sim/body/MeasuredBody.h: the solve and the full measurement of what
// it achieved), timed; then checked, untimed, for skin crossings the base mesh does not have
// (sim/collision/SelfIntersections.h). The targets are read once before timing (a service
// keeps them loaded), and that load is reported apart.

#include <string>

namespace figment::bench {

struct BodyStudyOptions {
  int repeat = 1;  // timings per set (the median is kept)
  std::string outDir = "bench-out";
};

// Writes DIR/bodies.csv and prints the median and p90. Returns the exit code.
int runBodyStudy(const BodyStudyOptions& options);

}  // namespace figment::bench
