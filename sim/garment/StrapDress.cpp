// The strap dress generator. Method:
// 1. Landmarks from horizontal sections (BodySlices): the armpits (where the arms part from
//    the torso) give the top edge, armpits - 3 cm; the hem defaults to 0.30 of stature, just
//    above the knee (knee height ~0.285 H: Drillis & Contini 1966, Winter's "Biomechanics and
//    Motor Control of Human Movement", fig. 4.1).
// 2. The tube's shape (StrapDressTube): rows around one vertical axis, clear of the torso's
//    convex sections, an A-line skirt below the hips, and the top edge raised between the
//    straps, front and back, fading out beyond the straps and over the first rows.
// 3. Columns: on the top edge, three per strap end sit exactly at the strap's lane x, so a
//    strap is two quads (strapWidth) wide where it joins the tube; the other columns share the
//    arcs between straps in proportion to their length (equal spacing on each arc, the left and
//    right sides given the same count: symmetry). Over the next rows the columns move to even
//    spacing by arc length, so the straps' close columns do not run down the dress as short
//    edges (an explicit solver's stable time step scales with the shortest edge).
// 4. Each strap follows the body's profile in the sagittal plane under it: rays from a centre
//    on the top edge's height under the strap (midway between its front and back ends) sweep
//    from the front over the shoulder to the back; on each the outermost crossing of the body's
//    sections across the strap's band (|x - strap| <= width/2 + 1 cm, and 1 cm clear of the
//    neck's side) below the neck, pushed out until the clearance
//    holds, is a profile point. The profile is resampled by arc length; near the ends it is
//    blended onto the tube's top-edge vertices, which the strap shares.
// 5. Windings: counter-clockwise seen from outside by construction (tube: theta grows from +x
//    towards +z, rows go down; straps: lanes grow in x, segments go front to back).

#include "sim/garment/StrapDress.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sim/body/BodySlices.h"
#include "sim/core/ParameterChecks.h"
#include "sim/garment/StrapDressTube.h"

namespace figment {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr int kAnchorSteps = 360;           // over half the top edge, when looking for a strap's lane
constexpr int kSettleRows = 4;              // rows over which columns go from the straps' layout to even
constexpr double kStrapBandMargin = 0.01;   // m beside the strap still looked at under it
constexpr double kStrapCutSpacing = 0.005;  // m between the sagittal sections under a strap
constexpr int kProfileRays = 181;           // rays over the shoulder, front to back
constexpr double kEndBlend = 0.25;          // fraction of a strap blended onto the tube at each end

void requireAtLeast(const char* field, int value, int least) {
  if (value < least)
    throw std::invalid_argument(std::string(field) + " = " + std::to_string(value) +
                                " must be >= " + std::to_string(least));
}

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}
Vec2 direction(double angle) {
  return StrapDressTube::direction(angle);
}

// The angle on the front (z > axis) or back half of the top edge where its x equals `x`.
double angleWhereXIs(const StrapDressTube& shape, double x, bool front) {
  const double start = front ? 0.0 : M_PI;
  auto offset = [&](double angle) { return shape.vertex(0, angle).x() - x; };
  const int steps = kAnchorSteps;
  double a = start, fa = offset(a);
  for (int s = 1; s <= steps; ++s) {
    double b = start + M_PI * s / steps, fb = offset(b);
    if ((fa > 0) != (fb > 0)) {
      for (int i = 0; i < 60; ++i) {
        const double m = 0.5 * (a + b), fm = offset(m);
        if ((fm > 0) == (fa > 0)) {
          a = m, fa = fm;
        } else {
          b = m;
        }
      }
      return 0.5 * (a + b);
    }
    a = b, fa = fb;
  }
  throw std::invalid_argument("strapOffset: x = " + formatNumber(x) + " is beyond the dress's top edge");
}

// A strap's three lanes (ascending x) and the tube columns they start and end at.
struct StrapLanes {
  std::array<double, 3> x{};
  std::array<double, 3> frontAngle{}, backAngle{};
  std::array<int, 3> frontColumn{}, backColumn{};
};

