#pragma once
// The collision volume study (paper §3): for each part of the default body, how closely
// a fitted capsule and a radial depth volume follow it, whether they enclose it, what
// fitting costs, and what one point query costs against them and against the part's
// own triangles (the exact BVH collider).
//
// What is measured, per part of splitIntoParts (sim/body/BodyParts.h):
//   volumes   exactly what shapeCapsules / shapeRadialVolumes (sim/volumes/VolumeShaping.h) return for
//             the part: one or more capsules; a radial volume, or the part's capsules
//             where it falls back (kind column);
//   gap       one-sided, from the body: for each vertex of the part, its depth in the
//             deepest of the part's volumes that holds it (exact when one holds it; where
//             sub-volumes overlap, a lower bound of the distance to their union's
//             surface), else its distance to the nearest volume; mean and max over the
//             part's vertices, by the volumes' exact nearest();
//   enclosed  the share of the part's vertices inside one of its volumes;
//   query     ns per point for 2000 points within 1 cm (per axis) of the part's vertices:
//             for each of the part's volumes, a bounding-sphere test, then its fast
//             nearest point (nearestFast: point, normal, signed distance); the exact row
//             is MeshCollider::contact on the part's triangles (BVH closest point with an
//             unbounded search radius and pseudo-normal sign, the same answer);
//   fit_s     seconds to fit the part's volumes (radial: with the capsules, when the
//             radial volume's gap is large enough to try them).

#include <string>

namespace figment::bench {

struct CollisionStudyOptions {
  std::string body = "human.zae";  // found through the model search path
  int harmonics = 8;               // K of the radial depth volumes
  double sectionSpacing = 0.02;    // m between their sections
  std::string outDir = "bench-out";
  std::string plotScript;  // python script that charts the CSV; "" = no chart
};

// Writes DIR/collision.csv (part,method,mean_gap_mm,max_gap_mm,enclosed_pct,query_ns,
// fit_s,vertices,volumes,kind) and DIR/collision.png, prints the medians and the query
// time ratios. Returns the exit code.
int runCollisionStudy(const CollisionStudyOptions& options);

}  // namespace figment::bench
