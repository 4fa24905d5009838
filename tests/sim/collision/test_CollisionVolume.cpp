// The collision volumes behind one interface: a capsule's and a closed mesh's inside and
// nearest point, and a volume carried into the world by a similarity (posing: a turn, a
// shift, a uniform scale), where the distance scales with it.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sim/collision/Capsule.h"
#include "sim/collision/CollisionVolume.h"
#include "support/BoxFigure.h"

using namespace figment;

namespace {

TEST(CollisionVolume, ACapsulesInsideAndNearestPoint) {
  const auto volume = makeVolume(CapsuleParameters{});  // radius 1/2 about the y axis at its middle
  EXPECT_TRUE(volume->contains(Vec3(0.3, 0, 0)));
  EXPECT_FALSE(volume->contains(Vec3(0.6, 0, 0)));
  const SurfacePoint s = volume->nearest(Vec3(0, 0, 1));
  EXPECT_NEAR(s.distance, 0.5, 1e-6);
  EXPECT_TRUE(s.point.isApprox(Vec3(0, 0, 0.5), 1e-6)) << s.point.transpose();
  EXPECT_TRUE(s.normal.isApprox(Vec3::UnitZ(), 1e-6));
  EXPECT_TRUE(volume->centre().isZero(1e-12));
}

TEST(CollisionVolume, AClosedMeshsInsideAndNearestPoint) {
  const auto cube = makeVolume(mannequin::boxMesh({{0, 0, 0}, {1, 1, 1}}));
  EXPECT_TRUE(cube->contains(Vec3(0.5, 0.5, 0.5)));
  EXPECT_FALSE(cube->contains(Vec3(1.5, 0.5, 0.5)));
  const SurfacePoint s = cube->nearest(Vec3(0.5, 0.5, 0.9));
  EXPECT_NEAR(s.distance, -0.1, 1e-12);  // inside, 0.1 m from the +z face
  EXPECT_TRUE(s.normal.isApprox(Vec3::UnitZ(), 1e-12));
  EXPECT_GE(cube->boundingRadius(), std::sqrt(3.0) / 2 - 1e-12);  // reaches every corner
  EXPECT_THROW(makeVolume(TriangleMesh{}), std::invalid_argument);
}

TEST(CollisionVolume, CarriedByASimilarityTheDistanceScales) {
  Eigen::Affine3d pose = Eigen::Affine3d::Identity();
  pose.translate(Vec3(0, 1, 0)).rotate(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())).scale(2.0);
  const auto moved = transformedVolume(makeVolume(CapsuleParameters{}), pose);
  // The capsule's axis now lies along x through (0, 1, 0), radius 1.
  EXPECT_TRUE(moved->contains(Vec3(0, 1.9, 0)));
  EXPECT_FALSE(moved->contains(Vec3(0, 2.1, 0)));
  const SurfacePoint s = moved->nearest(Vec3(0, 1, 3));
  EXPECT_NEAR(s.distance, 2.0, 1e-6);
  EXPECT_TRUE(s.point.isApprox(Vec3(0, 1, 1), 1e-6)) << s.point.transpose();
  Eigen::Affine3d flat = Eigen::Affine3d::Identity();
  flat.linear().setZero();  // singular: no inverse to answer through
  EXPECT_THROW(transformedVolume(makeVolume(CapsuleParameters{}), flat), std::invalid_argument);
}

}  // namespace
