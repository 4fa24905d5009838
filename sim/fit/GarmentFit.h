#pragma once
// How a draped garment fits, region by region (sim/fit/FitRegion.h): its stretch (the
// largest principal strain of each section, % of rest), its ease (the garment's mean
// distance from the skin, and its taped girth less the body's), and its pressure on the
// body (the contact forces over the garment's area). Measured on the drape's end state;
// the verdict on these is sim/fit/FitVerdict.h's. Definitions in docs/sizes.md. On a posed
// body the regions and girths are the standing body's, each node told where it would lie
// on it (sim/fit/PosedSkin.h); stretch, ease and pressure are the posed drape's own.

#include <limits>
#include <string>
#include <vector>

#include "sim/cloth/ClothParameters.h"
#include "sim/cloth/RestShape.h"
#include "sim/collision/MeshCollider.h"
#include "sim/core/TriangleMesh.h"
#include "sim/fit/FitRegion.h"
#include "sim/fit/PosedSkin.h"

namespace figment {

struct RegionFit {
  std::string name;
  int nodes = 0;          // garment nodes in the region (0: the garment does not cover it)
  double meanStrain = 0;  // area-weighted mean of the sections' largest principal strain
  double maxStrain = 0;   // the largest; both dimensionless (0.07 = 7 % over rest length)
  double ease = 0;        // m, mean distance of the region's nodes from the skin, less the offset
  // m, taped round the garment at the region's level (or the highest level below it in
  // the region where the garment goes all round), and that less the body's there.
  double garmentGirth = std::numeric_limits<double>::quiet_NaN();
  double girthEase = std::numeric_limits<double>::quiet_NaN();
  double drop = 0;  // m from the region's top down to its highest garment node; 0 where the garment goes on above it
  double pressure = 0;     // Pa: the contact forces' sum over the region's garment area
  double maxPressure = 0;  // Pa: the largest at one node (its force over its share of area)
  // On a posed body, why the region's girth and drop cannot be told (NaN and 0 then); ""
  // where they can, and on a standing body.
  std::string unmeasured{};
  bool covered() const { return nodes > 0; }
};

struct FitInput {
  const TriangleMesh* rest = nullptr;  // the garment as cut (its triangles, and its rest shape but for `restShape`)
  const std::vector<Vec3>* positions = nullptr;  // where each rest point lies after the drape
  const MeshCollider* body = nullptr;            // the skin
  ClothParameters parameters;                    // the drape's: material, gravity, clearance
  // The body's skin at rest and posed (`body` is its posed shape), or null for a body that
  // stands as its regions were found (the regions are then the rest skin's).
  const PosedSkin* pose = nullptr;
  // Set: the garment's rest shape when `rest`'s vertices are not it (a sewn garment: its
  // flat panels, each section its own corners; `rest` is then the panels as placed, and
  // `positions` one per panel node): stretch and forces are measured against it. Its
  // triangles must be `rest`'s. Null: `rest` is the rest shape.
  const RestShape* restShape = nullptr;
};

// The largest principal strain of a section: sqrt of the largest eigenvalue of F^T F less 1,
// F the deformation gradient from its rest triangle (a, b, c) to (x, y, z). Negative when
// compressed both ways.
double largestPrincipalStrain(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x, const Vec3& y, const Vec3& z);

// Each node's pressure on the body, Pa: where the node touches (within the clearance and
// 2 mm), the component into the body of the cloth's elastic and gravity forces on it, at
// rest (zero velocity), over the node's share of the draped area; 0 elsewhere.
std::vector<double> contactPressures(const FitInput& input);

// Each node's region: its index in `regions` (found on the rest skin when `input.pose` is
// set, the node told where it would lie on it), or -1. What measureFit counts by.
std::vector<int> nodeRegions(const FitInput& input, const std::vector<FitRegion>& regions);

// Fit in each region (found on the rest skin when `input.pose` is set). Throws
// std::invalid_argument when an input is missing or the positions do not match the rest mesh.
std::vector<RegionFit> measureFit(const FitInput& input, const std::vector<FitRegion>& regions);

}  // namespace figment
