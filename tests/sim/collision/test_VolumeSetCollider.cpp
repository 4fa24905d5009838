// Posed part volumes (sim/collision/CollisionVolume.h) and the mannequin as their union
// (sim/collision/VolumeSetCollider.h): mapped queries against dense sampling of the mapped surface,
// and the overlap rule at a bent elbow.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "sim/collision/CollisionVolume.h"
#include "sim/collision/MeshCollider.h"
#include "sim/collision/VolumeSetCollider.h"
#include "support/TestCapsules.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

using test::segmentCapsule;

// A stretched, rotated, moved frame: what sizing and posing make of a part.
Eigen::Affine3d stretchedMap() {
  Eigen::Affine3d map = Eigen::Affine3d::Identity();
  map.linear() = Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix() *
                 Vec3(1.25, 0.85, 1.1).asDiagonal() *
                 Eigen::AngleAxisd(-0.3, Vec3(0, 1, 1).normalized()).toRotationMatrix();
  map.translation() = Vec3(0.1, -0.2, 0.3);
  return map;
}

// A shape's surface samples (point and tangents) carried through `map`.
template <class Shape>
auto mappedSurface(const Shape& shape, const Eigen::Affine3d& map) {
  return [&shape, map](double t, double a) {
    const SurfaceSample x = shape.sample(t, a);
    return SurfaceSample{map * x.w, map.linear() * x.dt, map.linear() * x.da};
  };
}

Eigen::Affine3d scaling(double x, double y, double z) {
  Eigen::Affine3d map = Eigen::Affine3d::Identity();
  map.linear() = Vec3(x, y, z).asDiagonal();
  return map;
}

// The bent elbow: an upper arm along +x, a forearm bent 90 degrees up at the elbow.
struct Elbow {
  Capsule upper{segmentCapsule(Vec3::Zero(), Vec3(0.3, 0, 0), 0.05)};
  Capsule fore{segmentCapsule(Vec3(0.3, 0, 0), Vec3(0.55, 0, 0), 0.045)};  // rest: straight on
  Eigen::Affine3d bend =
      Eigen::Translation3d(0.3, 0, 0) * Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()) * Eigen::Translation3d(-0.3, 0, 0);
  VolumeSetCollider collider{
      {{0, makeVolume(upper.parameters()), Eigen::Affine3d::Identity()}, {1, makeVolume(fore.parameters()), bend}}};
  // Exact (Levenberg-Marquardt) signed distances to each volume in world space.
  double upperDistance(const Vec3& p) const { return upper.nearest(p).distance; }
  double foreDistance(const Vec3& p) const { return fore.nearest(bend.inverse() * p).distance; }
  bool inside(const Vec3& p) const { return upper.contains(p) || fore.contains(bend.inverse() * p); }
};

Vec3 randomIn(std::mt19937& rng, const Vec3& low, const Vec3& high) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  return low + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(high - low);
}

Vec3 randomDirection(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Vec3(g(rng), g(rng), g(rng)).normalized();
}

// A dense grid of a mapped surface's side: `steps` + 1 rows over t in [0, tMax] by
// `angles` columns; each point and its (t, a) appended.
template <typename Sample>
void sampleGrid(const Sample& sample, double tMax, int steps, int angles, std::vector<Vec3>& samples,
                std::vector<std::array<double, 2>>& parameters) {
  for (int i = 0; i <= steps; ++i)
    for (int j = 0; j < angles; ++j) {
      const double t = tMax * i / steps, a = 2 * M_PI * j / angles;
      samples.push_back(sample(t, a).w);
      parameters.push_back({t, a});
    }
}

