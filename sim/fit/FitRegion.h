#pragma once
// The parts of a body a garment's fit is told for (bust, underbust, waist, hips, thighs,
// shoulders, upper arms): each a band of heights and a range across (x) from the body's
// landmarks (sim/body/BodyMeasurements.h), and for the torso's bands the body's convex
// section at the level a tape measures it, against which the garment's girth is taken.
// Bounds and why: docs/sizes.md.

#include <limits>
#include <string>
#include <vector>

#include "sim/body/BodyMeasurements.h"
#include "sim/body/BodySlices.h"

namespace figment {

struct FitRegion {
  std::string name;          // "hips", "upper arms"
  double low = 0, high = 0;  // m: a garment point with low <= y < high may be the region's
  // Across: with `inside`, a point with minX <= x <= maxX is the region's; without, one
  // outside that range (the arms beside the torso).
  double minX = -std::numeric_limits<double>::infinity(), maxX = std::numeric_limits<double>::infinity();
  bool inside = true;
  // The level a tape takes the region's girth at and the body's convex section there;
  // empty for a region without a girth (shoulders, upper arms).
  double girthLevel = 0;
  TorsoSlice bodySection;
  SliceOptions slicing;  // how the body's sections are cut (for levels below girthLevel)
  // Whether the girth leaves out what lies beside the torso (minX to maxX): where a sleeve
  // joins the garment's loop round the torso (bust, underbust).
  bool girthWithinAcross = false;

  bool holds(const Vec3& p) const;
  bool hasGirth() const { return !bodySection.empty(); }
};

// The regions of a standing body (metres, y up, about symmetric in x), from its
// measurements; `underbust` false leaves the underbust out (a men's chart has none). A
// garment point belongs to the first region in the list that holds it.
std::vector<FitRegion> bodyRegions(const TriangleMesh& body, const BodyMeasurements& measured, bool underbust);

// Every region's name bodyRegions may give, in its order: what a catalogue's style may
// name as the regions its fit is told for.
const std::vector<std::string>& fitRegionNames();

// The region of `p`: its index in `regions`, or -1.
int regionOf(const std::vector<FitRegion>& regions, const Vec3& p);

}  // namespace figment
