#pragma once
// The mannequin as a set of posed part volumes (paper §3.3), a Collider for the cloth
// solver. The volumes overlap at the joints, and a node inside two of them must end
// outside all of them, without jitter between them. The contact is a pure function of
// the point, built so that its push-out target surfacePoint + clearance normal is clear
// of every volume (beyond the clearance):
//
//   touching(i, p)  volume i's signed distance at p < clearance (less 1 nm, so that a
//                   node set on a target by rounding is not touched again)
//   candidates      each touching volume's nearest point w_i, normal n_i, target
//                   x_i = w_i + clearance n_i
//   contact(p)      the candidate nearest p (smallest |d_i|, ties: the first volume)
//                   whose target is clear of every volume; distance = |d_i|, negative
//                   when p is inside any volume
//   crease          no target clear (p deep in the fold between two volumes): from the
//                   nearest target, push out of the volumes it is still in (the two
//                   deepest at once, by their tangent planes, which a convex volume lies
//                   behind), at most 16 times; then march away from p, doubling the step,
//                   until clear (the volumes are bounded: it ends). The contact then runs
//                   from p to that point: normal along it, surfacePoint = x - clearance n.
//   not touching    out.distance = min over volumes of their distance or their bounding
//                   sphere's (a lower bound of the distance to the union's surface).
// A target is a fixed point: queried again, it touches nothing. No heap allocation per
// query; bounding spheres skip far volumes.

#include "CollisionVolume.h"
#include "Collider.h"

#include <Eigen/Geometry>

#include <memory>
#include <vector>

namespace figment {

struct PosedVolume {
  int part = -1;                                // skeleton part index (for the caller)
  std::shared_ptr<const CollisionVolume> volume;  // in the part's rest frame
  Eigen::Affine3d transform = Eigen::Affine3d::Identity();  // rest frame -> world
};

class VolumeSetCollider : public Collider {
 public:
  // Throws std::invalid_argument when a volume is null or its transform singular.
  explicit VolumeSetCollider(std::vector<PosedVolume> volumes);

  // With no volumes: false, and out.distance = +infinity. `searchRadius` is not needed:
  // every volume answers from anywhere.
  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override;

  size_t size() const { return world_.size(); }
  int part(size_t i) const { return parts_[i]; }
  // Volume i in world space (its transform built in): for tests and benchmarks.
  const CollisionVolume& worldVolume(size_t i) const { return *world_[i]; }

 private:
  // Lower bound of p's distance to volume i by its bounding sphere.
  double sphereGap(size_t i, const Vec3& p) const { return (p - centres_[i]).norm() - radii_[i]; }
  bool clearOfAll(const Vec3& x, double clearance) const;
  Vec3 creaseTarget(const Vec3& p, const Vec3& start, const Vec3& away, double clearance) const;

  std::vector<int> parts_;
  std::vector<std::shared_ptr<const CollisionVolume>> world_;
  std::vector<Vec3> centres_;
  std::vector<double> radii_;
};

}  // namespace figment
