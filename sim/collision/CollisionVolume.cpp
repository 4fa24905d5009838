#include "sim/collision/CollisionVolume.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "sim/collision/MeshCollider.h"
#include "sim/collision/SurfaceProjection.h"
#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {
// Gauss-Newton steps on a mapped parametric surface: the map's stretch moves the answer
// farther from the start than the volumes' own fast paths (2-3 steps) expect.
constexpr int kMappedSteps = 5;
// How far the residual may lean off the normal (cosine against a tangent) before the
// answer counts as unconverged.
constexpr double kStationary = 1e-3;

// A SurfaceSample carried by an affine map.
SurfaceSample mapped(const Eigen::Affine3d& map, const SurfaceSample& s) {
  return {map * s.w, map.linear() * s.dt, map.linear() * s.da};
}

// Gauss-Newton from the start; where that stops short of a stationary point (near a
// capsule's pole, where the angle degenerates), Levenberg-Marquardt from there. A clamped
// t counts as stationary unless the ends are poles (a radial volume's rims are edges).
template <typename Sample>
SurfaceSample refineMapped(const Sample& sample, const Vec3& p, double tMin, double tMax, bool polesAtEnds, double& t,
                           double& a) {
  const SurfaceSample s = refineOnSurface(sample, p, tMin, tMax, t, a, kMappedSteps);
  const Vec3 r = s.w - p;
  const double gap = r.norm();
  const auto leans = [&](const Vec3& tangent) {
    const double length = tangent.norm();
    return length > 1e-12 && std::abs(r.dot(tangent)) > kStationary * length * gap;
  };
  const bool atEnd = t <= tMin || t >= tMax;
  if (gap < 1e-12 || (!(atEnd && polesAtEnds) && !leans(s.da) && (atEnd || !leans(s.dt)))) return s;
  projectOntoSurface(sample, p, tMin, tMax, t, a);
  return sample(t, a);
}

SurfacePoint fromSample(const SurfaceSample& s, const Vec3& p, bool inside, const Vec3& outwardHint,
                        const Vec3& fallback) {
  SurfacePoint out;
  out.point = s.w;
  const double gap = (p - s.w).norm();
  out.distance = inside ? -gap : gap;
  out.normal = !inside && gap > 1e-6 ? Vec3((p - s.w) / gap) : surfaceNormal(s, outwardHint, fallback);
  // Inside, the push-out from p to point + clearance normal must not move p sideways:
  // where the search stopped short of that, the normal is the way out from p.
  if (inside && gap > 1e-6 && sideways(p - s.w, out.normal) > kSideways) out.normal = (s.w - p) / gap;
  return out;
}