// Column angles around the tube: the straps' anchors, and between them columns spaced evenly
// along the top edge. Fills in the lanes' column indices.
std::vector<double> placeColumns(const StrapDressTube& shape, int columns, std::array<StrapLanes, 2>& straps) {
  // Counter-clockwise from +x: right strap front, left strap front, left back, right back.
  const std::array<const std::array<double, 3>*, 4> groups = {&straps[1].frontAngle, &straps[0].frontAngle,
                                                              &straps[0].backAngle, &straps[1].backAngle};
  auto sortedGroup = [&](int g) {
    std::array<double, 3> angles = *groups[g];
    std::sort(angles.begin(), angles.end());
    return angles;
  };
  // Gap g runs from the last anchor of group g to the first of group g + 1 (the last wraps
  // through theta = 0): front centre, left side, back centre, right side.
  std::array<double, 4> gapStart{}, gapLength{};
  for (int g = 0; g < 4; ++g) {
    if (!(sortedGroup(g)[2] < sortedGroup((g + 1) % 4)[0] + (g == 3 ? kTwoPi : 0.0)))
      throw std::invalid_argument("strapOffset: the straps overlap on the top edge (too close for strapWidth)");
    gapStart[g] = shape.arcTo(0, sortedGroup(g)[2]);
    gapLength[g] = shape.arcTo(0, sortedGroup((g + 1) % 4)[0]) - gapStart[g];
    if (gapLength[g] < 0) gapLength[g] += shape.perimeter(0);
  }
  const int intervals = columns - 12 + 4;
  const double total = gapLength[0] + gapLength[1] + gapLength[2] + gapLength[3];
  const int side = std::max(1, static_cast<int>(std::lround(intervals * 0.5 * (gapLength[1] + gapLength[3]) / total)));
  const int centres = intervals - 2 * side;
  if (centres < 2) throw std::invalid_argument("columns = " + std::to_string(columns) + " is too few");
  const int front =
      std::clamp(static_cast<int>(std::lround(centres * gapLength[0] / (gapLength[0] + gapLength[2]))), 1, centres - 1);
  const std::array<int, 4> counts = {front, side, centres - front, side};

  std::vector<double> angles;
  for (int g = 0; g < 4; ++g) {
    for (double anchor : sortedGroup(g)) angles.push_back(anchor);
    for (int k = 1; k < counts[g]; ++k)
      angles.push_back(shape.angleAtArc(0, gapStart[g] + gapLength[g] * k / counts[g]));
  }
  auto columnOf = [&](double angle) {
    return static_cast<int>(std::find(angles.begin(), angles.end(), angle) - angles.begin());
  };
  for (StrapLanes& strap : straps)
    for (int k = 0; k < 3; ++k) {
      strap.frontColumn[k] = columnOf(strap.frontAngle[k]);
      strap.backColumn[k] = columnOf(strap.backAngle[k]);
    }
  return angles;
}

// Column angles for every row. Row 0 keeps the straps' layout; below it the columns move, over
// kSettleRows rows, to even spacing along each row (the straps' close columns would otherwise
// run down the whole dress as short edges, which limit an explicit solver's time step). Columns
// keep their arc-length fraction around the row, measured from the front centre; the even
// layout is the one nearest the top's in least squares, which keeps a symmetric layout
// symmetric.
std::vector<std::vector<double>> rowAngles(const StrapDressTube& shape, const std::vector<double>& top) {
  const int columns = static_cast<int>(top.size());
  std::vector<double> fraction(columns);
  for (int j = 0; j < columns; ++j) fraction[j] = shape.arcTo(0, top[j]) / shape.perimeter(0);
  std::vector<int> order(columns);
  for (int j = 0; j < columns; ++j) order[j] = j;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return fraction[a] < fraction[b]; });
  double phase = 0;
  for (int m = 0; m < columns; ++m) phase += (fraction[order[m]] - static_cast<double>(m) / columns) / columns;
  std::vector<double> even(columns);
  for (int m = 0; m < columns; ++m) even[order[m]] = phase + static_cast<double>(m) / columns;

  std::vector<std::vector<double>> angles = {top};
  for (int i = 1; i < shape.rowCount(); ++i) {
    const double t = std::min(1.0, static_cast<double>(i) / kSettleRows);
    const double w = t * t * (3 - 2 * t);  // smoothstep: no kink where the settling starts or ends
    std::vector<double> row(columns);
    for (int j = 0; j < columns; ++j)
      row[j] = shape.angleAtArc(i, ((1 - w) * fraction[j] + w * even[j]) * shape.perimeter(i));
    angles.push_back(std::move(row));
  }
  return angles;
}

