#pragma once
// MakeHuman's model and the shipped size chart (scenes/sizes/chart.txt), read once for a
// test suite of bodies made to the chart (tests/io/scenarios/test_SixBodyDrapes.cpp,
// test_SizeRecommendation.cpp): the suite keeps them from SetUpTestSuite to
// TearDownTestSuite, so the targets the fits blend are read once for all its tests.

#include <memory>

#include "io/MakeHumanLibrary.h"
#include "io/SizeChartFile.h"

namespace figment::test {

// Why a test that needs MakeHuman's data skips without it.
inline constexpr const char* kMakeHumanDataSkip = "MakeHuman's data not found (scripts/setup.sh fetches it)";

struct ChartBodies {
  std::unique_ptr<MakeHumanLibrary> human;  // its model read
  SizeChart chart;
};

// Null when MakeHuman's data is absent (the suite's tests then skip); the chart is read
// only when it is there.
inline std::unique_ptr<ChartBodies> loadChartBodies() {
  auto human = std::make_unique<MakeHumanLibrary>();
  if (human->dir().empty()) return nullptr;
  human->model();
  return std::make_unique<ChartBodies>(ChartBodies{std::move(human), readSizeChart(defaultSizeChartPath())});
}

}  // namespace figment::test
