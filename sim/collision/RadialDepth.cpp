#include "sim/collision/RadialDepth.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/collision/SurfaceProjection.h"
#include "sim/core/ParameterChecks.h"

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
                                  std::to_string(coefficients[j].size()) +
                                  " values, need 2 harmonics + 1 = " + std::to_string(2 * harmonics + 1));
}

RadialDepth::RadialDepth(RadialDepthParameters parameters) : parameters_(std::move(parameters)) {
  parameters_.validate();
  parameters_.direction.normalize();
  parameters_.reference.normalize();
  side_ = parameters_.direction.cross(parameters_.reference);
  // The table, and the bounds distanceBound() relies on (see the header): each from the
  // function's largest value on a grid of kGrid angles plus pi / kGrid times a bound of
  // its derivative (every angle lies within pi / kGrid of a grid angle). cos k a and sin k a
  // are the same for every section: taken once per grid angle (per section and bound, they
  // were most of the time a scene took to read its radial volumes).
  const auto& c = parameters_.coefficients;
  const int harmonics = parameters_.harmonics;
  const size_t sections = c.size();
  const double spacing = parameters_.length / static_cast<double>(sections - 1);
  constexpr int kGrid = 256;
  std::vector<double> turningMost(sections, 0.0), slopeMost(sections - 1, 0.0);
  std::vector<double> cosines(harmonics + 1), sines(harmonics + 1);
  for (int i = 0; i < kGrid; ++i) {
    const double a = 2 * M_PI * i / kGrid;
    for (int k = 1; k <= harmonics; ++k) cosines[k] = std::cos(k * a), sines[k] = std::sin(k * a);
    for (size_t j = 0; j < sections; ++j) {
      double turning = 0.0;  // d r_j / d a
      for (int k = 1; k <= harmonics; ++k) turning += k * (c[j][2 * k] * cosines[k] - c[j][2 * k - 1] * sines[k]);
      turningMost[j] = std::max(turningMost[j], std::abs(turning));
      if (j + 1 == sections) break;
      double change = c[j + 1][0] - c[j][0];  // r_{j+1}(a) - r_j(a)
      for (int k = 1; k <= harmonics; ++k)
        change += (c[j + 1][2 * k - 1] - c[j][2 * k - 1]) * cosines[k] + (c[j + 1][2 * k] - c[j][2 * k]) * sines[k];
      slopeMost[j] = std::max(slopeMost[j], std::abs(change));
    }
  }
  for (size_t j = 0; j < sections; ++j) {
    table_.insert(table_.end(), c[j].begin(), c[j].end());
    double amplitude = 0.0, curvature = 0.0;  // sum |harmonic k|, sum k^2 |harmonic k|
    for (int k = 1; k <= harmonics; ++k) {
      const double a = std::hypot(c[j][2 * k - 1], c[j][2 * k]);
      amplitude += a, curvature += k * k * a;
    }
    rMax_ = std::max(rMax_, c[j][0] + amplitude);
    turning_.push_back(turningMost[j] + M_PI / kGrid * curvature);
    if (j + 1 == sections) break;
    double change = 0.0;  // sum k |harmonic k of the difference to the next section|
    for (int k = 1; k <= harmonics; ++k)
      change += k * std::hypot(c[j + 1][2 * k - 1] - c[j][2 * k - 1], c[j + 1][2 * k] - c[j][2 * k]);
    slope_.push_back((slopeMost[j] + M_PI / kGrid * change) / spacing);
  }
}

namespace {
// Turns the direction (c, s) = (cos b, sin b) by the angle whose cosine and sine are (cd, sd).
inline void turn(double& c, double& s, double cd, double sd) {
  const double next = c * cd - s * sd;
  s = s * cd + c * sd, c = next;
}

// closest's and closestFast's answer: `best`, `gap` from p (negative inside). Its normal points
// from `best` to p where p lies off the surface, else along the cap's normal when `best` is on
// a cap, else the side's (sideNormal(), computed only then).
template <typename SideNormal>
SurfacePoint surfacePoint(const Vec3& p, const Vec3& best, double gap, bool inside, const Vec3* capNormal,
                          SideNormal sideNormal) {
  SurfacePoint out;
  out.point = best;
  out.distance = inside ? -gap : gap;
  if (!inside && gap > 1e-6)
    out.normal = (p - best) / gap;
  else if (capNormal)
    out.normal = *capNormal;
  else
    out.normal = sideNormal();
  return out;
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
    if (k < harmonics)
      even += (g * c0[2 * k + 1] + f * c1[2 * k + 1]) * ce + (g * c0[2 * k + 2] + f * c1[2 * k + 2]) * se;
    turn(co, so, cos2, sin2), turn(ce, se, cos2, sin2);
  }
  return odd + even;
}

double RadialDepth::radius(double s, double a) const {
  return std::max(seriesAt(s, std::cos(a), std::sin(a)), 0.0);
}

SurfaceSample RadialDepth::sample(double s, double a) const {
  return sampleAt(s, std::cos(a), std::sin(a));
}

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
  return {parameters_.base + s * parameters_.direction + radiusHere * radial, parameters_.direction + rs * radial,
          (clamped ? 0.0 : ra) * radial + radiusHere * turning};
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
  if (h > 0.0)
    cosA = x / h, sinA = y / h;
  else
    cosA = 1.0, sinA = 0.0;  // on the axis: atan2's angle 0
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

SurfacePoint RadialDepth::nearest(const Vec3& p) const {
  return closest(p, false);
}

SurfacePoint RadialDepth::nearestFast(const Vec3& p) const {
  return closestFast(p);
}

SurfacePoint RadialDepth::closest(const Vec3& p, bool fast) const {
  double s, a, rho;
  toAxis(p, s, a, rho);
  const double length = parameters_.length;
  const bool inside = contains(p);
  // The side, from the radial projection.
  double t = std::clamp(s, 0.0, length), angle = a;
  const auto side = [this](double ti, double ai) { return sample(ti, ai); };
  Vec3 best =
      fast ? refineOnSurface(side, p, 0.0, length, t, angle).w : projectOntoSurface(side, p, 0.0, length, t, angle);
  double bestGap = (p - best).norm();
  bool onCap = false;
  Vec3 capNormal;
  // The flat caps: straight onto a cap where p lies over it.
  for (const double capS : {0.0, length}) {
    if (rho > radius(capS, a)) continue;
    const Vec3 q = p - (s - capS) * parameters_.direction;
    const double gap = std::abs(s - capS);
    if (gap < bestGap)
      best = q, bestGap = gap, onCap = true, capNormal = capS == 0.0 ? -parameters_.direction : parameters_.direction;
  }
  return surfacePoint(p, best, bestGap, inside, onCap ? &capNormal : nullptr, [&] {
    return surfaceNormal(side(t, angle), best - (parameters_.base + t * parameters_.direction), parameters_.direction);
  });
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
  SurfacePoint out = surfacePoint(p, best, bestGap, inside, onCap ? &capNormal : nullptr, [&] {
    return surfaceNormal(at, best - (parameters_.base + t * parameters_.direction), parameters_.direction);
  });
  // Inside, where p does not lie along the side's normal (a deep point's steps stop short
  // of the stationary point), a push-out to point + clearance normal would move p
  // sideways: the normal is then the way out from p to the point.
  if (inside && !onCap && bestGap > 1e-6 && sideways(p - best, out.normal) > kSideways)
    out.normal = (best - p) / bestGap;
  return out;
}

}  // namespace figment