// Checks `volume` (a mapped parametric surface) against `samples` of that surface: within
// 0.2 mm of the best sample and of the sample's refinement; on the surface; normal
// perpendicular to the refined tangents and pointing out.
template <typename Sample>
void expectNearestMatchesSampling(const CollisionVolume& volume, const std::vector<Vec3>& samples,
                                  const std::vector<std::array<double, 2>>& parameters, const Sample& sample,
                                  double tMin, double tMax, const std::vector<Vec3>& queries) {
  int perpendicularChecks = 0;
  for (const Vec3& p : queries) {
    size_t best = 0;
    double bestGap = kInf;
    for (size_t i = 0; i < samples.size(); ++i)
      if ((samples[i] - p).squaredNorm() < bestGap) bestGap = (samples[i] - p).squaredNorm(), best = i;
    bestGap = std::sqrt(bestGap);
    const SurfacePoint s = volume.nearest(p);
    EXPECT_EQ(s.distance < 0.0, volume.contains(p));
    EXPECT_LE(std::abs(s.distance), bestGap + 2e-4) << p.transpose();
    EXPECT_NEAR(std::abs(s.distance), (p - s.point).norm(), 1e-12);
    // Refine the best sample (when it is a parametric one) for a tighter reference.
    if (best < parameters.size()) {
      double t = parameters[best][0], a = parameters[best][1];
      const Vec3 reference = projectOntoSurface(sample, p, tMin, tMax, t, a);
      EXPECT_LE(std::abs(s.distance), (p - reference).norm() + 2e-4);
      const SurfaceSample at = sample(t, a);
      if ((reference - s.point).norm() < 1e-5 && at.dt.norm() > 1e-3 && at.da.norm() > 1e-3 && t > tMin + 1e-3 &&
          t < tMax - 1e-3) {
        EXPECT_LT(std::abs(s.normal.dot(at.dt.normalized())), 2e-3);
        EXPECT_LT(std::abs(s.normal.dot(at.da.normalized())), 2e-3);
        ++perpendicularChecks;
      }
    }
    EXPECT_NEAR(s.normal.norm(), 1.0, 1e-12);
    EXPECT_FALSE(volume.contains(s.point + 1e-4 * s.normal)) << p.transpose();
    EXPECT_TRUE(volume.contains(s.point - 1e-4 * s.normal)) << p.transpose();
  }
  EXPECT_GT(perpendicularChecks, static_cast<int>(queries.size()) / 2);
}
}  // namespace

TEST(CollisionVolume, RigidAndUniformlyScaledMapsAreExact) {
  // A rotation and a move (posing), then also a uniform scale (height): the mapped answer
  // is the rest-frame answer, mapped, its distance scaled.
  CapsuleParameters c = segmentCapsule(Vec3(0, 0, 0), Vec3(0, 0.3, 0), 0.05);
  c.tx = 0.3;
  const auto rest = makeVolume(c);
  for (const double scale : {1.0, 1.1}) {
    const Eigen::Affine3d map = Eigen::Translation3d(0.2, 1.0, -0.1) *
                                Eigen::AngleAxisd(1.1, Vec3(1, 1, 0).normalized()) * Eigen::Scaling(scale);
    const auto world = transformedVolume(rest, map);
    std::mt19937 rng(3);
    for (int i = 0; i < 200; ++i) {
      const Vec3 p = randomIn(rng, Vec3(-0.1, 0.8, -0.3), Vec3(0.5, 1.3, 0.2));
      const SurfacePoint r = rest->nearest(map.inverse() * p), w = world->nearest(p);
      EXPECT_NEAR(w.distance, scale * r.distance, 1e-12);
      EXPECT_LT((w.point - map * r.point).norm(), 1e-12);
      EXPECT_LT((w.normal - map.linear() * r.normal / scale).norm(), 1e-12);
      EXPECT_EQ(world->contains(p), rest->contains(map.inverse() * p));
    }
  }
  EXPECT_EQ(transformedVolume(rest, Eigen::Affine3d::Identity()), rest);  // identity: the volume itself
}

TEST(CollisionVolume, StretchedCapsuleMatchesDenseSampling) {
  CapsuleParameters c;
  c.r1 = 0.6, c.r2 = 0.9, c.tx = 0.2, c.tz = -0.1, c.x = 0.1, c.y = 0.35, c.z = 0.08;
  c.ox = 0.01, c.oy = 0.02, c.oz = -0.03, c.theta = 0.3, c.phi = 0.7;
  const Capsule capsule(c);
  const auto world = transformedVolume(makeVolume(c), stretchedMap());
  const auto sample = mappedSurface(capsule, stretchedMap());
  std::vector<Vec3> samples;
  std::vector<std::array<double, 2>> parameters;
  sampleGrid(sample, 3.0, 400, 250, samples, parameters);
  // Queries within 2 cm of the side.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> queries;
  for (int i = 0; i < 1000; ++i)
    queries.push_back(sample(3.0 * u(rng), 2 * M_PI * u(rng)).w + 0.02 * u(rng) * randomDirection(rng));
  expectNearestMatchesSampling(*world, samples, parameters, sample, 0.0, 3.0, queries);
}

