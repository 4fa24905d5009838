// A skin in two poses carries points between them: on a limb turned rigidly (a cylinder
// turned 90 degrees about a joint, an arm raised), a point near the posed skin goes back
// exactly where it lay by the rest skin, at the same distance off it, and into the pose
// again; skins that do not match are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/fit/PosedSkin.h"
#include "support/FitTubes.h"

using namespace figment;

namespace {

// The rigid turn of the test: 90 degrees about z through (0, 0.5, 0), the cylinder's foot.
Vec3 turned(const Vec3& p) {
  const Vec3 joint(0, 0.5, 0);
  return joint + Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()) * (p - joint);
}

TriangleMesh turned(TriangleMesh mesh) {
  for (Vec3& p : mesh.vertices) p = turned(p);
  return mesh;
}

}  // namespace

TEST(PosedSkin, CarriesPointsOnATurnedLimbBackWhereTheyLay) {
  const TriangleMesh rest = test::cylinder(0.15);
  const PosedSkin skin(rest, turned(rest));
  // The tube 2 cm off the cylinder, and one on it: each point back where it was, to
  // rounding (the turn is rigid: every triangle's frame turns as the limb does).
  for (const double radius : {0.15, 0.17, 0.2}) {
    const TriangleMesh tube = test::tube(radius);
    const std::vector<Vec3> back = skin.toRest(turned(tube).vertices);
    ASSERT_EQ(back.size(), tube.vertices.size());
    for (size_t i = 0; i < back.size(); ++i) {
      EXPECT_NEAR((back[i] - tube.vertices[i]).norm(), 0.0, 1e-9) << radius << " " << i;
      EXPECT_NEAR((skin.toPosed(tube.vertices[i]) - turned(tube.vertices[i])).norm(), 0.0, 1e-9) << radius << " " << i;
    }
  }
}

TEST(PosedSkin, SkinsThatDoNotMatchAreRefused) {
  TriangleMesh rest = test::cylinder(0.15), posed = rest;
  posed.vertices.pop_back();
  // Refused by the skins' own check, before a tree is built over the shorter one (which read
  // past its end: the sanitizer job, 2026-12-03).
  try {
    PosedSkin skin(rest, posed);
    FAIL() << "a posed skin short of a vertex was taken";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()).rfind("posed skin: ", 0), 0u) << error.what();
  }
  posed = rest;
  std::swap(posed.triangles[0][1], posed.triangles[0][2]);
  EXPECT_THROW(PosedSkin(rest, posed), std::invalid_argument);
}
