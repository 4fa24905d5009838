// Edge curves against what they must be: a half circle is pi r long, a cubic whose control
// points lie on its chord is that chord, a parabola's length has a closed form; an arc
// bulges to the side its flag says; samples lie at equal fractions of arc length.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "sim/pattern/EdgeCurves.h"

using namespace figment;

namespace {

// A panel with one edge from s to e of the given curve (and the way back, straight, so it
// is a loop).
Panel oneEdge(const Vec2& s, const Vec2& e, const EdgeCurve& curve) {
  Panel panel;
  panel.name = "test";
  panel.vertices = {s, e};
  panel.edges = {{0, 1, curve}, {1, 0, EdgeCurve{}}};
  return panel;
}

EdgeCurve arc(double radius, bool largeArc, bool right) {
  EdgeCurve curve;
  curve.kind = EdgeCurve::Kind::Circle;
  curve.radius = radius;
  curve.largeArc = largeArc;
  curve.right = right;
  return curve;
}

EdgeCurve bezier(std::vector<Vec2> controls) {
  EdgeCurve curve;
  curve.kind = controls.size() == 1 ? EdgeCurve::Kind::Quadratic : EdgeCurve::Kind::Cubic;
  curve.controls = std::move(controls);
  return curve;
}

// Which side of s -> e a point is on: > 0 left, < 0 right.
double side(const Vec2& s, const Vec2& e, const Vec2& p) {
  const Vec2 d = e - s, q = p - s;
  return d.x() * q.y() - d.y() * q.x();
}

// The edge as a polyline of n segments by its own parameter, with each point's arc length:
// an independent measure (the polyline's error falls as 1/n^2: 1e-12 relative at n = 1e6
// for curves bent on the scale of their length).
struct Dense {
  std::vector<Vec2> points;
  std::vector<double> along;
};
Dense dense(const Panel& panel, int n) {
  Dense d;
  d.points.reserve(n + 1);
  d.along.reserve(n + 1);
  for (int k = 0; k <= n; ++k) {
    d.points.push_back(edgePoint(panel, 0, static_cast<double>(k) / n));
    d.along.push_back(k == 0 ? 0.0 : d.along.back() + (d.points[k] - d.points[k - 1]).norm());
  }
  return d;
}
// The point at arc length `s` along the polyline.
Vec2 at(const Dense& d, double s) {
  const auto it = std::lower_bound(d.along.begin(), d.along.end(), s);
  if (it == d.along.begin()) return d.points.front();
  if (it == d.along.end()) return d.points.back();
  const size_t k = it - d.along.begin();
  const double f = (s - d.along[k - 1]) / (d.along[k] - d.along[k - 1]);
  return d.points[k - 1] + f * (d.points[k] - d.points[k - 1]);
}

}  // namespace

TEST(EdgeCurves, AStraightEdgeIsItsChord) {
  const Panel panel = oneEdge({0.1, 0.2}, {0.4, 0.6}, EdgeCurve{});
  EXPECT_DOUBLE_EQ(edgeLength(panel, 0), 0.5);
  const std::vector<Vec2> samples = sampleEdge(panel, 0, 5);
  ASSERT_EQ(samples.size(), 6u);
  for (int k = 0; k <= 5; ++k) EXPECT_NEAR((samples[k] - Vec2(0.1 + 0.06 * k, 0.2 + 0.08 * k)).norm(), 0.0, 1e-15);
}

// Radius exactly half the chord: both arcs are the same half circle, pi r long, through the
// point r to the side it bulges to.
TEST(EdgeCurves, AHalfCircleIsPiR) {
  const double r = 0.25;
  for (bool large : {false, true})
    for (bool right : {false, true}) {
      const Panel panel = oneEdge({0, 0}, {2 * r, 0}, arc(r, large, right));
      EXPECT_NEAR(edgeLength(panel, 0), M_PI * r, 1e-15) << large << right;
      const Vec2 top = edgePoint(panel, 0, 0.5);
      EXPECT_NEAR((top - Vec2(r, right ? -r : r)).norm(), 0.0, 1e-15) << large << right;
    }
}

// A quarter circle's chord: from (r, 0) to (0, r) with radius r the small arc is a quarter
// (pi r / 2), the large one three quarters; each bulges to the side its flag says, and its
// middle lies where the circle about the right centre puts it.
TEST(EdgeCurves, LargeAndSmallArcsBulgeToTheirSide) {
  const double r = 0.3, c = r / std::sqrt(2.0);
  const Vec2 s(r, 0), e(0, r);
  struct Case {
    bool large, right;
    double length;
    Vec2 middle;
  };
  // Seen along s -> e, the origin is on the left.
  const Case cases[] = {
      {false, true, 0.5 * M_PI * r, {c, c}},           // centre at the origin, bulging away from it
      {false, false, 0.5 * M_PI * r, {r - c, r - c}},  // centre (r, r), bulging towards the origin
      {true, true, 1.5 * M_PI * r, {r + c, r + c}},    // centre (r, r), round the far side
      {true, false, 1.5 * M_PI * r, {-c, -c}},         // centre at the origin, round the far side
  };
  for (const Case& k : cases) {
    const Panel panel = oneEdge(s, e, arc(r, k.large, k.right));
    EXPECT_NEAR(edgeLength(panel, 0), k.length, 1e-14) << k.large << k.right;
    const Vec2 middle = edgePoint(panel, 0, 0.5);
    EXPECT_NEAR((middle - k.middle).norm(), 0.0, 1e-14) << k.large << k.right;
    EXPECT_EQ(side(s, e, middle) < 0, k.right) << k.large << k.right;
    // Every point of the arc is r from its centre, and the samples are evenly spaced: an
    // arc's chords between equal arc lengths are equal.
    const std::vector<Vec2> samples = sampleEdge(panel, 0, 12);
    for (size_t j = 1; j < samples.size(); ++j)
      EXPECT_NEAR((samples[j] - samples[j - 1]).norm(), 2 * r * std::sin(k.length / r / 24), 1e-14);
  }
}

