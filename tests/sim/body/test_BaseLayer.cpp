// The base layer cut from a skin, on a prism standing in for a trunk (its lower part the
// thighs' by the parts), where every bound's effect can be computed exactly: the flat side
// faces make the band's area the prism's perimeter times its height.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "sim/body/BaseLayer.h"

using namespace figment;

namespace {

constexpr int kSides = 24, kRings = 41;
constexpr double kRadius = 0.15, kBottom = 0.5, kTop = 1.5;

// An open prism about the y axis, CCW seen from outside; parts by the triangle's middle:
// the trunk above y = 0.8, else a thigh by the side of x.
struct Prism {
  TriangleMesh mesh;
  std::vector<int> parts;
  BodyLandmarks landmarks{.crotch = 0.8, .hip = 0.9, .waist = 1.05, .underbust = 1.2, .bust = 1.28, .armpit = 1.38};
};

Prism prism() {
  Prism p;
  for (int r = 0; r < kRings; ++r)
    for (int s = 0; s < kSides; ++s) {
      const double a = 2 * std::numbers::pi * s / kSides;
      p.mesh.vertices.emplace_back(kRadius * std::sin(a), kBottom + (kTop - kBottom) * r / (kRings - 1),
                                   kRadius * std::cos(a));
    }
  auto at = [](int r, int s) { return r * kSides + (s % kSides); };
  for (int r = 0; r + 1 < kRings; ++r)
    for (int s = 0; s < kSides; ++s) {
      p.mesh.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s + 1)});
      p.mesh.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r + 1, s)});
    }
  for (const Triangle& t : p.mesh.triangles) {
    const Vec3 middle =
        (p.mesh.vertices[size_t(t[0])] + p.mesh.vertices[size_t(t[1])] + p.mesh.vertices[size_t(t[2])]) / 3;
    p.parts.push_back(middle.y() > 0.8 ? 0 : (middle.x() > 0 ? 8 : 9));
  }
  return p;
}

double area(const TriangleMesh& mesh, double fromY, double toY) {
  double sum = 0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[size_t(t[0])], &b = mesh.vertices[size_t(t[1])], &c = mesh.vertices[size_t(t[2])];
    const double y = (a.y() + b.y() + c.y()) / 3;
    if (y > fromY && y < toY) sum += 0.5 * (b - a).cross(c - a).norm();
  }
  return sum;
}

// Whether `p` lies on one of the bounds' planes (within 1e-9 m).
bool onABound(const Vec3& p, const BaseLayerBounds& b) {
  const double leg = b.legBottom + b.legSlope * std::abs(p.x() - b.centreX);
  for (double level : {b.briefsTop, b.bandBottom, b.bandTop})
    if (std::abs(p.y() - level) < 1e-9) return true;
  return std::abs(p.y() - leg) < 1e-9;
}

// The layer cut on the skin itself (not lifted), and the bounds it was cut to.
struct OnTheSkin {
  BaseLayerBounds bounds;
  TriangleMesh layer;
};
OnTheSkin cutOnTheSkin(const Prism& p) {
  BaseLayerShape shape;
  shape.offset = 0;
  const BaseLayerBounds b = baseLayerBounds(p.mesh, p.parts, p.landmarks, shape);
  return {b, cutBaseLayer(p.mesh, p.mesh, p.parts, b, shape)};
}

}  // namespace

TEST(BaseLayer, BoundsFollowTheLandmarksAndTheHipsWidth) {
  const Prism p = prism();
  const BaseLayerBounds b = baseLayerBounds(p.mesh, p.parts, p.landmarks, {});
  EXPECT_NEAR(b.centreX, 0, 1e-12);
  EXPECT_NEAR(b.briefsTop, 0.95, 1e-12);  // a third of the way from hip to waist
  EXPECT_NEAR(b.legBottom, 0.785, 1e-12);
  EXPECT_NEAR(b.legSlope, (0.9 - 0.785) / kRadius, 1e-9);  // the prism's widest vertex is at x = R
  EXPECT_NEAR(b.bandBottom, 1.18, 1e-12);
  EXPECT_NEAR(b.bandTop, 1.33, 1e-12);
}