// The body under a strap, in the sagittal plane (z, y), below the neck.
std::vector<Segment2> strapBand(const TriangleMesh& body, double centreX, double halfWidth, double neck) {
  std::vector<Segment2> band;
  const int cuts = static_cast<int>(std::ceil(2 * halfWidth / kStrapCutSpacing));
  for (int c = 0; c <= cuts; ++c) {
    for (Segment2 s : planeSection(body, SectionAxis::X, centreX - halfWidth + 2 * halfWidth * c / cuts)) {
      if (s.a.y() > neck && s.b.y() > neck) continue;
      // Clip at the neck: above it the head (ears reach |x| ~ 8 cm) would hold the strap up.
      for (Vec2* end : {&s.a, &s.b}) {
        const Vec2& other = end == &s.a ? s.b : s.a;
        if (end->y() > neck) *end = other + (*end - other) * ((neck - other.y()) / (end->y() - other.y()));
      }
      band.push_back(s);
    }
  }
  return band;
}

double distanceToSegments(const Vec2& p, const std::vector<Segment2>& segments) {
  double best = std::numeric_limits<double>::infinity();
  for (const Segment2& s : segments) {
    const Vec2 ab = s.b - s.a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0 ? std::clamp((p - s.a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    best = std::min(best, (s.a + t * ab - p).norm());
  }
  return best;
}

// `p` moved away from `centre` until it is at least `clearance` from every segment of `band`.
// Steps out by a tenth of the clearance, then bisects the last step to 1 nm.
Vec2 pushedOut(const Vec2& p, const Vec2& centre, const std::vector<Segment2>& band, double clearance) {
  const Vec2 outward = (p - centre).normalized();
  auto clear = [&](double t) { return distanceToSegments(p + t * outward, band) >= clearance; };
  if (clear(0)) return p;
  double low = 0, high = 0.1 * clearance;
  while (!clear(high)) low = high, high += 0.1 * clearance;
  while (high - low > 1e-9) {
    const double mid = 0.5 * (low + high);
    (clear(mid) ? high : low) = mid;
  }
  return p + high * outward;
}

// The strap's path over the shoulder in (z, y): front end first, `segments` + 1 points at
// equal arc lengths, each at least `clearance` from the band.
std::vector<Vec2> strapProfile(const std::vector<Segment2>& band, const Vec2& centre, double clearance, int segments) {
  std::vector<Vec2> profile;
  for (int m = 0; m < kProfileRays; ++m) {
    const Vec2 d = direction(M_PI * m / (kProfileRays - 1));
    double outermost = -1;
    for (const Segment2& s : band) {
      const Vec2 edge = s.b - s.a;
      const double denominator = cross(d, edge);
      if (std::abs(denominator) < 1e-15) continue;
      const double t = cross(s.a - centre, edge) / denominator, u = cross(s.a - centre, d) / denominator;
      if (t >= 0 && u >= 0 && u <= 1) outermost = std::max(outermost, t);
    }
    if (outermost < 0)
      throw std::invalid_argument("body: nothing under the strap in direction " +
                                  formatNumber(180.0 * m / (kProfileRays - 1)) +
                                  " degrees from the front at y = " + formatNumber(centre.y()));
    profile.push_back(pushedOut(centre + (outermost + clearance) * d, centre, band, clearance));
  }
  std::vector<double> along(profile.size(), 0.0);
  for (size_t m = 1; m < profile.size(); ++m) along[m] = along[m - 1] + (profile[m] - profile[m - 1]).norm();
  std::vector<Vec2> resampled;
  size_t m = 1;
  for (int i = 0; i <= segments; ++i) {
    const double target = along.back() * i / segments;
    while (m + 1 < profile.size() && along[m] < target) ++m;
    const double f = std::clamp((target - along[m - 1]) / (along[m] - along[m - 1]), 0.0, 1.0);
    resampled.push_back(profile[m - 1] + f * (profile[m] - profile[m - 1]));
  }
  return resampled;
}

// Quad (a, b, c, d) counter-clockwise seen from outside, split along alternating diagonals
// so the mesh has no preferred shear direction.
void addQuad(std::vector<Triangle>& triangles, int a, int b, int c, int d, bool flip) {
  if (flip) {
    triangles.push_back({a, b, c});
    triangles.push_back({a, c, d});
  } else {
    triangles.push_back({a, b, d});
    triangles.push_back({b, c, d});
  }
}

// Appends the tube to an empty mesh: vertex (row i, column j) is i * columns + j, so the top
// edge's vertices are the first `columns`.
void appendTube(const StrapDressTube& shape, const std::vector<std::vector<double>>& angles, TriangleMesh& mesh) {
  assert(mesh.vertices.empty());
  const int columns = static_cast<int>(angles[0].size()), rows = shape.rowCount();
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < columns; ++j) {
      mesh.vertices.push_back(shape.vertex(i, angles[i][j]));
    }
  auto vertex = [columns](int i, int j) { return i * columns + (j % columns); };
  for (int i = 0; i + 1 < rows; ++i)
    for (int j = 0; j < columns; ++j)
      addQuad(mesh.triangles, vertex(i, j), vertex(i, j + 1), vertex(i + 1, j + 1), vertex(i + 1, j), (i + j) % 2 == 1);
}

// Where a strap's band is cut (x): the strap's width and kStrapBandMargin either side, but
// never nearer the neck than kStrapBandMargin. On a body whose neck reaches under the strap's
// inner side (HUMAN.blend: neck 5.9 cm from the centre, straps at 8 cm on its sloping
// shoulders) the neck's side up to neckHeight was the body under the strap, which then stood
// 4 cm above the shoulder.
struct StrapBandRange {
  double centreX = 0, halfWidth = 0;  // m
};

StrapBandRange bandBesideTheNeck(const StrapLanes& strap, const StrapDress& dress, const StrapDressOptions& options) {
  const double centreX = 0.5 * (strap.x[0] + strap.x[2]), halfWidth = 0.5 * options.strapWidth + kStrapBandMargin;
  const double side = centreX > dress.neckCentreX ? 1.0 : -1.0;
  const double neckEdge = dress.neckCentreX + side * (dress.neckHalfWidth + kStrapBandMargin);
  const double inner = centreX - side * halfWidth, outer = centreX + side * halfWidth;
  if (side * (inner - neckEdge) >= 0) return {centreX, halfWidth};  // clear of the neck
  if (side * (outer - neckEdge) < options.strapWidth)
    throw std::invalid_argument("strapOffset = " + formatNumber(options.strapOffset) +
                                " puts the straps over the neck, which reaches " + formatNumber(dress.neckHalfWidth) +
                                " m from the centre: try at least " +
                                formatNumber(dress.neckHalfWidth + options.strapWidth));
  return {0.5 * (neckEdge + outer), 0.5 * side * (outer - neckEdge)};
}

// Appends a strap whose lanes start and end at the tube's top-edge vertices (appendTube first).
void appendStrap(const TriangleMesh& body, const StrapLanes& strap, const StrapDress& dress,
                 const StrapDressOptions& options, TriangleMesh& mesh) {
  // The profile's rays start at the top edge's height under the strap's centre line: with the
  // neckline raised there, the strap's ends meet the top edge nearly level.
  auto topEdge = [&](int column) {  // (z, y) of a tube vertex on the top edge
    const Vec3& v = mesh.vertices[column];
    return Vec2(v.z(), v.y());
  };
  const Vec2 centre = 0.5 * (topEdge(strap.frontColumn[1]) + topEdge(strap.backColumn[1]));
  const StrapBandRange range = bandBesideTheNeck(strap, dress, options);
  const std::vector<Segment2> band = strapBand(body, range.centreX, range.halfWidth, dress.neckHeight);
  const int n = options.strapSegments;
  const std::vector<Vec2> path = strapProfile(band, centre, options.clearance, n);
  std::array<std::vector<int>, 3> lane;
  for (int k = 0; k < 3; ++k) {
    const Vec2 frontShift = topEdge(strap.frontColumn[k]) - path.front();
    const Vec2 backShift = topEdge(strap.backColumn[k]) - path.back();
    lane[k].push_back(strap.frontColumn[k]);
    for (int i = 1; i < n; ++i) {
      const double s = static_cast<double>(i) / n;
      // Blending towards the tube's vertices may cut a corner: restore the clearance.
      const Vec2 p = pushedOut(path[i] + std::max(0.0, 1.0 - s / kEndBlend) * frontShift +
                                   std::max(0.0, 1.0 - (1.0 - s) / kEndBlend) * backShift,
                               centre, band, options.clearance);
      lane[k].push_back(static_cast<int>(mesh.vertices.size()));
      mesh.vertices.emplace_back(strap.x[k], p.y(), p.x());
    }
    lane[k].push_back(strap.backColumn[k]);
  }
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < n; ++i)
      addQuad(mesh.triangles, lane[k][i], lane[k + 1][i], lane[k + 1][i + 1], lane[k][i + 1], (i + k) % 2 == 1);
}

}  // namespace

