#pragma once
// The closed curves where a plane cuts a triangle mesh, one per connected piece: a torso, an
// arm, a leg. What a tape measure is laid along (sim/body/BodyMeasurements.h).

#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

// One connected piece of a plane section: the points where the mesh's edges cross the
// plane (m, in the mesh's frame), in no particular order, and their bounds.
struct SectionLoop {
  std::vector<Vec3> points;
  Bounds bounds;
  Vec3 centroid() const;  // mean of the points
};

// The pieces of the section of `mesh` by the plane through `point` with normal `normal`
// (need not be unit length, must not be zero). Two crossings belong to one piece when a
// triangle joins them, so pieces that touch no common triangle stay apart however near
// they are: an arm beside the torso, the two legs below the crotch. A vertex lying exactly
// on the plane counts as just above it, so no crossing is lost or doubled.
std::vector<SectionLoop> sectionLoops(const TriangleMesh& mesh, const Vec3& point, const Vec3& normal);

// The same for the horizontal plane y = height, faster: the triangles filed once by the
// 5 mm bands of height they span, so a level looks only at its band's.
class HorizontalSections {
 public:
  explicit HorizontalSections(const TriangleMesh& mesh);
  std::vector<SectionLoop> at(double height) const;

 private:
  static constexpr double kBand = 0.005;  // m
  const TriangleMesh& mesh_;
  double bottom_ = 0;       // m: the lowest vertex's height, band 0's foot
  std::vector<int> start_;  // band b's triangles: members_[start_[b] .. start_[b + 1])
  std::vector<int> members_;
};

}  // namespace figment
