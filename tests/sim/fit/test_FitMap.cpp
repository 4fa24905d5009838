// The fit map's colours follow the values drawn: a tube stretched round a cylinder by a known
// strain lands in the band that strain is of the fabric's limit, blue at rest, red at and
// past the limit; ease and pressure read the same way.
#include <gtest/gtest.h>

#include "sim/fit/FitMap.h"
#include "support/FitTubes.h"

using namespace figment;
using test::Case;

TEST(FitMap, EightBandsFromBlueToRed) {
  EXPECT_EQ(fitMapColour(0), Vec3(0, 0, 1));
  EXPECT_EQ(fitMapColour(kFitMapBands - 1), Vec3(1, 0, 0));
  EXPECT_EQ(fitMapBand(0.0), 0);
  EXPECT_EQ(fitMapBand(0.124), 0);
  EXPECT_EQ(fitMapBand(0.126), 1);
  EXPECT_EQ(fitMapBand(1.0), kFitMapBands - 1);
  // The hue falls band by band: from blue over cyan, green and yellow to red.
  for (int band = 1; band < kFitMapBands; ++band) {
    const Vec3 a = fitMapColour(band - 1), b = fitMapColour(band);
    EXPECT_NE(a, b) << band;
    EXPECT_GE(b.x(), a.x()) << band;  // red grows
    EXPECT_LE(b.z(), a.z()) << band;  // blue fades
  }
}

TEST(FitMap, AStretchedTubeIsColouredByItsStrain) {
  const FabricLimits cotton = fabricLimits("cotton");  // 4 %
  for (const double strain : {0.0, 0.006, 0.011, 0.021, 0.036, 0.05}) {
    const double body = 0.15, draped = body + 0.003;
    Case c(draped / (1 + strain), draped, body, 0.003);
    const std::vector<double> values = fitMapValues(c.input, FitMapKind::Stretch);
    const int expected = std::min(kFitMapBands - 1, static_cast<int>(strain / cotton.stretch * kFitMapBands));
    for (const double value : values) {
      EXPECT_NEAR(value, strain, 1e-9);
      EXPECT_EQ(fitMapBand(fitMapShare(value, FitMapKind::Stretch, cotton)), expected) << strain;
    }
  }
}

TEST(FitMap, EaseIsRedOnTheSkinAndBlueFarFromIt) {
  const FabricLimits jersey = fabricLimits("jersey");
  Case on(0.153, 0.153, 0.15, 0.003);
  for (const double value : fitMapValues(on.input, FitMapKind::Ease))
    EXPECT_EQ(fitMapBand(fitMapShare(value, FitMapKind::Ease, jersey)), kFitMapBands - 1);
  Case off(0.21, 0.21, 0.15, 0.003);
  for (const double value : fitMapValues(off.input, FitMapKind::Ease))
    EXPECT_EQ(fitMapBand(fitMapShare(value, FitMapKind::Ease, jersey)), 0);
}

TEST(FitMap, PressureIsTheContactPressure) {
  Case c(0.153 / 1.02, 0.153, 0.15, 0.003);
  EXPECT_EQ(fitMapValues(c.input, FitMapKind::Pressure), contactPressures(c.input));
  EXPECT_EQ(fitMapShare(3000, FitMapKind::Pressure, fabricLimits("jersey")), 1.0);
}

TEST(FitMap, KindsByName) {
  EXPECT_EQ(fitMapKind("stretch"), FitMapKind::Stretch);
  EXPECT_EQ(fitMapKind("ease"), FitMapKind::Ease);
  EXPECT_EQ(fitMapKind("pressure"), FitMapKind::Pressure);
  EXPECT_THROW(fitMapKind("colour"), std::invalid_argument);
}
