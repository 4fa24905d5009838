#pragma once
// The collision volume study (paper §3): for each part of the default body, how closely
// a fitted capsule and a radial depth volume follow it, whether they enclose it, what
// fitting costs, and what one point query costs against them and against the part's
// own triangles (the exact BVH collider).

#include <string>

namespace figment::bench {

struct CollisionStudyOptions {
  std::string body = "human.zae";  // found through the model search path
  int harmonics = 8;               // K of the radial depth volumes
  double sectionSpacing = 0.02;    // m between their sections
  std::string outDir = "bench-out";
  std::string plotScript;          // python script that charts the CSV; "" = no chart
};

// Writes DIR/collision.csv (part,method,mean_gap_mm,max_gap_mm,enclosed_pct,query_ns,
// fit_s,vertices) and DIR/collision.png, prints the medians. Returns the exit code.
int runCollisionStudy(const CollisionStudyOptions& options);

}  // namespace figment::bench
