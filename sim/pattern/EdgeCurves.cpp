// Based on:
// - circular arcs as SVG's endpoint parametrisation (W3C SVG 1.1, appendix F.6.5: centre on
//   the chord's perpendicular bisector, large-arc and sweep flags), with GarmentCode's
//   `right` as the side the arc bulges to (io/PatternFile.cpp says where that was checked);
// - arc length of a Bézier by adaptive Gauss-Legendre quadrature of |B'(t)| (each interval
//   halved until its two halves agree with the whole), and its inverse by Newton's method
//   safeguarded by bisection (the speed |B'| may vanish at a cusp).
#include "sim/pattern/EdgeCurves.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace figment {

namespace {

// What an edge is, once its indices are checked: the end points and, for an arc, its
// centre, start angle and signed sweep (rad; positive counter-clockwise).
struct Curve {
  EdgeCurve::Kind kind;
  Vec2 s, e;
  std::array<Vec2, 2> c;  // Bézier control points
  Vec2 centre = Vec2::Zero();
  double radius = 0.0, start = 0.0, sweep = 0.0;
};

std::string edgeName(const Panel& panel, int edge) {
  return "panel '" + panel.name + "' edge " + std::to_string(edge);
}

Curve curveOf(const Panel& panel, int edge) {
  if (edge < 0 || edge >= static_cast<int>(panel.edges.size()))
    throw std::invalid_argument("edge index " + std::to_string(edge) + " out of range: panel '" + panel.name +
                                "' has " + std::to_string(panel.edges.size()) + " edges");
  const PanelEdge& pe = panel.edges[edge];
  const int n = static_cast<int>(panel.vertices.size());
  if (pe.from < 0 || pe.from >= n || pe.to < 0 || pe.to >= n)
    throw std::invalid_argument(edgeName(panel, edge) + ": end point index out of range (from " +
                                std::to_string(pe.from) + ", to " + std::to_string(pe.to) + ", " + std::to_string(n) +
                                " vertices)");
  Curve curve;
  curve.kind = pe.curve.kind;
  curve.s = panel.vertices[pe.from];
  curve.e = panel.vertices[pe.to];
  const size_t needed = curve.kind == EdgeCurve::Kind::Quadratic ? 1 : curve.kind == EdgeCurve::Kind::Cubic ? 2 : 0;
  if (pe.curve.controls.size() < needed)
    throw std::invalid_argument(edgeName(panel, edge) + ": " + std::to_string(pe.curve.controls.size()) +
                                " control points, needs " + std::to_string(needed));
  for (size_t k = 0; k < needed; ++k) curve.c[k] = pe.curve.controls[k];
  if (curve.kind != EdgeCurve::Kind::Circle) return curve;

  const Vec2 chord = curve.e - curve.s;
  const double length = chord.norm(), r = pe.curve.radius;
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::invalid_argument(edgeName(panel, edge) + ": a circular arc between coincident end points");
  if (!std::isfinite(r) || r < 0.5 * length * (1.0 - kArcRadiusSlack))
    throw std::invalid_argument(edgeName(panel, edge) + ": circle radius " + std::to_string(r) +
                                " m is less than half its chord " + std::to_string(0.5 * length) + " m");
  // The centre lies on the chord's bisector, h from its middle: to the left of s -> e
  // (along left = perp(chord)) for the small arc bulging right or the large one bulging
  // left, to the right otherwise. An arc bulging right turns counter-clockwise.
  const Vec2 left = Vec2(-chord.y(), chord.x()) / length;
  const double h = std::sqrt(std::max(0.0, r * r - 0.25 * length * length));
  const double side = pe.curve.right != pe.curve.largeArc ? 1.0 : -1.0;
  curve.radius = std::max(r, 0.5 * length);
  curve.centre = 0.5 * (curve.s + curve.e) + side * h * left;
  const Vec2 fromCentre = curve.s - curve.centre;
  curve.start = std::atan2(fromCentre.y(), fromCentre.x());
  const double small = 2.0 * std::asin(std::min(1.0, 0.5 * length / curve.radius));
  const double angle = pe.curve.largeArc ? 2.0 * M_PI - small : small;
  curve.sweep = pe.curve.right ? angle : -angle;
  return curve;
}

Vec2 point(const Curve& curve, double t) {
  const double u = 1.0 - t;
  switch (curve.kind) {
    case EdgeCurve::Kind::Straight:
      return u * curve.s + t * curve.e;
    case EdgeCurve::Kind::Quadratic:
      return u * u * curve.s + 2.0 * u * t * curve.c[0] + t * t * curve.e;
    case EdgeCurve::Kind::Cubic:
      return u * u * u * curve.s + 3.0 * u * u * t * curve.c[0] + 3.0 * u * t * t * curve.c[1] + t * t * t * curve.e;
    case EdgeCurve::Kind::Circle: {
      const double a = curve.start + t * curve.sweep;
      return curve.centre + curve.radius * Vec2(std::cos(a), std::sin(a));
    }
  }
  return curve.s;
}

// dB/dt of a Bézier (m per unit t).
Vec2 velocity(const Curve& curve, double t) {
  const double u = 1.0 - t;
  if (curve.kind == EdgeCurve::Kind::Quadratic)
    return 2.0 * u * (curve.c[0] - curve.s) + 2.0 * t * (curve.e - curve.c[0]);
  return 3.0 * u * u * (curve.c[0] - curve.s) + 6.0 * u * t * (curve.c[1] - curve.c[0]) +
         3.0 * t * t * (curve.e - curve.c[1]);
}

// 10-point Gauss-Legendre on [a, b]: exact for polynomials of degree 19; |B'| is smooth
// away from cusps, so a few halvings reach 1e-12.
double gauss(const Curve& curve, double a, double b) {
  static constexpr std::array<double, 5> kNodes = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                                                   0.8650633666889845, 0.9739065285171717};
  static constexpr std::array<double, 5> kWeights = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                                                     0.1494513491505806, 0.0666713443086881};
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  double sum = 0.0;
  for (int k = 0; k < 5; ++k)
    sum +=
        kWeights[k] * (velocity(curve, mid - half * kNodes[k]).norm() + velocity(curve, mid + half * kNodes[k]).norm());
  return half * sum;
}