class CapsuleVolume final : public CollisionVolume {
 public:
  explicit CapsuleVolume(const CapsuleParameters& parameters) : capsule_(parameters) {
    centre_ = capsule_.fromUnit(Vec3::Zero());
    // As CapsuleCollider: the taper is bilinear, so the unit box's corners bound the image.
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 u(corner & 1 ? 0.5 : -0.5, corner & 2 ? 0.5 : -0.5, corner & 4 ? 0.5 : -0.5);
      radius_ = std::max(radius_, (capsule_.fromUnit(u) - centre_).norm());
    }
    axis_ = (capsule_.fromUnit(Vec3(0, 0.5, 0)) - capsule_.fromUnit(Vec3(0, -0.5, 0))).normalized();
    // The unit capsule lies in the unit cylinder (radius 1/2, y in [-1/2, 1/2]); the taper
    // and scale take a point of it at most (1/2) max(x (1 + |tx| / 2), z (1 + |tz| / 2))
    // from the axis, and the axis onto the segment of length y: a bounding cylinder.
    const CapsuleParameters& c = capsule_.parameters();
    halfHeight_ = 0.5 * c.y;
    axisRadius_ = 0.5 * std::max(c.x * (1.0 + 0.5 * std::abs(c.tx)), c.z * (1.0 + 0.5 * std::abs(c.tz)));
  }
  bool contains(const Vec3& p) const override { return capsule_.contains(p); }
  SurfacePoint nearest(const Vec3& p) const override { return capsule_.nearestFast(p); }
  Vec3 centre() const override { return centre_; }
  double boundingRadius() const override { return radius_; }
  BoundingCapsule boundingCapsule() const override {
    return {centre_ - halfHeight_ * axis_, centre_ + halfHeight_ * axis_, axisRadius_};
  }
  // The bounding cylinder's signed distance.
  double distanceBound(const Vec3& p) const override {
    const Vec3 q = p - centre_;
    const double h = q.dot(axis_);
    const double radial = (q - h * axis_).norm() - axisRadius_, axial = std::abs(h) - halfHeight_;
    if (axial > 0.0) return std::hypot(axial, std::max(radial, 0.0));
    return std::max(radial, axial);
  }

  SurfacePoint nearestUnder(const Eigen::Affine3d& map, const Eigen::Affine3d& inverse, const Vec3& p) const override {
    const Vec3 rest = inverse * p;
    const Vec3 unit = capsule_.toUnit(rest);
    const auto side = [&](double ti, double ai) { return mapped(map, capsule_.sample(ti, ai)); };
    // Two starts, the nearer result kept: the unit-space projection, and the rest
    // frame's own nearest point (inside, under a stretch, one of them can sit in a local
    // minimum far from the nearest point: a push-out there kicks the node).
    double t, a, tRest, aRest;
    parametersOf(capsule_.unitProjection(unit), t, a);
    parametersOf(capsule_.toUnit(capsule_.nearestFast(rest).point), tRest, aRest);
    SurfaceSample s = refineMapped(side, p, 0.0, 3.0, true, t, a);
    const SurfaceSample fromRest = refineMapped(side, p, 0.0, 3.0, true, tRest, aRest);
    if ((fromRest.w - p).squaredNorm() < (s.w - p).squaredNorm()) s = fromRest, t = tRest;
    const Vec3 pole = (inverse.linear().transpose() * (t < 1.5 ? -axis_ : axis_)).normalized();
    return fromSample(s, p, capsule_.containsUnit(unit), s.w - map * centre_, pole);
  }

 private:
  // (t, a) of a point q on the unit capsule's surface: Capsule's own starting guess.
  void parametersOf(const Vec3& q, double& t, double& a) const {
    const double r1 = capsule_.parameters().r1, r2 = capsule_.parameters().r2;
    const double bottom = -0.5 + 0.5 * r1, top = 0.5 - 0.5 * r2;
    a = std::atan2(q.z(), q.x());
    const double rho = std::sqrt(q.x() * q.x() + q.z() * q.z()) / 0.5;
    const double flat = std::sqrt(std::max(0.0, 1.0 - rho * rho));
    if (q.y() < bottom || (q.y() == bottom && rho < 1.0 && r1 <= 0.0))
      t = std::atan2(rho, r1 > 0.0 ? (bottom - q.y()) / (0.5 * r1) : flat) / (0.5 * M_PI);
    else if (q.y() > top || (q.y() == top && rho < 1.0 && r2 <= 0.0))
      t = 2.0 + std::atan2(r2 > 0.0 ? (q.y() - top) / (0.5 * r2) : flat, rho) / (0.5 * M_PI);
    else
      t = top > bottom ? 1.0 + (q.y() - bottom) / (top - bottom) : 1.5;
    t = std::clamp(t, 0.0, 3.0);
  }

  Capsule capsule_;
  Vec3 centre_, axis_;
  double radius_ = 0.0;
  double halfHeight_ = 0.0, axisRadius_ = 0.0;  // the bounding cylinder about axis_, m
};

class RadialVolume final : public CollisionVolume {
 public:
  explicit RadialVolume(const RadialDepthParameters& parameters) : volume_(parameters) {
    const RadialDepthParameters& q = volume_.parameters();
    centre_ = q.base + 0.5 * q.length * q.direction;
    // |r| <= |c0| + sum |ck| per section; between sections r interpolates linearly.
    double widest = 0.0;
    for (const auto& section : q.coefficients) {
      double bound = 0.0;
      for (double c : section) bound += std::abs(c);
      widest = std::max(widest, bound);
    }
    radius_ = std::hypot(0.5 * q.length, widest);
  }
  bool contains(const Vec3& p) const override { return volume_.contains(p); }
  SurfacePoint nearest(const Vec3& p) const override { return volume_.nearestFast(p); }
  Vec3 centre() const override { return centre_; }
  double boundingRadius() const override { return radius_; }
  BoundingCapsule boundingCapsule() const override {
    const RadialDepthParameters& q = volume_.parameters();
    return {q.base, q.base + q.length * q.direction, volume_.rMax()};
  }
  double distanceBound(const Vec3& p) const override { return volume_.distanceBound(p); }

