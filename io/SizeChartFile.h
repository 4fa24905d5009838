#pragma once
// A size chart's text file (scenes/sizes/chart.txt): one size a line, "sex size number
// stature bust waist hip" (female|male, the letter code, the chart's number, metres); '#'
// starts a comment. What figment-size and the tests read (sim/garment/SizeChart.h).

#include <string>

#include "sim/garment/SizeChart.h"

namespace figment {

// The chart shipped with the sources (scenes/sizes/chart.txt).
std::string defaultSizeChartPath();

// Throws std::runtime_error("<path>:<line>: <reason>") for a file that cannot be read, a
// malformed line or a chart SizeChart refuses.
SizeChart readSizeChart(const std::string& path);

}  // namespace figment
