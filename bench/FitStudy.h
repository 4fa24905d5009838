#pragma once
// The size-recommendation study (issue 31): for each style and each body of the size chart,
// figment-size's recommendation (sim/fit/SizeFitter.h) with warm starts and cold: whether it
// is the body's own size, its wall time (the chart's garments graded beforehand, as a
// service keeps its catalogue) and the steps the warm starts saved; and over a grid of
// bodies along the chart, whether the recommendation ever gets smaller as the body grows.

#include <string>
#include <vector>

namespace figment::bench {

struct FitStudyOptions {
  std::vector<std::string> styles = {"pencil", "dress", "skirt", "tshirt"};
  std::vector<std::string> sexes = {"female", "male"};
  int repeat = 3;           // warm recommendations timed per body (the median is kept)
  int grid = 0;             // bodies along the chart per sex and style for the monotony check (0: none)
  double gridBeyond = 1.0;  // sizes the grid reaches beyond each end of the chart
  std::string outDir = "bench-out";
};

// Writes DIR/fit.csv (and DIR/fit-grid.csv with a grid) and prints the medians. Returns the
// exit code.
int runFitStudy(const FitStudyOptions& options);

}  // namespace figment::bench