TEST(CollisionVolume, StretchedRadialVolumeMatchesDenseSampling) {
  RadialDepthParameters r;
  r.base = Vec3(0.0, 0.1, 0.0);
  r.direction = Vec3(0.1, 1.0, 0.0);
  r.reference = Vec3(1.0, -0.1, 0.0);
  r.length = 0.3;
  r.harmonics = 2;
  r.coefficients = {{0.060, 0.008, 0.004, 0.005, -0.002},
                    {0.070, 0.006, -0.003, 0.004, 0.001},
                    {0.065, 0.004, 0.002, 0.006, 0.000},
                    {0.050, 0.002, 0.001, 0.003, 0.002}};
  const RadialDepth volume(r);
  const Eigen::Affine3d map = stretchedMap();
  const auto world = transformedVolume(makeVolume(r), map);
  const auto sample = mappedSurface(volume, map);
  std::vector<Vec3> samples;
  std::vector<std::array<double, 2>> parameters;
  sampleGrid(sample, r.length, 300, 250, samples, parameters);
  // The caps after the side: flat discs out to the rim.
  const Vec3 axis = volume.parameters().direction, reference = volume.parameters().reference;
  const Vec3 side = axis.cross(reference);
  for (const double s : {0.0, r.length})
    for (int i = 0; i < 60; ++i)
      for (int j = 0; j < 200; ++j) {
        const double a = 2 * M_PI * j / 200, rho = volume.radius(s, a) * i / 60;
        samples.push_back(map * (r.base + s * axis + rho * (std::cos(a) * reference + std::sin(a) * side)));
      }
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> queries;
  for (int i = 0; i < 1000; ++i)
    queries.push_back(samples[static_cast<size_t>(u(rng) * samples.size()) % samples.size()] +
                      0.02 * u(rng) * randomDirection(rng));
  expectNearestMatchesSampling(*world, samples, parameters, sample, 0.0, r.length, queries);
}

TEST(CollisionVolume, StretchedMeshIsRebuiltExactly) {
  const TriangleMesh sphere = meshes::sphere(0.1, 24, 12);
  const Eigen::Affine3d map = stretchedMap();
  TriangleMesh mapped = sphere;
  for (Vec3& v : mapped.vertices) v = map * v;
  const MeshCollider reference(mapped);
  const auto world = transformedVolume(makeVolume(sphere), map);
  std::mt19937 rng(5);
  for (int i = 0; i < 300; ++i) {
    const Vec3 p = map * Vec3::Zero() + randomIn(rng, Vec3::Constant(-0.2), Vec3::Constant(0.2));
    Contact c;
    reference.contact(p, 0.0, kInf, c);
    const SurfacePoint s = world->nearest(p);
    EXPECT_NEAR(s.distance, c.distance, 1e-12);
    EXPECT_LT((s.point - c.surfacePoint).norm(), 1e-12);
    EXPECT_EQ(world->contains(p), c.distance < 0.0);
  }
  EXPECT_THROW(makeVolume(TriangleMesh{}), std::invalid_argument);
}

