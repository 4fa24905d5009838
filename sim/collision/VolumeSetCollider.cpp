#include "sim/collision/VolumeSetCollider.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace figment {

namespace {
// Touching: d < clearance - kTouchMargin; clear: d >= clearance - kClearMargin. Clear is
// the stricter of the two, so a node set on a target (rounded) touches nothing; the touch
// margin also covers the fast paths' convergence noise (nanometres) in the target's
// distance to its own volume, which is not searched again.
constexpr double kTouchMargin = 1e-7;    // m
constexpr double kClearMargin = 0.5e-9;  // m
constexpr int kMaxCandidates = 8;        // a node touches a few volumes at most: keep the nearest
constexpr int kCreasePushes = 16;
constexpr int kMarchSteps = 64;  // doubling steps from >= 0.1 mm: beyond any body

struct Candidate {
  size_t volume = 0;
  SurfacePoint s;
};
}  // namespace

VolumeSetCollider::VolumeSetCollider(std::vector<PosedCollisionVolume> volumes) {
  for (size_t i = 0; i < volumes.size(); ++i) {
    PosedCollisionVolume& v = volumes[i];
    const std::string which = "volume " + std::to_string(i) + " (part " + std::to_string(v.part) + ")";
    if (!v.volume) throw std::invalid_argument(which + " is null");
    std::shared_ptr<const CollisionVolume> world;
    try {
      world = transformedVolume(std::move(v.volume), v.transform);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(which + ": " + e.what());
    }
    parts_.push_back(v.part);
    reach_.emplace_back(world->boundingCapsule());
    world_.push_back(std::move(world));
  }
}

std::shared_ptr<const Collider> VolumeSetCollider::focusedOn(const Eigen::AlignedBox3d& region, double reach) const {
  std::shared_ptr<VolumeSetCollider> focused(
      new VolumeSetCollider(std::vector<PosedCollisionVolume>{}));  // filled below
  for (size_t i = 0; i < world_.size(); ++i) {
    const BoundingCapsule c = world_[i]->boundingCapsule();
    const Vec3 grow = Vec3::Constant(c.radius);
    const Eigen::AlignedBox3d box(c.a.cwiseMin(c.b) - grow, c.a.cwiseMax(c.b) + grow);
    // The gap between the boxes, per axis: no point of one is nearer the other.
    const Vec3 gap = (region.min() - box.max()).cwiseMax(box.min() - region.max()).cwiseMax(0.0);
    if (gap.norm() >= reach) continue;
    focused->parts_.push_back(parts_[i]);
    focused->world_.push_back(world_[i]);
    focused->reach_.push_back(reach_[i]);
  }
  if (focused->world_.size() == world_.size()) return nullptr;
  return focused;
}

std::vector<int> VolumeSetCollider::partsWithin(const std::vector<Vec3>& points, double distance) const {
  std::vector<int> parts;
  for (size_t i = 0; i < world_.size(); ++i) {
    if (std::find(parts.begin(), parts.end(), parts_[i]) != parts.end()) continue;
    for (const Vec3& x : points)
      if (!beyond(i, x, distance) && world_[i]->nearest(x).distance < distance) {
        parts.push_back(parts_[i]);
        break;
      }
  }
  std::sort(parts.begin(), parts.end());
  return parts;
}

VolumeSetCollider::Reach::Reach(const BoundingCapsule& c)
    : a(c.a), ab(c.b - c.a), inverseLength2(ab.squaredNorm() > 0.0 ? 1.0 / ab.squaredNorm() : 0.0), radius(c.radius) {}

double VolumeSetCollider::Reach::squaredAxisDistance(const Vec3& p) const {
  const Vec3 ap = p - a;
  const double t = std::clamp(ap.dot(ab) * inverseLength2, 0.0, 1.0);
  return (ap - t * ab).squaredNorm();
}

bool VolumeSetCollider::Reach::beyond(const Vec3& p, double gap) const {
  const double reach = radius + gap;
  return reach <= 0.0 || squaredAxisDistance(p) >= reach * reach;
}

bool VolumeSetCollider::beyond(size_t i, const Vec3& x, double gap) const {
  return reach_[i].beyond(x, gap) || world_[i]->distanceBound(x) >= gap;
}

bool VolumeSetCollider::clearOfAll(const Vec3& x, double clearance, size_t own, const Measured& measured,
                                   double moved) const {
  const double clear = clearance - kClearMargin;
  for (size_t i = 0; i < world_.size(); ++i) {
    if (i == own) {
      if (world_[i]->contains(x)) return false;
      continue;
    }
    if (reach_[i].beyond(x, clear)) continue;
    // Bounded or measured at p, `moved` from x: a distance function changes no faster.
    const double* d = measured.find(i);
    if (d && *d - moved >= clear) continue;
    if (world_[i]->distanceBound(x) >= clear) continue;
    if (world_[i]->nearest(x).distance < clear) return false;
  }
  return true;
}

