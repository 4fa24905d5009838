// A region holds the points of its band of heights, within its range across or (for the arms)
// outside it; a point belongs to the first region that holds it.
#include <gtest/gtest.h>

#include <vector>

#include "sim/fit/FitRegion.h"

using namespace figment;

namespace {

FitRegion band(const char* name, double low, double high, double minX, double maxX, bool inside) {
  FitRegion region;
  region.name = name;
  region.low = low, region.high = high, region.minX = minX, region.maxX = maxX, region.inside = inside;
  return region;
}

TEST(FitRegion, HoldsItsBandWithinOrOutsideItsRangeAcross) {
  const FitRegion waist = band("waist", 1.0, 1.1, -0.2, 0.2, true);
  EXPECT_TRUE(waist.holds(Vec3(0, 1.0, 0.3)));   // low is in the band
  EXPECT_FALSE(waist.holds(Vec3(0, 1.1, 0)));    // high is not
  EXPECT_TRUE(waist.holds(Vec3(0.2, 1.05, 0)));  // the range across includes its ends
  EXPECT_FALSE(waist.holds(Vec3(0.25, 1.05, 0)));
  const FitRegion arms = band("upper arms", 1.1, 1.4, -0.2, 0.2, false);
  EXPECT_TRUE(arms.holds(Vec3(0.25, 1.2, 0)));
  EXPECT_FALSE(arms.holds(Vec3(0.1, 1.2, 0)));
  EXPECT_FALSE(waist.hasGirth());  // no body section given
}

TEST(FitRegion, APointIsTheFirstRegionThatHoldsIt) {
  const std::vector<FitRegion> regions = {band("bust", 1.2, 1.4, -0.2, 0.2, true),
                                          band("upper arms", 1.1, 1.4, -0.2, 0.2, false),
                                          band("shoulders", 1.3, 1.5, -1, 1, true)};
  EXPECT_EQ(regionOf(regions, Vec3(0, 1.35, 0)), 0);    // bust and shoulders: the bust first
  EXPECT_EQ(regionOf(regions, Vec3(0.3, 1.35, 0)), 1);  // beside the torso
  EXPECT_EQ(regionOf(regions, Vec3(0, 1.45, 0)), 2);
  EXPECT_EQ(regionOf(regions, Vec3(0, 0.5, 0)), -1);
}

TEST(FitRegion, NamesEveryRegionABodyMayHaveInOrder) {
  EXPECT_EQ(fitRegionNames(),
            (std::vector<std::string>{"bust", "underbust", "waist", "hips", "thighs", "shoulders", "upper arms"}));
}

}  // namespace
