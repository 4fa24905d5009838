#pragma once
// The mannequin as a set of posed part volumes (paper §3.3), a Collider for the cloth
// solver. The volumes overlap at the joints, and a node inside two of them must end
// outside all of them, without jitter between them. The contact is a pure function of
// the point, built so that its push-out target surfacePoint + clearance normal is clear
// of every volume (beyond the clearance):
//
//   touching(i, p)  volume i's signed distance at p < clearance (less 0.1 um, so that a
//                   node set on a target by rounding, or by a fast path's few nanometres,
//                   is not touched again)
//   candidates      each touching volume's nearest point w_i, normal n_i, target
//                   x_i = w_i + clearance n_i
//   contact(p)      the candidate nearest p (smallest |d_i|, ties: the first volume)
//                   whose target is clear of every volume; distance = |d_i|, negative
//                   when p is inside any volume. Its own volume is not searched again:
//                   the target lies the clearance out along the normal by construction
//                   (re-measuring it by the same fast path only adds its convergence
//                   noise, nanometres, which used to reject good targets); only its
//                   inside test must say outside.
//   crease          no target clear (p deep in the fold between two volumes): from the
//                   nearest target, push out of the volumes it is still in (the two
//                   deepest at once, by their tangent planes, which a convex volume lies
//                   behind), at most 16 times; then march away from p, doubling the step,
//                   until clear (the volumes are bounded: it ends). The contact then runs
//                   from p to that point: normal along it, surfacePoint = x - clearance n.
//   not touching    out.distance = min over volumes of a lower bound of their distance:
//                   their bounding capsule's, their own cheap bound
//                   (CollisionVolume::distanceBound) or their distance (a lower bound of
//                   the distance to the union's surface).
// A target is a fixed point: queried again, it touches nothing. No heap allocation per
// query; the cheap bounds skip the nearest-point search of every volume they show to be
// beyond the clearance, here and in the clear-of-all test, where a volume bounded or
// measured at p is also clear of a target whose step from p its bound exceeds by the
// clearance (distances are 1-Lipschitz).

#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <vector>

#include "sim/collision/Collider.h"
#include "sim/collision/CollisionVolume.h"

namespace figment {

struct PosedCollisionVolume {
  int part = -1;                                            // skeleton part index (for the caller)
  std::shared_ptr<const CollisionVolume> volume;            // in the part's rest frame
  Eigen::Affine3d transform = Eigen::Affine3d::Identity();  // rest frame -> world
};

class VolumeSetCollider : public Collider {
 public:
  // Throws std::invalid_argument when a volume is null or its transform singular.
  explicit VolumeSetCollider(std::vector<PosedCollisionVolume> volumes);

  // With no volumes: false, and out.distance = +infinity. `searchRadius` is not needed:
  // every volume answers from anywhere.
  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override;

  // The volumes whose bounding capsule's box comes within `reach` of `region` (a box
  // test: conservative, it may keep a volume a capsule test would leave out).
  std::shared_ptr<const Collider> focusedOn(const Eigen::AlignedBox3d& region, double reach) const override;

  // The parts (PosedCollisionVolume::part, ascending, each once) of the volumes that come
  // within `distance` (m) of any of `points`: where a garment placed at `points` meets
  // the body.
  std::vector<int> partsWithin(const std::vector<Vec3>& points, double distance) const;

  size_t size() const { return world_.size(); }
  int part(size_t i) const { return parts_[i]; }
  // Volume i in world space (its transform built in): for tests and benchmarks.
  const CollisionVolume& worldVolume(size_t i) const { return *world_[i]; }

 private:
  // A bounding capsule for the squared-distance early-out.
  struct Reach {
    explicit Reach(const BoundingCapsule& c);
    double squaredAxisDistance(const Vec3& p) const;  // to the segment, m^2
    bool beyond(const Vec3& p, double gap) const;     // its capsule's gap >= gap
    Vec3 a, ab;
    double inverseLength2, radius;
  };
  // The volumes contact() found not touching p within their bounding capsules' reach, each
  // with a lower bound of its distance (its distanceBound or its distance): the first
  // kMeasured, no heap allocation.
  static constexpr int kMeasured = 16;
  struct Measured {
    std::array<size_t, kMeasured> volume{};
    std::array<double, kMeasured> distance{};
    int count = 0;
    void add(size_t i, double d) {
      if (count < kMeasured) volume[count] = i, distance[count] = d, ++count;
    }
    const double* find(size_t i) const {
      for (int k = 0; k < count; ++k)
        if (volume[k] == i) return &distance[k];
      return nullptr;
    }
  };
  static constexpr size_t kNone = static_cast<size_t>(-1);

  // Whether x is at least `gap` from volume i by a cheap lower bound (its bounding
  // capsule's, then its own distanceBound): no nearest-point search needed.
  bool beyond(size_t i, const Vec3& x, double gap) const;
  // Whether x is clear of every volume. `own` (the volume whose target x is, or kNone) only
  // by its inside test: x lies the clearance out along its normal by construction. A
  // volume in `measured` (at a point `moved` from x) is clear where its bound there less
  // `moved` is (distance functions are 1-Lipschitz).
  bool clearOfAll(const Vec3& x, double clearance, size_t own, const Measured& measured, double moved) const;
  // out.distance when nothing touches p.
  double lowerBound(const Vec3& p, double clear, const Measured& measured) const;
  Vec3 creaseTarget(const Vec3& p, const Vec3& start, const Vec3& away, double clearance) const;

  std::vector<int> parts_;
  std::vector<std::shared_ptr<const CollisionVolume>> world_;
  std::vector<Reach> reach_;
};

}  // namespace figment