bool VolumeSetCollider::contact(const Vec3& p, double clearance, double /*searchRadius*/, Contact& out) const {
  const double touch = clearance - kTouchMargin, clear = clearance - kClearMargin;
  std::array<Candidate, kMaxCandidates> candidates;
  int count = 0;
  bool inside = false;
  Measured measured;  // not touching: their bounds or distances
  for (size_t i = 0; i < world_.size(); ++i) {
    // The cheap lower bounds first: the bounding capsule, then the volume's own; they
    // decide only where they show the volume clear (so a target, clear by a search of
    // its volumes, reports a distance of at least the clearance less kClearMargin).
    if (reach_[i].beyond(p, clear)) continue;
    const double bound = world_[i]->distanceBound(p);
    if (bound >= clear) {
      measured.add(i, bound);
      continue;
    }
    const SurfacePoint s = world_[i]->nearest(p);
    if (s.distance >= touch) {
      measured.add(i, s.distance);
      continue;
    }
    inside = inside || s.distance < 0.0;
    // Insert by |d| (after equals: ties go to the first volume); the farthest falls off.
    int at = std::min(count, kMaxCandidates - 1);
    if (count == kMaxCandidates && std::abs(s.distance) >= std::abs(candidates[at].s.distance)) continue;
    while (at > 0 && std::abs(candidates[at - 1].s.distance) > std::abs(s.distance)) {
      candidates[at] = candidates[at - 1];
      --at;
    }
    candidates[at] = {i, s};
    count = std::min(count + 1, kMaxCandidates);
  }
  if (count == 0) {
    out.distance = lowerBound(p, clear, measured);
    return false;
  }
  for (int k = 0; k < count; ++k) {
    const SurfacePoint& s = candidates[k].s;
    const Vec3 target = s.point + clearance * s.normal;
    if (!clearOfAll(target, clearance, candidates[k].volume, measured, (target - p).norm())) continue;
    out = {s.point, s.normal, inside ? -std::abs(s.distance) : std::abs(s.distance)};
    return true;
  }
  // A crease: every volume's own target lies in (or too near) another volume.
  const SurfacePoint& nearest = candidates[0].s;
  const Vec3 target = creaseTarget(p, nearest.point + clearance * nearest.normal, nearest.normal, clearance);
  const Vec3 move = target - p;
  out.normal = move.norm() > 1e-12 ? Vec3(move.normalized()) : nearest.normal;
  out.surfacePoint = target - clearance * out.normal;
  const double gap = (p - out.surfacePoint).norm();
  out.distance = inside ? -gap : gap;
  return true;
}

double VolumeSetCollider::lowerBound(const Vec3& p, double clear, const Measured& measured) const {
  // Each volume's bounding-capsule gap, or what contact() found: its own bound or its
  // distance (or, past kMeasured of them, the same again).
  double bound = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < world_.size(); ++i) {
    double gap = std::sqrt(reach_[i].squaredAxisDistance(p)) - reach_[i].radius;
    if (gap < clear) {
      const double* d = measured.find(i);
      if (d)
        gap = *d;
      else if ((gap = world_[i]->distanceBound(p)) < clear)
        gap = world_[i]->nearest(p).distance;
    }
    bound = std::min(bound, gap);
  }
  return bound;
}

Vec3 VolumeSetCollider::creaseTarget(const Vec3& p, const Vec3& start, const Vec3& away, double clearance) const {
  Vec3 x = start;
  const double kFar = std::numeric_limits<double>::infinity();
  for (int push = 0; push < kCreasePushes; ++push) {
    // The two volumes x is deepest in (or nearest within the clearance of).
    SurfacePoint first{Vec3::Zero(), Vec3::Zero(), kFar}, second = first;
    for (size_t i = 0; i < world_.size(); ++i) {
      if (beyond(i, x, clearance - kClearMargin)) continue;
      const SurfacePoint s = world_[i]->nearest(x);
      if (s.distance >= clearance - kClearMargin) continue;
      if (s.distance < first.distance)
        second = first, first = s;
      else if (s.distance < second.distance)
        second = s;
    }
    if (first.distance == kFar) return x;
    // Out past each tangent plane by the clearance: delta . n >= h. A convex volume lies
    // behind its tangent plane, so that clears it.
    const Vec3 &na = first.normal, &nb = second.normal;
    const double ha = clearance - (x - first.point).dot(na);
    if (second.distance == kFar) {
      x += ha * na;
      continue;
    }
    const double hb = clearance - (x - second.point).dot(nb);
    if ((ha * na).dot(nb) >= hb) {
      x += ha * na;
    } else if ((hb * nb).dot(na) >= ha) {
      x += hb * nb;
    } else {
      // Both planes: the shortest step in their normals' span.
      const double cosine = na.dot(nb), det = 1.0 - cosine * cosine;
      if (det < 1e-9) break;  // facing planes (a gap narrower than twice the clearance)
      x += (ha - cosine * hb) / det * na + (hb - cosine * ha) / det * nb;
    }
  }
  // Away from p until clear: the volumes are bounded, so this ends.
  Vec3 direction = x - p;
  direction = direction.norm() > 1e-12 ? Vec3(direction.normalized()) : away;
  double step = std::max(clearance, 1e-4);
  for (int k = 0; k < kMarchSteps && !clearOfAll(x, clearance, kNone, Measured{}, 0.0); ++k, step *= 2.0)
    x += step * direction;
  return x;
}

}  // namespace figment
