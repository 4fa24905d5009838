#pragma once
// A body surface that moves during a drape (issue 30: the garment is put on in the rest
// pose and the body moves to its pose over simulated time, so no pose tangles it): the
// exact collider (MeshCollider) of the surface as it is at the drape's time, rebuilt at
// keyframes spaced so that no vertex moves more than `maxStep` between two.
//
// The drape's clock (DrapeRequest::bodyClock) calls advanceTo(t) before the first step and
// after each; between calls contact() answers for the current keyframe. While the body
// still moves, a point's distance reported as a lower bound is cut by how far the surface
// may yet move (so the solvers' query skipping, exact for a still body, stays safe), and
// every query searches without a radius (the surface may have come onto a point from
// farther than the caller's radius). From the last keyframe on it answers as the final
// surface's MeshCollider.
//
// Before any advanceTo() it stands at its last keyframe (the final shape): whoever asks
// without a clock sees the body as drawn.

#include <functional>
#include <memory>
#include <vector>

#include "sim/collision/MeshCollider.h"

namespace figment {

class MovingMeshCollider : public Collider {
 public:
  // The surface's vertices `share` of the way from the first shape (0) to the last (1).
  using ShapeAt = std::function<std::vector<Vec3>(double share)>;

  // Samples the motion (kSamples shapes) to bound the farthest any vertex travels, and
  // spaces the keyframes by it. `duration` (s): how long the motion takes; 0: as long as
  // the farthest-travelling vertex needs at kSpeed. Throws std::invalid_argument when
  // duration < 0, maxStep is not > 0, or a shape's vertex count differs from the first's.
  MovingMeshCollider(std::vector<Triangle> triangles, ShapeAt shapeAt, double duration, double maxStep = 0.01,
                     OpenEdges openEdges = OpenEdges::PseudoNormal);
  static constexpr int kSamples = 32;
  // m/s: slow enough that at the implicit drapes' 0.05 s steps the surface moves about
  // a centimetre a step, far less than a limb's radius, so a node it reaches is pushed
  // out on the side it came from.
  static constexpr double kSpeed = 0.25;

  // Moves the surface to its shape at simulated time `time` (s): the keyframe at or
  // before it. Not concurrent with contact().
  void advanceTo(double time) const override;
  bool moves() const override { return true; }
  bool contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const override;

  double duration() const { return duration_; }
  int keyframes() const { return keyframes_; }
  // The farthest any vertex travels over the whole motion (m, the samples' sum).
  double travel() const { return travel_; }
  // The collider of the keyframe now.
  const MeshCollider& current() const { return *current_; }

 private:
  std::vector<Triangle> triangles_;
  ShapeAt shapeAt_;
  OpenEdges openEdges_;
  double duration_ = 0.0, travel_ = 0.0;
  int keyframes_ = 1;
  mutable int keyframe_ = -1;
  mutable std::shared_ptr<const MeshCollider> current_;
  void build(int keyframe) const;
};

}  // namespace figment