  SurfacePoint nearestUnder(const Eigen::Affine3d& map, const Eigen::Affine3d& inverse, const Vec3& p) const override {
    const RadialDepthParameters& q = volume_.parameters();
    const Vec3 rest = inverse * p;
    double s, a, rho;
    volume_.toAxis(rest, s, a, rho);
    // The side, from the radial projection; then the caps, planes under any affine map:
    // p's foot on the mapped plane counts where it lies within the cap.
    double t = std::clamp(s, 0.0, q.length), angle = a;
    const auto side = [&](double ti, double ai) { return mapped(map, volume_.sample(ti, ai)); };
    // Two starts, the nearer result kept: the radial projection, and the rest frame's own
    // nearest side point (inside, under a stretch, one of them can sit in a local minimum
    // far from the nearest point: a push-out there kicks the node).
    SurfaceSample sample = refineMapped(side, p, 0.0, q.length, false, t, angle);
    double restS, restA, restRho;
    volume_.toAxis(volume_.nearestFast(rest).point, restS, restA, restRho);
    restS = std::clamp(restS, 0.0, q.length);
    const SurfaceSample fromRest = refineMapped(side, p, 0.0, q.length, false, restS, restA);
    if ((fromRest.w - p).squaredNorm() < (sample.w - p).squaredNorm()) sample = fromRest, t = restS;
    const bool inside = volume_.contains(rest);
    SurfacePoint out =
        fromSample(sample, p, inside, sample.w - map * (q.base + t * q.direction), map.linear() * q.direction);
    const Eigen::Matrix3d normalMap = inverse.linear().transpose();
    for (const double capS : {0.0, q.length}) {
      const Vec3 normal = (normalMap * (capS == 0.0 ? -q.direction : q.direction)).normalized();
      const double height = (p - map * (q.base + capS * q.direction)).dot(normal);
      const Vec3 foot = p - height * normal;
      double footS, footA, footRho;
      volume_.toAxis(inverse * foot, footS, footA, footRho);
      if (footRho > volume_.radius(capS, footA) || std::abs(height) >= std::abs(out.distance)) continue;
      out.point = foot;
      out.distance = inside ? -std::abs(height) : std::abs(height);
      out.normal = normal;
    }
    return out;
  }

 private:
  RadialDepth volume_;
  Vec3 centre_;
  double radius_ = 0.0;
};

class MeshVolume final : public CollisionVolume {
 public:
  explicit MeshVolume(TriangleMesh mesh) : collider_(checked(std::move(mesh)), OpenEdges::Outside) {
    const Bounds box = boundsOf(collider_.surface().vertices);
    centre_ = 0.5 * (box.min + box.max);
    for (const Vec3& v : collider_.surface().vertices) radius_ = std::max(radius_, (v - centre_).norm());
  }
  bool contains(const Vec3& p) const override { return nearest(p).distance < 0.0; }
  SurfacePoint nearest(const Vec3& p) const override {
    Contact c;
    collider_.contact(p, 0.0, std::numeric_limits<double>::infinity(), c);
    return {c.surfacePoint, c.normal, c.distance};
  }
  Vec3 centre() const override { return centre_; }
  double boundingRadius() const override { return radius_; }

  std::shared_ptr<const CollisionVolume> mappedCopy(const Eigen::Affine3d& map) const override {
    TriangleMesh mesh = collider_.surface();
    for (Vec3& v : mesh.vertices) v = map * v;
    if (map.linear().determinant() < 0.0)  // a mirror turns the winding inside out
      for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
    return std::make_shared<MeshVolume>(std::move(mesh));
  }

 private:
  static TriangleMesh checked(TriangleMesh mesh) {
    if (mesh.triangles.empty()) throw std::invalid_argument("partTriangles: no triangles");
    return mesh;
  }
  MeshCollider collider_;
  Vec3 centre_;
  double radius_ = 0.0;
};

