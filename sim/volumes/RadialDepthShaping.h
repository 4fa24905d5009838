#pragma once
// Shaping the paper's radial depth volume (§3.2, sim/collision/RadialDepth.h) to a body
// part: the analytic half of "a combination of analytic and iterative (genetic)
// techniques" (the axis search is sim/volumes/AxisSearch.h). Two fits, both ending in
// enclosure (§3.3): every section's constant term grows until the part is inside.

#include <vector>

#include "sim/collision/RadialDepth.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

// Fits a radial depth volume to `body`'s triangles whose centroid projects onto the axis
// [base, base + length direction] and lies within `maxRadius` of it: `sections` cross
// sections (>= 2), each sampled at `angles` angles by the farthest section point per
// angular bin, then K = `harmonics` Fourier terms by least squares; then every section's
// constant term grows until each of those triangles' vertices is inside (enclosure).
RadialDepth shapeRadialDepth(const TriangleMesh& body, const Vec3& base, const Vec3& direction, double length,
                             double maxRadius, int sections, int harmonics, int angles = 64);

// Fits a radial depth volume on the axis [base, base + length direction] to the points
// of a part's surface (its vertices, say, and its triangles' centroids), all of which
// must project onto the axis: the coefficients of all `sections` at once by least
// squares on the radial depths, r(s_i, a_i) ~ rho_i, with the linear interpolation
// between sections built in, each point falling short (r < rho) weighing
// `outsideWeight` times one standing inside (iterated until the weights settle: an
// envelope fit, since the cloth drapes over convexities); a light smoothness penalty
// (second differences along the axis, k^4-weighted harmonics) keeps sections with few
// points well posed. Then enclosure, per section: each point of `enclose` left outside
// raises the constant terms of its two sections by its shortfall.
RadialDepth shapeRadialDepthToPoints(const std::vector<Vec3>& points, const std::vector<Vec3>& enclose,
                                     const Vec3& base, const Vec3& direction, double length, int sections,
                                     int harmonics, double outsideWeight = 100.0);

}  // namespace figment
