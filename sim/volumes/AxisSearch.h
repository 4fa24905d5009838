#pragma once
// The genetic search for a radial depth volume's axis (paper §3.2: "a combination of
// analytic and iterative (genetic) techniques"): the analytic part fits the harmonics
// for a given axis; this searches the axis.
//
// A member is an axis near a starting one: its direction tilted by (u, v) radians about
// two directions perpendicular to the start's, its origin moved by (du, dv) m along
// them, each within its limit. The search is geneticSearch (sim/volumes/GeneticSearch.h):
// the starting axis and members spread uniformly within the limits; the shares of the
// population rounded to the nearest count (at least one mutant and one parent, the best
// member always kept); a mutation moves its gene by 0.3 times its limit times a standard
// normal draw. The result never costs more than the starting axis; a search repeats
// exactly with its seed.

#include <functional>

#include "sim/core/TriangleMesh.h"
#include "sim/volumes/GeneticSearch.h"

namespace figment {

struct AxisSearchOptions : GeneticShares {  // population 10, 6 generations
  double maxTilt = 0.35;                    // rad, about each perpendicular
  double maxShift = 0.02;                   // m, along each perpendicular
};

struct Axis {
  Vec3 origin;
  Vec3 direction;  // unit
};

struct AxisSearchResult {
  Axis axis;
  double cost = 0.0;
  int evaluations = 0;
};

// `cost` of an axis (lower is better; e.g. the gap of the volume fitted along it).
// Throws std::invalid_argument when the start's direction is zero or the options are
// out of range.
AxisSearchResult searchAxis(const Axis& start, const std::function<double(const Axis&)>& cost,
                            const AxisSearchOptions& options = {});

}  // namespace figment
