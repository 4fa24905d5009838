#include "sim/collision/RadialDepth.h"

#include "sim/body/BodySlices.h"
#include "sim/collision/SurfaceProjection.h"
#include "sim/core/ParameterChecks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace figment {

void RadialDepthParameters::validate() const {
  if (!(direction.norm() > 0.0) || !direction.allFinite()) throw std::invalid_argument("direction must not be zero");
  if (!(reference.norm() > 0.0) || std::abs(reference.normalized().dot(direction.normalized())) > 1e-6)
    throw std::invalid_argument("reference must be perpendicular to direction");
  requirePositive("length", length);
  if (harmonics < 0) throw std::invalid_argument("harmonics = " + std::to_string(harmonics) + " must be >= 0");
  if (coefficients.size() < 2)
    throw std::invalid_argument("coefficients: " + std::to_string(coefficients.size()) + " sections, need >= 2");
  for (size_t j = 0; j < coefficients.size(); ++j)
    if (coefficients[j].size() != static_cast<size_t>(2 * harmonics + 1))
      throw std::invalid_argument("coefficients of section " + std::to_string(j) + ": " +
                                  std::to_string(coefficients[j].size()) + " values, need 2 harmonics + 1 = " +
                                  std::to_string(2 * harmonics + 1));
}

RadialDepth::RadialDepth(RadialDepthParameters parameters) : parameters_(std::move(parameters)) {
  parameters_.validate();
  parameters_.direction.normalize();
  parameters_.reference.normalize();
  side_ = parameters_.direction.cross(parameters_.reference);
  // The table, and the bounds distanceBound() relies on (see the header): each from the
  // function's largest value on a grid of kGrid angles plus pi / kGrid times a bound of
  // its derivative (every angle lies within pi / kGrid of a grid angle).
  const auto& c = parameters_.coefficients;
  const int harmonics = parameters_.harmonics;
  const size_t sections = c.size();
  const double spacing = parameters_.length / static_cast<double>(sections - 1);
  constexpr int kGrid = 256;
  const auto largest = [&](auto&& f, double derivativeBound) {
    double most = 0.0;
    for (int i = 0; i < kGrid; ++i) most = std::max(most, std::abs(f(2 * M_PI * i / kGrid)));
    return most + M_PI / kGrid * derivativeBound;
  };
  for (size_t j = 0; j < sections; ++j) {
    table_.insert(table_.end(), c[j].begin(), c[j].end());
    double amplitude = 0.0, curvature = 0.0;  // sum |harmonic k|, sum k^2 |harmonic k|
    for (int k = 1; k <= harmonics; ++k) {
      const double a = std::hypot(c[j][2 * k - 1], c[j][2 * k]);
      amplitude += a, curvature += k * k * a;
    }
    rMax_ = std::max(rMax_, c[j][0] + amplitude);
    turning_.push_back(largest(
        [&](double a) {
          double d = 0.0;
          for (int k = 1; k <= harmonics; ++k) d += k * (c[j][2 * k] * std::cos(k * a) - c[j][2 * k - 1] * std::sin(k * a));
          return d;
        },
        curvature));
    if (j + 1 == sections) break;
    double change = 0.0;  // sum k |harmonic k of the difference to the next section|
    for (int k = 1; k <= harmonics; ++k)
      change += k * std::hypot(c[j + 1][2 * k - 1] - c[j][2 * k - 1], c[j + 1][2 * k] - c[j][2 * k]);
    slope_.push_back(largest(
                         [&](double a) {
                           double d = c[j + 1][0] - c[j][0];
                           for (int k = 1; k <= harmonics; ++k)
                             d += (c[j + 1][2 * k - 1] - c[j][2 * k - 1]) * std::cos(k * a) +
                                  (c[j + 1][2 * k] - c[j][2 * k]) * std::sin(k * a);
                           return d;
                         },
                         change) /
                     spacing);
  }
}