TEST(BaseLayer, TheBandIsTheSkinBetweenItsLevelsExactly) {
  const auto [b, layer] = cutOnTheSkin(prism());
  const double perimeter = 2 * kSides * kRadius * std::sin(std::numbers::pi / kSides);
  EXPECT_NEAR(area(layer, b.bandBottom - 1e-9, b.bandTop + 1e-9), perimeter * (b.bandTop - b.bandBottom), 1e-9);
  // Between hip level and the briefs' top nothing is cut away either.
  EXPECT_NEAR(area(layer, 0.9, b.briefsTop + 1e-9), perimeter * (b.briefsTop - 0.9), 1e-3 * perimeter * 0.05);
  for (const Vec3& v : layer.vertices) {
    const bool inBriefs = v.y() <= b.briefsTop + 1e-9 && v.y() >= b.legBottom + b.legSlope * std::abs(v.x()) - 1e-9;
    const bool inBand = v.y() >= b.bandBottom - 1e-9 && v.y() <= b.bandTop + 1e-9;
    EXPECT_TRUE(inBriefs || inBand) << v.transpose();
  }
  double lowestAtTheMiddle = 1e9, highest = 0;
  for (const Vec3& v : layer.vertices) {
    if (std::abs(v.x()) < 1e-9) lowestAtTheMiddle = std::min(lowestAtTheMiddle, v.y());
    highest = std::max(highest, v.y());
  }
  EXPECT_NEAR(lowestAtTheMiddle, b.legBottom, 1e-9);  // the gusset, front and back
  EXPECT_NEAR(highest, b.bandTop, 1e-9);
}

TEST(BaseLayer, OneSurfaceWhoseOnlyEdgesAreItsBounds) {
  const auto [b, layer] = cutOnTheSkin(prism());
  std::map<std::pair<int, int>, int> uses;
  for (const Triangle& t : layer.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[size_t(k)], t[size_t((k + 1) % 3)])];
  int open = 0, inside = 0;
  for (const auto& [edge, count] : uses) {
    if (count != 1) continue;
    ++open;
    if (!onABound(layer.vertices[size_t(edge.first)], b) || !onABound(layer.vertices[size_t(edge.second)], b)) ++inside;
  }
  EXPECT_GT(open, 4 * kSides);  // four rims: the briefs' top, two leg openings' worth, the band's two
  EXPECT_EQ(inside, 0);         // no crack where two clipped triangles meet
}

TEST(BaseLayer, LiftedOffTheSkinAlongItsNormals) {
  const Prism p = prism();
  const BaseLayerShape shape;  // 1.5 mm
  const TriangleMesh layer =
      cutBaseLayer(p.mesh, p.mesh, p.parts, baseLayerBounds(p.mesh, p.parts, p.landmarks, shape), shape);
  ASSERT_FALSE(layer.vertices.empty());
  const double chord = kRadius * std::cos(std::numbers::pi / kSides);
  for (const Vec3& v : layer.vertices) {
    const double r = std::hypot(v.x(), v.z());
    EXPECT_GE(r, chord + shape.offset - 1e-9);
    EXPECT_LE(r, kRadius + shape.offset + 1e-9);
  }
}

TEST(BaseLayer, PosedItFollowsTheSkinItWasDecidedOn) {
  const Prism p = prism();
  TriangleMesh moved = p.mesh;
  for (Vec3& v : moved.vertices) v += Vec3(0.3, 0.1, -0.2);
  BaseLayerShape shape;
  shape.offset = 0;
  const BaseLayerBounds b = baseLayerBounds(p.mesh, p.parts, p.landmarks, shape);
  const TriangleMesh here = cutBaseLayer(p.mesh, p.mesh, p.parts, b, shape);
  const TriangleMesh there = cutBaseLayer(p.mesh, moved, p.parts, b, shape);
  ASSERT_EQ(here.vertices.size(), there.vertices.size());
  EXPECT_EQ(here.triangles, there.triangles);
  for (size_t i = 0; i < here.vertices.size(); ++i)
    EXPECT_LT((there.vertices[i] - here.vertices[i] - Vec3(0.3, 0.1, -0.2)).norm(), 1e-12);
}

TEST(BaseLayer, AMensBodyHasBriefsOnly) {
  const Prism p = prism();
  BaseLayerShape shape;
  shape.top = false;
  const BaseLayerBounds b = baseLayerBounds(p.mesh, p.parts, p.landmarks, shape);
  const TriangleMesh layer = cutBaseLayer(p.mesh, p.mesh, p.parts, b, shape);
  ASSERT_FALSE(layer.vertices.empty());
  for (const Vec3& v : layer.vertices) EXPECT_LE(v.y(), b.briefsTop + 1e-9);
}

TEST(BaseLayer, LandmarksOutOfOrderOrMeshesThatDisagreeAreRefused) {
  Prism p = prism();
  p.landmarks.hip = 0.7;  // under the crotch
  try {
    baseLayerBounds(p.mesh, p.parts, p.landmarks, {});
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("hip 0.700000"), std::string::npos) << e.what();
  }
  p.parts.pop_back();
  EXPECT_THROW(cutBaseLayer(p.mesh, p.mesh, p.parts, {}, {}), std::invalid_argument);
}
