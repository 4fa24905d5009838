// Keyframes of a moving surface, each an exact MeshCollider (building one is a BVH over
// the triangles: a few milliseconds for a body), and lower bounds that allow for the
// motion still to come.

#include "sim/collision/MovingMeshCollider.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace figment {

namespace {

double farthestMove(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.size() != b.size())
    throw std::invalid_argument("MovingMeshCollider: a shape has " + std::to_string(b.size()) + " vertices, not " +
                                std::to_string(a.size()));
  double farthest = 0.0;
  for (size_t i = 0; i < a.size(); ++i) farthest = std::max(farthest, (b[i] - a[i]).norm());
  return farthest;
}

}  // namespace

MovingMeshCollider::MovingMeshCollider(std::vector<Triangle> triangles, ShapeAt shapeAt, double duration,
                                       double maxStep, OpenEdges openEdges)
    : triangles_(std::move(triangles)), shapeAt_(std::move(shapeAt)), openEdges_(openEdges), duration_(duration) {
  if (!(duration >= 0.0)) throw std::invalid_argument("MovingMeshCollider: duration " + std::to_string(duration));
  if (!(maxStep > 0.0)) throw std::invalid_argument("MovingMeshCollider: maxStep " + std::to_string(maxStep));
  std::vector<Vec3> previous = shapeAt_(0.0);
  for (int k = 1; k <= kSamples; ++k) {
    std::vector<Vec3> next = shapeAt_(double(k) / kSamples);
    travel_ += farthestMove(previous, next);
    previous = std::move(next);
  }
  keyframes_ = std::max(1, int(std::ceil(travel_ / maxStep)));
  if (duration_ == 0.0) duration_ = travel_ / kSpeed;
  build(keyframes_);
}

void MovingMeshCollider::build(int keyframe) const {
  if (keyframe == keyframe_) return;
  std::vector<Vec3> vertices = shapeAt_(double(keyframe) / keyframes_);
  if (current_) {  // the same triangles: keep their edges' numbering
    current_ = std::make_shared<const MeshCollider>(*current_, std::move(vertices));
  } else {
    current_ = std::make_shared<const MeshCollider>(TriangleMesh{std::move(vertices), triangles_}, openEdges_);
  }
  keyframe_ = keyframe;
}

void MovingMeshCollider::advanceTo(double time) const {
  const double share = duration_ > 0.0 ? time / duration_ : 1.0;
  build(std::clamp(int(std::floor(share * keyframes_ + 1e-9)), 0, keyframes_));
}

bool MovingMeshCollider::contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const {
  if (keyframe_ >= keyframes_) return current_->contact(p, clearance, searchRadius, out);
  // Still moving: the rest of the motion, with room for the samples' underestimate of
  // each vertex's path, and one keyframe's jump.
  const double yetToMove = 1.25 * travel_ * (1.0 - double(keyframe_) / keyframes_) + travel_ / keyframes_;
  const bool touching = current_->contact(p, clearance, std::numeric_limits<double>::infinity(), out);
  if (!touching) out.distance = std::max(0.0, out.distance - yetToMove);
  return touching;
}

}  // namespace figment