namespace {
// Turns the direction (c, s) = (cos b, sin b) by the angle whose cosine and sine are (cd, sd).
inline void turn(double& c, double& s, double cd, double sd) {
  const double next = c * cd - s * sd;
  s = s * cd + c * sd, c = next;
}
}  // namespace

// The series below run the harmonics in two chains, odd k and even k, each turned by 2a
// from its first: cos k a and sin k a by the angle-addition recurrence (no sin or cos),
// two independent recurrences and sums for the processor to overlap.

double RadialDepth::seriesAt(double s, double cosA, double sinA) const {
  const size_t sections = parameters_.coefficients.size(), terms = 2 * parameters_.harmonics + 1;
  const double x = std::clamp(s / parameters_.length, 0.0, 1.0) * static_cast<double>(sections - 1);
  const size_t j = std::min(static_cast<size_t>(x), sections - 2);
  const double f = x - static_cast<double>(j), g = 1.0 - f;
  const double *c0 = &table_[j * terms], *c1 = c0 + terms;
  const double cos2 = cosA * cosA - sinA * sinA, sin2 = 2.0 * sinA * cosA;
  double co = cosA, so = sinA, ce = cos2, se = sin2;  // harmonics k (odd) and k + 1
  double odd = g * c0[0] + f * c1[0], even = 0.0;
  const int harmonics = parameters_.harmonics;
  for (int k = 1; k <= harmonics; k += 2) {
    odd += (g * c0[2 * k - 1] + f * c1[2 * k - 1]) * co + (g * c0[2 * k] + f * c1[2 * k]) * so;
    if (k < harmonics) even += (g * c0[2 * k + 1] + f * c1[2 * k + 1]) * ce + (g * c0[2 * k + 2] + f * c1[2 * k + 2]) * se;
    turn(co, so, cos2, sin2), turn(ce, se, cos2, sin2);
  }
  return odd + even;
}

double RadialDepth::radius(double s, double a) const {
  return std::max(seriesAt(s, std::cos(a), std::sin(a)), 0.0);
}

SurfaceSample RadialDepth::sample(double s, double a) const { return sampleAt(s, std::cos(a), std::sin(a)); }

SurfaceSample RadialDepth::sampleAt(double s, double cosA, double sinA) const {
  // r and its derivatives: linear in s between sections, a Fourier series in a.
  const size_t sections = parameters_.coefficients.size(), terms = 2 * parameters_.harmonics + 1;
  const double spacing = parameters_.length / static_cast<double>(sections - 1);
  const double x = std::clamp(s / parameters_.length, 0.0, 1.0) * static_cast<double>(sections - 1);
  const size_t j = std::min(static_cast<size_t>(x), sections - 2);
  const double f = x - static_cast<double>(j);
  const double *c0 = &table_[j * terms], *c1 = c0 + terms;
  // r at sections j and j + 1 and their d/da, odd and even harmonics apart.
  double r0 = c0[0], r1 = c1[0], a0 = 0.0, a1 = 0.0, r0Even = 0.0, r1Even = 0.0, a0Even = 0.0, a1Even = 0.0;
  const double cos2 = cosA * cosA - sinA * sinA, sin2 = 2.0 * sinA * cosA;
  double co = cosA, so = sinA, ce = cos2, se = sin2;
  const int harmonics = parameters_.harmonics;
  for (int k = 1; k <= harmonics; k += 2) {
    r0 += c0[2 * k - 1] * co + c0[2 * k] * so;
    r1 += c1[2 * k - 1] * co + c1[2 * k] * so;
    a0 += k * (c0[2 * k] * co - c0[2 * k - 1] * so);
    a1 += k * (c1[2 * k] * co - c1[2 * k - 1] * so);
    if (k < harmonics) {
      r0Even += c0[2 * k + 1] * ce + c0[2 * k + 2] * se;
      r1Even += c1[2 * k + 1] * ce + c1[2 * k + 2] * se;
      a0Even += (k + 1) * (c0[2 * k + 2] * ce - c0[2 * k + 1] * se);
      a1Even += (k + 1) * (c1[2 * k + 2] * ce - c1[2 * k + 1] * se);
    }
    turn(co, so, cos2, sin2), turn(ce, se, cos2, sin2);
  }
  r0 += r0Even, r1 += r1Even;
  const double ra = (1.0 - f) * (a0 + a0Even) + f * (a1 + a1Even);
  const double r = (1.0 - f) * r0 + f * r1;
  const bool clamped = r < 0.0;  // radius() clamps at 0: a point on the axis
  const double rs = clamped ? 0.0 : (r1 - r0) / spacing;
  const Vec3 radial = cosA * parameters_.reference + sinA * side_;
  const Vec3 turning = -sinA * parameters_.reference + cosA * side_;
  const double radiusHere = std::max(r, 0.0);
  return {parameters_.base + s * parameters_.direction + radiusHere * radial,
          parameters_.direction + rs * radial, (clamped ? 0.0 : ra) * radial + radiusHere * turning};
}