TEST(CollisionVolume, BoundingSphereEnclosesTheMappedVolume) {
  const CapsuleParameters c = segmentCapsule(Vec3::Zero(), Vec3(0, 0.3, 0), 0.05);
  const auto world = transformedVolume(makeVolume(c), stretchedMap());
  const Capsule capsule(c);
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j < 60; ++j) {
      const Vec3 p = stretchedMap() * capsule.surface(3.0 * i / 60, 2 * M_PI * j / 60);
      EXPECT_LE((p - world->centre()).norm(), world->boundingRadius() + 1e-12);
    }
  EXPECT_THROW(transformedVolume(world, scaling(1.0, 0.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(transformedVolume(nullptr, Eigen::Affine3d::Identity()), std::invalid_argument);
}

TEST(VolumeSetCollider, EmptySetIsNeverInContact) {
  const VolumeSetCollider none({});
  Contact c;
  EXPECT_FALSE(none.contact(Vec3::Zero(), 0.003, 0.05, c));
  EXPECT_EQ(c.distance, kInf);
}

TEST(VolumeSetCollider, PointInsideOneVolumeGetsThatVolumesContact) {
  const Elbow elbow;
  std::mt19937 rng(1);
  const double clearance = 0.003;
  int tested = 0;
  while (tested < 300) {
    // Inside the upper arm, well away from the elbow.
    const Vec3 p = randomIn(rng, Vec3(-0.05, -0.05, -0.05), Vec3(0.15, 0.05, 0.05));
    if (!elbow.upper.contains(p)) continue;
    ++tested;
    Contact c;
    ASSERT_TRUE(elbow.collider.contact(p, clearance, 0.05, c));
    const SurfacePoint s = elbow.collider.worldVolume(0).nearest(p);
    EXPECT_EQ(c.distance, s.distance);
    EXPECT_EQ(c.surfacePoint, s.point);
    EXPECT_EQ(c.normal, s.normal);
  }
}

TEST(VolumeSetCollider, PointsInsideTheElbowEndOutsideBothVolumesWithoutJitter) {
  const Elbow elbow;
  std::mt19937 rng(2);
  const double clearance = 0.003;
  int inside = 0, crease = 0;
  while (inside < 2000) {
    const Vec3 p = randomIn(rng, Vec3(-0.06, -0.06, -0.06), Vec3(0.36, 0.31, 0.06));
    if (!elbow.inside(p)) continue;
    ++inside;
    Contact c;
    ASSERT_TRUE(elbow.collider.contact(p, clearance, 0.05, c)) << p.transpose();
    EXPECT_LT(c.distance, 0.0);
    EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
    const Vec3 target = c.surfacePoint + clearance * c.normal;
    EXPECT_GE(elbow.upperDistance(target), clearance - 1e-9) << p.transpose();
    EXPECT_GE(elbow.foreDistance(target), clearance - 1e-9) << p.transpose();
    // A fixed point: the node set on its target is left there.
    Contact again;
    EXPECT_FALSE(elbow.collider.contact(target, clearance, 0.05, again)) << p.transpose();
    EXPECT_GE(again.distance, clearance - 1e-9);
    // Neither volume's own push-out: the crease search answered.
    const bool fromUpper = (c.surfacePoint - elbow.collider.worldVolume(0).nearest(p).point).norm() < 1e-12;
    const bool fromFore = (c.surfacePoint - elbow.collider.worldVolume(1).nearest(p).point).norm() < 1e-12;
    crease += !fromUpper && !fromFore;
    // Pure: the same point, the same answer.
    Contact repeat;
    elbow.collider.contact(p, clearance, 0.05, repeat);
    EXPECT_EQ(repeat.surfacePoint, c.surfacePoint);
  }
  EXPECT_GT(crease, 0);  // the inner corner of the elbow takes the crease search
}

TEST(VolumeSetCollider, CreaseTargetsAreNearTheInnerCorner) {
  // Just inside the inner corner of the bend, in both volumes: the target lies in the
  // fold, clear of both, and not far (no escape to the far side of a volume).
  const Elbow elbow;
  const Vec3 p(0.265, 0.045, 0.0);
  ASSERT_TRUE(elbow.upper.contains(p));
  ASSERT_TRUE(elbow.fore.contains(elbow.bend.inverse() * p));
  Contact c;
  ASSERT_TRUE(elbow.collider.contact(p, 0.003, 0.05, c));
  const Vec3 target = c.surfacePoint + 0.003 * c.normal;
  EXPECT_GE(elbow.upperDistance(target), 0.003 - 1e-9);
  EXPECT_GE(elbow.foreDistance(target), 0.003 - 1e-9);
  EXPECT_LT((target - p).norm(), 0.02);
}

TEST(VolumeSetCollider, DistanceIsALowerBoundWhenNothingTouches) {
  const Elbow elbow;
  std::mt19937 rng(4);
  const double clearance = 0.003;
  int outside = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 p = randomIn(rng, Vec3(-0.3, -0.3, -0.3), Vec3(0.7, 0.6, 0.3));
    const double exact = std::min(elbow.upperDistance(p), elbow.foreDistance(p));
    Contact c;
    if (elbow.collider.contact(p, clearance, 0.05, c)) {
      EXPECT_LT(exact, clearance + 1e-9);
      continue;
    }
    ++outside;
    EXPECT_GE(exact, clearance - 1e-9);
    EXPECT_LE(c.distance, exact + 1e-9) << p.transpose();
  }
  EXPECT_GT(outside, 2000);
}

TEST(VolumeSetCollider, RejectsNullVolumesAndSingularTransforms) {
  EXPECT_THROW(VolumeSetCollider({{0, nullptr, Eigen::Affine3d::Identity()}}), std::invalid_argument);
  const auto volume = makeVolume(CapsuleParameters{});
  EXPECT_THROW(VolumeSetCollider({{3, volume, scaling(0.0, 1.0, 1.0)}}), std::invalid_argument);
}

TEST(VolumeSetCollider, DeepPointsArePushedStraightOut) {
  // A garment may start with nodes centimetres inside fitted capsules (tapered, wider
  // than deep), posed by a stretch: the contact's push-out p -> surfacePoint + clearance
  // normal runs along the normal, since the solver takes it into velocity (a sideways
  // millimetre in a 0.15 ms step is 7 m/s).
  CapsuleParameters c;
  c.r1 = 0.5, c.r2 = 0.7, c.tx = -0.35, c.tz = 0.1;
  c.x = 0.16, c.y = 0.32, c.z = 0.11;
  c.theta = 0.4, c.phi = -0.8;
  const double clearance = 0.006;
  for (const Eigen::Affine3d& map : {Eigen::Affine3d(Eigen::Translation3d(0, 1, 0)), stretchedMap()}) {
    const VolumeSetCollider collider({{0, makeVolume(c), map}});
    std::mt19937 rng(8);
    int inside = 0;
    for (int i = 0; i < 3000; ++i) {
      const Vec3 p = map * randomIn(rng, Vec3(-0.1, -0.2, -0.07), Vec3(0.1, 0.2, 0.07));
      if (!collider.worldVolume(0).contains(p)) continue;
      ++inside;
      Contact contact;
      ASSERT_TRUE(collider.contact(p, clearance, kInf, contact));
      const Vec3 push = contact.surfacePoint + clearance * contact.normal - p;
      EXPECT_LT((push - push.dot(contact.normal) * contact.normal).norm(), kSideways + 1e-12) << p.transpose();
    }
    EXPECT_GT(inside, 500);
  }
}

TEST(VolumeSetCollider, PartsWithinADistanceOfAGarment) {
  // Three parts along x, 0.3 m apart; a garment's nodes about the middle one.
  std::vector<PosedCollisionVolume> volumes;
  for (int part = 0; part < 3; ++part)
    volumes.push_back({10 + part, makeVolume(segmentCapsule(Vec3(0.3 * part, 0, 0), Vec3(0.3 * part, 0.2, 0), 0.05)),
                       Eigen::Affine3d::Identity()});
  volumes.push_back({11, makeVolume(segmentCapsule(Vec3(0.3, 0.2, 0), Vec3(0.3, 0.4, 0), 0.05)),
                     Eigen::Affine3d::Identity()});  // a second volume of the middle part
  const VolumeSetCollider set(std::move(volumes));
  const std::vector<Vec3> garment = {Vec3(0.3, 0.1, 0.06), Vec3(0.3, 0.3, -0.065)};
  EXPECT_EQ(set.partsWithin(garment, 0.02), std::vector<int>{11});
  EXPECT_EQ(set.partsWithin(garment, 0.005), std::vector<int>{}) << "the nearest node is 1 cm out";
  EXPECT_EQ(set.partsWithin(garment, 0.3), (std::vector<int>{10, 11, 12}));
}