void StrapDressOptions::validate() const {
  requirePositive("clearance", clearance);
  requireNonNegative("topBelowArmpit", topBelowArmpit);
  if (topHeight) requireFinite("topHeight", *topHeight);
  if (hemHeight) requireFinite("hemHeight", *hemHeight);
  requireOpenRange("hemHeightRatio", hemHeightRatio, 0.0, 1.0);
  requireAtLeast("rows", rows, 2);
  requireAtLeast("columns", columns, 16);
  requireNonNegative("hemFlare", hemFlare);
  requirePositive("strapWidth", strapWidth);
  requirePositive("strapOffset", strapOffset);
  if (!(strapOffset > 0.5 * strapWidth))
    throw std::invalid_argument("strapOffset = " + formatNumber(strapOffset) +
                                " must exceed strapWidth / 2 = " + formatNumber(0.5 * strapWidth));
  requireAtLeast("strapSegments", strapSegments, 4);
  requirePositive("clusterGap", clusterGap);
  requirePositive("torsoHalfWidth", torsoHalfWidth);
  requireNonNegative("necklineRise", necklineRise);
  requirePositive("necklineFade", necklineFade);
}

StrapDress makeStrapDress(const TriangleMesh& body, const StrapDressOptions& options) {
  options.validate();
  if (body.triangles.empty()) throw std::invalid_argument("body: no triangles");
  const Bounds bounds = boundsOf(body.vertices);
  const SliceOptions slicing = centredSlicing(body, options.clusterGap, options.torsoHalfWidth);

  StrapDress dress;
  dress.armpitHeight = armpitHeight(body, slicing);
  dress.neckHeight = neckHeight(body, dress.armpitHeight, slicing);
  const TorsoSlice neck = sliceTorso(body, dress.neckHeight, slicing);
  if (!neck.empty()) {
    dress.neckCentreX = 0.5 * (neck.minX() + neck.maxX());
    dress.neckHalfWidth = 0.5 * (neck.maxX() - neck.minX());
  } else {
    dress.neckCentreX = slicing.torsoCentreX;
  }
  dress.topHeight = options.topHeight.value_or(dress.armpitHeight - options.topBelowArmpit);
  dress.hemHeight = options.hemHeight.value_or(bounds.min.y() + options.hemHeightRatio * bounds.size().y());
  if (!(dress.topHeight > dress.hemHeight))
    throw std::invalid_argument("hemHeight = " + formatNumber(dress.hemHeight) +
                                " must be below topHeight = " + formatNumber(dress.topHeight));

  Neckline neckline;
  neckline.rise = options.necklineRise;
  neckline.centreX = slicing.torsoCentreX;
  neckline.plateau = options.strapOffset;
  neckline.fade = options.necklineFade;
  const StrapDressTube shape(body, dress.topHeight, dress.hemHeight, std::max(dress.topHeight, dress.armpitHeight),
                             options.rows, options.clearance, options.hemFlare, slicing, neckline);
  dress.necklineHeight = dress.topHeight + options.necklineRise;
  std::array<StrapLanes, 2> straps;  // left (x < centre), right
  for (int side = 0; side < 2; ++side) {
    dress.strapX[side] = slicing.torsoCentreX + (side == 0 ? -1 : 1) * options.strapOffset;
    for (int k = 0; k < 3; ++k) {
      straps[side].x[k] = dress.strapX[side] + (k - 1) * 0.5 * options.strapWidth;
      straps[side].frontAngle[k] = angleWhereXIs(shape, straps[side].x[k], true);
      straps[side].backAngle[k] = angleWhereXIs(shape, straps[side].x[k], false);
    }
  }
  const std::vector<std::vector<double>> angles = rowAngles(shape, placeColumns(shape, options.columns, straps));

  TriangleMesh mesh;
  appendTube(shape, angles, mesh);
  dress.tubeTriangles = static_cast<int>(mesh.triangles.size());
  for (const StrapLanes& strap : straps) appendStrap(body, strap, dress, options, mesh);
  dress.mesh = numberedByFirstUse(mesh);
  return dress;
}

}  // namespace figment