Vec3 RadialDepth::surface(double s, double a) const {
  return parameters_.base + s * parameters_.direction +
         radius(s, a) * (std::cos(a) * parameters_.reference + std::sin(a) * side_);
}

void RadialDepth::toAxis(const Vec3& p, double& s, double& a, double& rho) const {
  const Vec3 d = p - parameters_.base;
  s = d.dot(parameters_.direction);
  const Vec3 across = d - s * parameters_.direction;
  rho = across.norm();
  a = std::atan2(across.dot(side_), across.dot(parameters_.reference));
}

void RadialDepth::toAxis(const Vec3& p, double& s, double& cosA, double& sinA, double& rho) const {
  const Vec3 d = p - parameters_.base;
  s = d.dot(parameters_.direction);
  const Vec3 across = d - s * parameters_.direction;
  rho = across.norm();
  const double x = across.dot(parameters_.reference), y = across.dot(side_), h = std::sqrt(x * x + y * y);
  if (h > 0.0) cosA = x / h, sinA = y / h;
  else cosA = 1.0, sinA = 0.0;  // on the axis: atan2's angle 0
}

bool RadialDepth::contains(const Vec3& p) const {
  double s, cosA, sinA, rho;
  toAxis(p, s, cosA, sinA, rho);
  return s >= 0.0 && s <= parameters_.length && rho <= std::max(seriesAt(s, cosA, sinA), 0.0);
}

double RadialDepth::distanceBound(const Vec3& p) const {
  double s, cosA, sinA, rho;
  toAxis(p, s, cosA, sinA, rho);
  const double length = parameters_.length;
  const double axial = s < 0.0 ? -s : s > length ? s - length : 0.0;
  if (axial > 0.0) return std::hypot(axial, std::max(rho - rMax_, 0.0));
  const double r = std::max(seriesAt(s, cosA, sinA), 0.0), g = rho - r;
  if (g <= 0.0) return -std::min({s, length - s, -g});
  const double cylinder = std::max(rho - rMax_, 0.0);
  if (!(r > 0.0)) return cylinder;
  // The spans that [s - g, s + g] meets.
  const double perSpan = static_cast<double>(slope_.size()) / length;
  const size_t last = slope_.size() - 1;
  const size_t from = std::min(static_cast<size_t>(std::max(s - g, 0.0) * perSpan), last);
  const size_t to = std::min(static_cast<size_t>(std::min(s + g, length) * perSpan), last);
  double slope = 0.0, turning = 0.0;
  for (size_t j = from; j <= to; ++j)
    slope = std::max(slope, slope_[j]), turning = std::max({turning, turning_[j], turning_[j + 1]});
  const double lean = turning / r;
  return std::max(g / std::sqrt(1.0 + slope * slope + lean * lean), cylinder);
}

SurfacePoint RadialDepth::nearest(const Vec3& p) const { return closest(p, false); }

SurfacePoint RadialDepth::nearestFast(const Vec3& p) const { return closestFast(p); }