double adaptive(const Curve& curve, double a, double b, double whole, double tolerance, int depth) {
  const double mid = 0.5 * (a + b);
  const double left = gauss(curve, a, mid), right = gauss(curve, mid, b);
  // Depth 40 halves [0, 1] to 1e-12: past that, a cusp's share of the length is below the
  // tolerance anyway.
  if (std::abs(left + right - whole) <= tolerance || depth >= 40) return left + right;
  return adaptive(curve, a, mid, left, 0.5 * tolerance, depth + 1) +
         adaptive(curve, mid, b, right, 0.5 * tolerance, depth + 1);
}

// The arc length (m) of a Bézier from a to b. The tolerance is relative to the length of
// its control polygon (which bounds the curve's length), so it holds at any scale.
double bezierLength(const Curve& curve, double a, double b) {
  double polygon = (curve.c[0] - curve.s).norm();
  if (curve.kind == EdgeCurve::Kind::Quadratic)
    polygon += (curve.e - curve.c[0]).norm();
  else
    polygon += (curve.c[1] - curve.c[0]).norm() + (curve.e - curve.c[1]).norm();
  if (polygon == 0.0 || a == b) return 0.0;
  return adaptive(curve, a, b, gauss(curve, a, b), 1e-13 * polygon, 0);
}

bool isBezier(const Curve& curve) {
  return curve.kind == EdgeCurve::Kind::Quadratic || curve.kind == EdgeCurve::Kind::Cubic;
}

double curveLength(const Curve& curve) {
  switch (curve.kind) {
    case EdgeCurve::Kind::Straight:
      return (curve.e - curve.s).norm();
    case EdgeCurve::Kind::Circle:
      return curve.radius * std::abs(curve.sweep);
    default:
      return bezierLength(curve, 0.0, 1.0);
  }
}

// The parameter past t0 where the arc length from t0 reaches `distance` (m): Newton's
// method on s(t) - distance, kept inside a bracket that bisection shrinks when a step
// leaves it (near a cusp, where the speed vanishes).
double parameterAt(const Curve& curve, double t0, double distance, double total) {
  // First guess: the mean speed over [0, 1], which is the length.
  double lo = t0, hi = 1.0, t = total > 0.0 ? std::min(1.0, t0 + distance / total) : 1.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double f = bezierLength(curve, t0, t) - distance;
    if (std::abs(f) <= 1e-14 * total) return t;
    (f > 0.0 ? hi : lo) = t;
    const double speed = velocity(curve, t).norm();
    double next = speed > 0.0 ? t - f / speed : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= 1e-16) return next;
    t = next;
  }
  return t;
}

}  // namespace

Vec2 edgePoint(const Panel& panel, int edge, double t) {
  const Curve curve = curveOf(panel, edge);
  if (t <= 0.0) return curve.s;
  if (t >= 1.0) return curve.e;
  return point(curve, t);
}

double edgeLength(const Panel& panel, int edge) {
  return curveLength(curveOf(panel, edge));
}

std::vector<Vec2> sampleEdge(const Panel& panel, int edge, int segments) {
  if (segments < 1) throw std::invalid_argument("sampleEdge: segments " + std::to_string(segments) + " < 1");
  const Curve curve = curveOf(panel, edge);
  std::vector<Vec2> samples;
  samples.reserve(segments + 1);
  samples.push_back(curve.s);
  if (!isBezier(curve)) {
    // A line's and an arc's parameters are proportional to their arc length.
    for (int k = 1; k < segments; ++k) samples.push_back(point(curve, static_cast<double>(k) / segments));
  } else {
    const double total = curveLength(curve);
    double t = 0.0;
    for (int k = 1; k < segments; ++k) {
      t = parameterAt(curve, t, total / segments, total);
      samples.push_back(point(curve, t));
    }
  }
  samples.push_back(curve.e);
  return samples;
}

}  // namespace figment
