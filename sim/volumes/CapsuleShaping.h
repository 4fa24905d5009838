#pragma once
// Shaping a capsule to a body part's vertices by the paper's genetic algorithm (§3.1).
//
// The search is geneticSearch (sim/volumes/GeneticSearch.h) over the capsule's 12
// parameters: a population of identical capsules starts from one default capsule set on
// the part (startingCapsule); the shares of the population rounded down to counts (at
// least 4 members and one parent); a mutation moves its parameter by a normal step of
// its scale, within limits set by the part's size. The cost of a member is the mean over
// the vertices of their squared distance to its surface, a vertex outside weighing
// `outsideWeight` times one inside (draping is decided by convexities: a capsule should
// enclose the part). A seeded generator makes a fit repeat exactly. Finally the best
// capsule is grown about its centre until it encloses every vertex (§3.3: the volume,
// not the mesh, is the body's shape for the cloth).
//
// The cost uses a cheap distance: the unit-capsule distance of the vertex, scaled by
// the capsule's dimensions in its direction. It is exact at the surface (zero there)
// and close to the world distance near it, which is where a good fit puts the vertices.

#include <vector>

#include "sim/collision/Capsule.h"
#include "sim/volumes/GeneticSearch.h"

namespace figment {

struct CapsuleShapingOptions : GeneticShares {
  CapsuleShapingOptions() {
    population = 60;
    generations = 400;
  }
  double outsideWeight = 10.0;
  bool enclose = true;  // grow the result until every vertex is inside
  // The cost of a member: the cost above of the member grown about its centre until it
  // encloses every point (enclosedCapsuleCost: the bias to enclosure taken to its end,
  // since enclosure is forced afterwards anyway); false: the cost above as it stands.
  bool costAfterEnclosure = true;
};

struct CapsuleShaping {
  CapsuleParameters parameters;
  double cost = 0.0;            // of the best member before enclosure
  double enclosureScale = 1.0;  // how much enclosure grew it (1: not at all)
};

// Throws std::invalid_argument when `points` has fewer than 4 points or no extent.
CapsuleShaping shapeCapsule(const std::vector<Vec3>& points, const CapsuleShapingOptions& options = {});

// The default capsule set on the points, where a fit starts: centred on them, along
// their principal axis (pointing up), as big as their extents, ends half rounded.
CapsuleParameters startingCapsule(const std::vector<Vec3>& points);

// Grows `capsule` about its centre by the smallest factor (to 0.1 %) that puts every
// point inside; returns the factor (1: it already enclosed them).
double growToEnclose(CapsuleParameters& capsule, const std::vector<Vec3>& points);

// The cost above of `capsule` for `points` (lower is better).
double capsuleCost(const Capsule& capsule, const std::vector<Vec3>& points, double outsideWeight);

// The factor g by which the untapered unit capsule must grow about its centre to reach
// the unit-space point u (u on its surface: 1; inside: < 1), in closed form: the side
// where |u.y| <= g (1/2 - h), else the end's half-ellipsoid of half-height h.
double unitGauge(const Capsule& capsule, const Vec3& u);

// capsuleCost (outsideWeight 1) of `parameters` grown about the centre by the largest
// unitGauge of the points: the mean squared gap once (nearly: the taper is ignored in
// the growth) every point is enclosed.
double enclosedCapsuleCost(const CapsuleParameters& parameters, const std::vector<Vec3>& points);

}  // namespace figment