SurfacePoint RadialDepth::closest(const Vec3& p, bool fast) const {
  double s, a, rho;
  toAxis(p, s, a, rho);
  const double length = parameters_.length;
  const bool inside = contains(p);
  // The side, from the radial projection.
  double t = std::clamp(s, 0.0, length), angle = a;
  const auto side = [this](double ti, double ai) { return sample(ti, ai); };
  Vec3 best = fast ? refineOnSurface(side, p, 0.0, length, t, angle).w : projectOntoSurface(side, p, 0.0, length, t, angle);
  double bestGap = (p - best).norm();
  bool onCap = false;
  Vec3 capNormal;
  // The flat caps: straight onto a cap where p lies over it.
  for (const double capS : {0.0, length}) {
    if (rho > radius(capS, a)) continue;
    const Vec3 q = p - (s - capS) * parameters_.direction;
    const double gap = std::abs(s - capS);
    if (gap < bestGap) best = q, bestGap = gap, onCap = true, capNormal = capS == 0.0 ? -parameters_.direction
                                                                                     : parameters_.direction;
  }
  SurfacePoint out;
  out.point = best;
  out.distance = inside ? -bestGap : bestGap;
  if (!inside && bestGap > 1e-6) out.normal = (p - best) / bestGap;
  else if (onCap) out.normal = capNormal;
  else out.normal = surfaceNormal(side(t, angle), best - (parameters_.base + t * parameters_.direction),
                                  parameters_.direction);
  return out;
}

namespace {
constexpr double kConverged = 1e-6;  // m: a Gauss-Newton step shorter than this ends the search
}  // namespace

SurfacePoint RadialDepth::closestFast(const Vec3& p) const {
  // closest(p, true), the angle carried as (cos a, sin a): refineOnSurface's three
  // Gauss-Newton steps with backtracking, each step turning the angle by rotateAngle.
  double s, cosA, sinA, rho;
  toAxis(p, s, cosA, sinA, rho);
  const double length = parameters_.length;
  const bool inside = s >= 0.0 && s <= length && rho <= std::max(seriesAt(s, cosA, sinA), 0.0);
  double t = std::clamp(s, 0.0, length), c = cosA, sn = sinA;
  SurfaceSample at = sampleAt(t, c, sn);
  double gap2 = (at.w - p).squaredNorm();
  for (int step = 0; step < 3; ++step) {
    const Eigen::Vector2d delta = gaussNewtonStep(at, p);
    double moved = -1.0;  // how far the accepted step moved the point, m
    for (double scale = 1.0; scale > 0.2 && moved < 0.0; scale *= 0.5) {
      const double tNext = std::clamp(t + scale * delta[0], 0.0, length);
      double cNext = c, sNext = sn;
      rotateAngle(scale * delta[1], cNext, sNext);
      const SurfaceSample next = sampleAt(tNext, cNext, sNext);
      const double nextGap2 = (next.w - p).squaredNorm();
      if (nextGap2 < gap2) moved = (next.w - at.w).norm(), t = tNext, c = cNext, sn = sNext, at = next, gap2 = nextGap2;
    }
    // Converged: Gauss-Newton's error shrinks by about p's distance times the surface's
    // curvature per step, so after a step of under 1 um the point is off by ~0.1 um at
    // most, the distance by its square (nothing) and the normal p - w by ~curvature x
    // 1 um (1e-5 rad on a body).
    if (moved < kConverged) break;
  }
  Vec3 best = at.w;
  double bestGap = std::sqrt(gap2);
  bool onCap = false;
  Vec3 capNormal;
  // The flat caps: straight onto a cap where p lies over it (and nearer than the side).
  for (const double capS : {0.0, length}) {
    const double gap = std::abs(s - capS);
    if (gap >= bestGap || rho > std::max(seriesAt(capS, cosA, sinA), 0.0)) continue;
    best = p - (s - capS) * parameters_.direction, bestGap = gap, onCap = true;
    capNormal = capS == 0.0 ? -parameters_.direction : parameters_.direction;
  }
  SurfacePoint out;
  out.point = best;
  out.distance = inside ? -bestGap : bestGap;
  if (!inside && bestGap > 1e-6) out.normal = (p - best) / bestGap;
  else if (onCap) out.normal = capNormal;
  else out.normal = surfaceNormal(at, best - (parameters_.base + t * parameters_.direction), parameters_.direction);
  // Inside, where p does not lie along the side's normal (a deep point's steps stop short
  // of the stationary point), a push-out to point + clearance normal would move p
  // sideways: the normal is then the way out from p to the point.
  if (inside && !onCap && bestGap > 1e-6 && sideways(p - best, out.normal) > kSideways)
    out.normal = (best - p) / bestGap;
  return out;
}

