#include "sim/fit/FitRegion.h"

namespace figment {

namespace {

constexpr double kAcrossMargin = 0.03;  // m beside the torso's section still the torso's
constexpr double kThighBand = 0.15;     // m below the crotch told as the thighs
constexpr double kArmBand = 0.25;       // m below the armpits the upper arms reach (A-pose)

// A torso band from `low` to `high` whose girth is taken at `level`: its across range is
// its own section's, widened by the margin (the arms beside it are not its).
FitRegion torsoBand(const TriangleMesh& body, const SliceOptions& slicing, const char* name, double low, double high,
                    double level) {
  FitRegion region;
  region.name = name;
  region.low = low;
  region.high = high;
  region.girthLevel = level;
  region.bodySection = sliceTorso(body, level, slicing);
  region.slicing = slicing;
  if (!region.bodySection.empty()) {
    region.minX = region.bodySection.minX() - kAcrossMargin;
    region.maxX = region.bodySection.maxX() + kAcrossMargin;
  }
  return region;
}

}  // namespace

bool FitRegion::holds(const Vec3& p) const {
  if (p.y() < low || p.y() >= high) return false;
  const bool within = p.x() >= minX && p.x() <= maxX;
  return within == inside;
}

std::vector<FitRegion> bodyRegions(const TriangleMesh& body, const BodyMeasurements& measured, bool underbust) {
  const BodyLandmarks& l = measured.landmarks;
  const SliceOptions slicing = centredSlicing(body, 0.04, 0.12);
  const double centreX = slicing.torsoCentreX;
  std::vector<FitRegion> regions;
  const double waistTop = underbust ? 0.5 * (l.waist + l.underbust) : 0.5 * (l.waist + l.bust);
  const double bustBottom = underbust ? 0.5 * (l.underbust + l.bust) : waistTop;
  regions.push_back(torsoBand(body, slicing, "bust", bustBottom, l.armpit, l.bust));
  if (underbust) regions.push_back(torsoBand(body, slicing, "underbust", waistTop, bustBottom, l.underbust));
  for (FitRegion& region : regions) region.girthWithinAcross = true;  // the sleeves reach down to here
  regions.push_back(torsoBand(body, slicing, "waist", 0.5 * (l.hip + l.waist), waistTop, l.waist));
  regions.push_back(torsoBand(body, slicing, "hips", l.crotch, 0.5 * (l.hip + l.waist), l.hip));
  regions.push_back(torsoBand(body, slicing, "thighs", l.crotch - kThighBand, l.crotch, l.crotch - 0.03));
  FitRegion shoulders;
  shoulders.name = "shoulders";
  shoulders.low = l.armpit;
  shoulders.high = l.neck;
  shoulders.minX = centreX - 0.5 * measured.shoulderWidth;
  shoulders.maxX = centreX + 0.5 * measured.shoulderWidth;
  regions.push_back(shoulders);
  FitRegion arms;
  arms.name = "upper arms";
  arms.low = l.armpit - kArmBand;
  arms.high = l.neck;
  arms.minX = regions.front().minX;  // beside the bust's section
  arms.maxX = regions.front().maxX;
  arms.inside = false;
  regions.push_back(arms);
  return regions;
}

const std::vector<std::string>& fitRegionNames() {
  static const std::vector<std::string> names = {"bust",   "underbust", "waist",     "hips",
                                                 "thighs", "shoulders", "upper arms"};
  return names;
}

int regionOf(const std::vector<FitRegion>& regions, const Vec3& p) {
  for (size_t i = 0; i < regions.size(); ++i)
    if (regions[i].holds(p)) return static_cast<int>(i);
  return -1;
}

}  // namespace figment