// s when the linear part is s times a rotation (to 1e-12), else 0.
double similarityScale(const Eigen::Affine3d& map) {
  const Eigen::Matrix3d& a = map.linear();
  const Eigen::Matrix3d gram = a.transpose() * a;
  const double s2 = gram.trace() / 3.0;
  const bool similar = (gram - s2 * Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-12 * s2;
  return similar && a.determinant() > 0.0 ? std::sqrt(s2) : 0.0;
}

// A volume under an affine map: queries go to the rest frame and come back; a rotation
// with a uniform scale (height) maps the rest-frame answer exactly.
class MappedCollisionVolume final : public CollisionVolume {
 public:
  MappedCollisionVolume(std::shared_ptr<const CollisionVolume> rest, const Eigen::Affine3d& map)
      : rest_(std::move(rest)), map_(map), inverse_(map.inverse()), scale_(similarityScale(map)) {
    centre_ = map_ * rest_->centre();
    // The largest singular value stretches the bounding sphere the most.
    const Vec3 stretch = Eigen::JacobiSVD<Eigen::Matrix3d>(map_.linear()).singularValues();
    radius_ = rest_->boundingRadius() * stretch[0];
    largest_ = stretch[0], smallest_ = stretch[2];
    const BoundingCapsule c = rest_->boundingCapsule();
    capsule_ = {map_ * c.a, map_ * c.b, c.radius * largest_};
  }
  bool contains(const Vec3& p) const override { return rest_->contains(inverse_ * p); }
  SurfacePoint nearest(const Vec3& p) const override {
    if (!(scale_ > 0.0)) return rest_->nearestUnder(map_, inverse_, p);
    const SurfacePoint s = rest_->nearest(inverse_ * p);
    return {map_ * s.point, map_.linear() * s.normal / scale_, s.distance * scale_};
  }
  Vec3 centre() const override { return centre_; }
  double boundingRadius() const override { return radius_; }
  BoundingCapsule boundingCapsule() const override { return capsule_; }
  // A rest-frame gap g maps to at least smallest g outside (no segment shrinks more) and
  // a depth -g to at most largest (-g) inside.
  double distanceBound(const Vec3& p) const override {
    const double rest = rest_->distanceBound(inverse_ * p);
    return rest >= 0.0 ? smallest_ * rest : largest_ * rest;
  }

 private:
  std::shared_ptr<const CollisionVolume> rest_;
  Eigen::Affine3d map_, inverse_;
  double scale_;  // > 0: a rotation times this scale, which maps nearest points exactly
  Vec3 centre_;
  double radius_ = 0.0;
  double largest_ = 1.0, smallest_ = 1.0;  // the map's singular values
  BoundingCapsule capsule_;
};
}  // namespace

SurfacePoint CollisionVolume::nearestUnder(const Eigen::Affine3d& map, const Eigen::Affine3d& inverse,
                                           const Vec3& p) const {
  const SurfacePoint s = nearest(inverse * p);
  const Vec3 point = map * s.point;
  const double gap = (p - point).norm();
  return {point, (inverse.linear().transpose() * s.normal).normalized(), s.distance < 0.0 ? -gap : gap};
}

std::shared_ptr<const CollisionVolume> CollisionVolume::mappedCopy(const Eigen::Affine3d& /*map*/) const {
  return nullptr;
}

std::shared_ptr<const CollisionVolume> makeVolume(const CapsuleParameters& parameters) {
  return std::make_shared<CapsuleVolume>(parameters);
}

std::shared_ptr<const CollisionVolume> makeVolume(const RadialDepthParameters& parameters) {
  return std::make_shared<RadialVolume>(parameters);
}

std::shared_ptr<const CollisionVolume> makeVolume(TriangleMesh partTriangles) {
  return std::make_shared<MeshVolume>(std::move(partTriangles));
}

std::shared_ptr<const CollisionVolume> transformedVolume(std::shared_ptr<const CollisionVolume> volume,
                                                         const Eigen::Affine3d& transform) {
  if (!volume) throw std::invalid_argument("volume is null");
  const double det = transform.linear().determinant();
  if (!transform.matrix().allFinite() || !(std::abs(det) > 1e-12))
    throw std::invalid_argument("transform is singular: det = " + formatNumber(det));
  if (transform.matrix() == Eigen::Matrix4d::Identity()) return volume;
  if (!(similarityScale(transform) > 0.0))
    if (auto copy = volume->mappedCopy(transform)) return copy;
  return std::make_shared<MappedCollisionVolume>(std::move(volume), transform);
}

}  // namespace figment