namespace {

// A fit's axis: from `base` along `direction` for `length`, any reference perpendicular
// to it (the world x or z axis made perpendicular), no coefficients yet.
RadialDepthParameters axisFrame(const Vec3& base, const Vec3& direction, double length, int harmonics) {
  RadialDepthParameters p;
  p.base = base;
  p.direction = direction.normalized();
  const Vec3 helper = std::abs(p.direction.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitZ();
  p.reference = (helper - helper.dot(p.direction) * p.direction).normalized();
  p.length = length;
  p.harmonics = harmonics;
  return p;
}

}  // namespace

RadialDepth fitRadialDepth(const TriangleMesh& body, const Vec3& base, const Vec3& direction, double length,
                                 double maxRadius, int sections, int harmonics, int angles) {
  if (sections < 2) throw std::invalid_argument("sections = " + std::to_string(sections) + " must be >= 2");
  if (angles < 2 * harmonics + 1)
    throw std::invalid_argument("angles = " + std::to_string(angles) + " must be >= 2 harmonics + 1");
  RadialDepthParameters p = axisFrame(base, direction, length, harmonics);
  const Vec3 side = p.direction.cross(p.reference);

  // The part's triangles in the axis frame: x along reference, y along the axis, z along side.
  TriangleMesh part;
  std::vector<int> local(body.vertices.size(), -1);
  for (const Triangle& t : body.triangles) {
    const Vec3 centroid = (body.vertices[t[0]] + body.vertices[t[1]] + body.vertices[t[2]]) / 3.0 - base;
    const double along = centroid.dot(p.direction);
    if (along < 0.0 || along > length || (centroid - along * p.direction).norm() > maxRadius) continue;
    Triangle kept;
    for (int k = 0; k < 3; ++k) {
      if (local[t[k]] < 0) {
        local[t[k]] = static_cast<int>(part.vertices.size());
        const Vec3 d = body.vertices[t[k]] - base;
        part.vertices.push_back(Vec3(d.dot(p.reference), d.dot(p.direction), d.dot(side)));
      }
      kept[k] = local[t[k]];
    }
    part.triangles.push_back(kept);
  }
  if (part.triangles.empty()) throw std::invalid_argument("no triangle of the body lies along the axis");

  // Each section: the farthest section point per angular bin, then the Fourier terms
  // (uniform bins: the discrete transform is the least-squares fit).
  const double margin = 1e-4 * length;  // end sections just inside, where the surface is cut
  std::vector<std::vector<double>> coefficients(sections);
  for (int j = 0; j < sections; ++j) {
    const double height = std::clamp(length * j / (sections - 1), margin, length - margin);
    std::vector<double> farthest(angles, -1.0);
    auto take = [&](const Vec2& q) {
      const double angle = std::atan2(q.y(), q.x());
      const int bin = static_cast<int>(std::floor((angle + M_PI) / (2 * M_PI) * angles)) % angles;
      farthest[bin] = std::max(farthest[bin], q.norm());
    };
    for (const Segment2& segment : planeSection(part, SectionAxis::Y, height)) take(segment.a), take(segment.b);
    // The vertices between this section and its neighbours count too: the volume
    // interpolates between sections, so each section must reach what lies next to it.
    const double spacing = length / (sections - 1);
    for (const Vec3& v : part.vertices)
      if (std::abs(v.y() - length * j / (sections - 1)) < spacing) take(Vec2(v.x(), v.z()));
    // Empty bins take the nearer filled neighbour's value (a coarse section).
    for (int pass = 0; pass < angles; ++pass)
      for (int b = 0; b < angles; ++b)
        if (farthest[b] < 0.0) farthest[b] = std::max(farthest[(b + 1) % angles], farthest[(b + angles - 1) % angles]);
    std::vector<double> c(2 * harmonics + 1, 0.0);
    if (farthest[0] >= 0.0) {
      for (int b = 0; b < angles; ++b) {
        const double angle = -M_PI + (b + 0.5) * 2 * M_PI / angles;
        c[0] += farthest[b] / angles;
        for (int k = 1; k <= harmonics; ++k) {
          c[2 * k - 1] += 2.0 * farthest[b] * std::cos(k * angle) / angles;
          c[2 * k] += 2.0 * farthest[b] * std::sin(k * angle) / angles;
        }
      }
    }
    coefficients[j] = c;
  }
  p.coefficients = coefficients;

  // Enclosure: each vertex outside raises the constant term of the sections around it
  // by its shortfall (linear interpolation: raising both raises r there by as much).
  RadialDepth fitted(p);
  std::vector<double> raise(sections, 0.0);
  for (const Vec3& v : part.vertices) {
    double s, a, rho;
    fitted.toAxis(base + v.x() * p.reference + v.y() * p.direction + v.z() * side, s, a, rho);
    if (s < 0.0 || s > length) continue;
    const double shortfall = rho - fitted.radius(s, a);
    if (shortfall <= 0.0) continue;
    const double x = s / length * (sections - 1);
    const int j = std::min(static_cast<int>(x), sections - 2);
    raise[j] = std::max(raise[j], shortfall * 1.0001);
    raise[j + 1] = std::max(raise[j + 1], shortfall * 1.0001);
  }
  for (int j = 0; j < sections; ++j) p.coefficients[j][0] += raise[j];
  return RadialDepth(p);
}

}  // namespace figment