TEST(EdgeCurves, ACubicOnItsChordIsTheChord) {
  // Control points on the chord but bunched towards the start: the parameter runs unevenly
  // along the line while the arc length is still the chord, so even samples must undo it.
  const Vec2 s(0.0, 0.0), e(0.3, 0.4);
  const Panel panel = oneEdge(s, e, bezier({s + 0.05 * (e - s), s + 0.1 * (e - s)}));
  EXPECT_NEAR(edgeLength(panel, 0), 0.5, 1e-13);
  const std::vector<Vec2> samples = sampleEdge(panel, 0, 10);
  for (int k = 0; k <= 10; ++k) EXPECT_NEAR((samples[k] - (s + 0.1 * k * (e - s))).norm(), 0.0, 1e-12) << k;
}

// B(t) = (t, t^2) scaled by a: the parabola y = x^2 / a over [0, a], whose length is
// a (sqrt(5) / 2 + asinh(2) / 4).
TEST(EdgeCurves, AQuadraticHasItsClosedFormLength) {
  const double a = 0.4;
  const Panel panel = oneEdge({0, 0}, {a, a}, bezier({{0.5 * a, 0.0}}));
  const double exact = a * (std::sqrt(5.0) / 2 + std::asinh(2.0) / 4);
  EXPECT_NEAR(edgeLength(panel, 0), exact, 1e-9 * exact);
  EXPECT_NEAR((edgePoint(panel, 0, 0.5) - Vec2(0.5 * a, 0.25 * a)).norm(), 0.0, 1e-16);
}

// The samples lie at equal fractions of arc length to 1e-6 of the length, measured on an
// independent dense polyline; the lengths agree with it to 1e-9. Cases: a cubic bent
// unevenly, and one with a cusp (its speed vanishes at t = 1/2).
TEST(EdgeCurves, SamplesAreEvenlySpacedByArcLength) {
  const std::vector<std::vector<Vec2>> cubics = {
      {{0, 0}, {0.05, 0.3}, {0.9, -0.2}, {1, 0}},
      {{0, 0}, {1, 1}, {0, 1}, {1, 0}},
  };
  for (const auto& p : cubics) {
    const Panel panel = oneEdge(0.5 * p[0], 0.5 * p[3], bezier({0.5 * p[1], 0.5 * p[2]}));
    const Dense d = dense(panel, 1000000);
    const double length = edgeLength(panel, 0);
    EXPECT_NEAR(length, d.along.back(), 1e-9 * length);
    const int n = 37;
    const std::vector<Vec2> samples = sampleEdge(panel, 0, n);
    ASSERT_EQ(samples.size(), static_cast<size_t>(n + 1));
    for (int k = 0; k <= n; ++k) EXPECT_LT((samples[k] - at(d, length * k / n)).norm(), 1e-6 * length) << k;
  }
}

TEST(EdgeCurves, EndPointsAreExact) {
  const Vec2 s(0.123456789, -0.987654321), e(0.3333333333, 0.7777777777);
  const EdgeCurve curves[] = {EdgeCurve{}, arc(1.2, false, true), arc(1.2, true, false), bezier({{0.2, 0.9}}),
                              bezier({{0.9, 0.1}, {-0.4, 0.3}})};
  for (const EdgeCurve& curve : curves) {
    const Panel panel = oneEdge(s, e, curve);
    EXPECT_EQ(edgePoint(panel, 0, 0.0), s);
    EXPECT_EQ(edgePoint(panel, 0, 1.0), e);
    const std::vector<Vec2> samples = sampleEdge(panel, 0, 7);
    EXPECT_EQ(samples.front(), s);
    EXPECT_EQ(samples.back(), e);
  }
}

TEST(EdgeCurves, RejectsAnArcShorterThanItsChordAndABadIndex) {
  const Panel panel = oneEdge({0, 0}, {1, 0}, arc(0.49, false, true));
  EXPECT_THROW(edgeLength(panel, 0), std::invalid_argument);
  // Within the slack, a radius a rounding short of half the chord is a half circle.
  EXPECT_NEAR(edgeLength(oneEdge({0, 0}, {1, 0}, arc(0.5 * (1 - 1e-9), false, true)), 0), 0.5 * M_PI, 1e-8);
  EXPECT_THROW(edgeLength(panel, 2), std::invalid_argument);
  EXPECT_THROW(sampleEdge(oneEdge({0, 0}, {1, 0}, EdgeCurve{}), 0, 0), std::invalid_argument);
}
