#pragma once
// A radial depth volume for one body part (paper §3.2): the analytic fit
// (sim/volumes/RadialDepthShaping.h) along the best axis the genetic search
// (sim/volumes/AxisSearch.h) finds.

#include <vector>

#include "sim/body/BodyParts.h"
#include "sim/collision/RadialDepth.h"

namespace figment {

// A radial depth volume on the best axis found: the best of three (the bone; the bone's
// direction through the part's centroid; the part's principal axis nearest the bone's
// direction, through the centroid) by radialGapEstimate, then the genetic search
// (sim/volumes/AxisSearch.h) from it; each volume lengthened to span every vertex of the part,
// with sections about `sectionSpacing` (m) apart and K = `harmonics`
// (shapeRadialDepthToPoints on the part's vertices and triangle centroids).
RadialDepth shapeRadialPart(const PartMesh& part, int harmonics, double sectionSpacing);

// A cheap estimate of the mean gap from `vertices` to `volume`: the radial shortfall
// r(s, a) - rho of each, at most its distance to the nearer cap (m).
double radialGapEstimate(const RadialDepth& volume, const std::vector<Vec3>& vertices);

}  // namespace figment