namespace figment {

namespace {

// Grows the constant terms of `p` until every point of `enclose` on the axis is inside.
void encloseBySection(RadialDepthParameters& p, const std::vector<Vec3>& enclose) {
  const int sections = static_cast<int>(p.coefficients.size());
  for (int pass = 0; pass < 3; ++pass) {
    const RadialDepth fitted(p);
    std::vector<double> raise(sections, 0.0);
    bool any = false;
    for (const Vec3& v : enclose) {
      double s, a, rho;
      fitted.toAxis(v, s, a, rho);
      if (s < 0.0 || s > p.length) continue;
      const double shortfall = rho - fitted.radius(s, a);
      if (shortfall <= 0.0) continue;
      const double x = s / p.length * (sections - 1);
      const int j = std::min(static_cast<int>(x), sections - 2);
      raise[j] = std::max(raise[j], shortfall * 1.0001 + 1e-9);
      raise[j + 1] = std::max(raise[j + 1], shortfall * 1.0001 + 1e-9);
      any = true;
    }
    if (!any) return;
    for (int j = 0; j < sections; ++j) p.coefficients[j][0] += raise[j];
  }
}

}  // namespace

RadialDepth fitRadialDepthToPoints(const std::vector<Vec3>& points, const std::vector<Vec3>& enclose,
                                         const Vec3& base, const Vec3& direction, double length, int sections,
                                         int harmonics, double outsideWeight) {
  if (sections < 2) throw std::invalid_argument("sections = " + std::to_string(sections) + " must be >= 2");
  if (points.empty()) throw std::invalid_argument("no points to fit");
  RadialDepthParameters p = axisFrame(base, direction, length, harmonics);
  const Vec3 side = p.direction.cross(p.reference);
  const int terms = 2 * harmonics + 1, unknowns = sections * terms;

  // Each point's row: its section pair j, j + 1, the interpolation weight and the basis.
  struct Row {
    int j;
    double f, rho;
    std::vector<double> basis;
  };
  std::vector<Row> rows;
  rows.reserve(points.size());
  for (const Vec3& v : points) {
    const Vec3 d = v - base;
    const double s = std::clamp(d.dot(p.direction), 0.0, length);
    const Vec3 across = d - d.dot(p.direction) * p.direction;
    const double a = std::atan2(across.dot(side), across.dot(p.reference));
    const double x = s / length * (sections - 1);
    Row r{std::min(static_cast<int>(x), sections - 2), 0.0, across.norm(), std::vector<double>(terms)};
    r.f = x - r.j;
    r.basis[0] = 1.0;
    for (int k = 1; k <= harmonics; ++k) r.basis[2 * k - 1] = std::cos(k * a), r.basis[2 * k] = std::sin(k * a);
    rows.push_back(std::move(r));
  }
  // Smoothness: a small multiple of the data's weight.
  Eigen::MatrixXd penalty = Eigen::MatrixXd::Zero(unknowns, unknowns);
  const double scale = 1e-3 * static_cast<double>(points.size()) / sections;
  for (int j = 0; j < sections; ++j)
    for (int k = 1; k <= harmonics; ++k)
      for (int i : {2 * k - 1, 2 * k}) penalty(j * terms + i, j * terms + i) += scale * std::pow(k, 4) * 1e-2;
  for (int j = 1; j + 1 < sections; ++j)
    for (int i = 0; i < terms; ++i) {
      const int c[3] = {(j - 1) * terms + i, j * terms + i, (j + 1) * terms + i};
      const double w[3] = {1.0, -2.0, 1.0};
      for (int m = 0; m < 3; ++m)
        for (int n = 0; n < 3; ++n) penalty(c[m], c[n]) += scale * w[m] * w[n];
    }
  std::vector<double> weight(rows.size(), 1.0);
  Eigen::VectorXd solution = Eigen::VectorXd::Zero(unknowns);
  for (int iteration = 0; iteration < 12; ++iteration) {
    Eigen::MatrixXd normal = penalty;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
    for (size_t n = 0; n < rows.size(); ++n) {
      const Row& r = rows[n];
      const double w = weight[n];
      for (int side0 = 0; side0 < 2; ++side0) {
        const double f0 = side0 ? r.f : 1.0 - r.f;
        const int o0 = (r.j + side0) * terms;
        for (int i = 0; i < terms; ++i) {
          const double bi = w * f0 * r.basis[i];
          rhs[o0 + i] += bi * r.rho;
          for (int side1 = 0; side1 < 2; ++side1) {
            const double f1 = side1 ? r.f : 1.0 - r.f;
            const int o1 = (r.j + side1) * terms;
            for (int m = 0; m < terms; ++m) normal(o0 + i, o1 + m) += bi * f1 * r.basis[m];
          }
        }
      }
    }
    solution = normal.ldlt().solve(rhs);
    bool changed = false;
    for (size_t n = 0; n < rows.size(); ++n) {
      const Row& r = rows[n];
      double value = 0.0;
      for (int i = 0; i < terms; ++i)
        value += ((1.0 - r.f) * solution[r.j * terms + i] + r.f * solution[(r.j + 1) * terms + i]) * r.basis[i];
      const double w = value < r.rho ? outsideWeight : 1.0;
      changed |= w != weight[n];
      weight[n] = w;
    }
    if (!changed) break;
  }
  p.coefficients.assign(sections, std::vector<double>(terms));
  for (int j = 0; j < sections; ++j)
    for (int i = 0; i < terms; ++i) p.coefficients[j][i] = solution[j * terms + i];
  encloseBySection(p, enclose);
  return RadialDepth(p);
}

}  // namespace figment
