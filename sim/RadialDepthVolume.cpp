#include "RadialDepthVolume.h"

#include "BodySlices.h"
#include "SurfaceProjection.h"
#include "Validation.h"

#include <algorithm>
#include <cmath>
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

RadialDepthVolume::RadialDepthVolume(RadialDepthParameters parameters) : parameters_(std::move(parameters)) {
  parameters_.validate();
  parameters_.direction.normalize();
  parameters_.reference.normalize();
  side_ = parameters_.direction.cross(parameters_.reference);
}

double RadialDepthVolume::radius(double s, double a) const {
  const auto& c = parameters_.coefficients;
  const double x = std::clamp(s / parameters_.length, 0.0, 1.0) * static_cast<double>(c.size() - 1);
  const size_t j = std::min(static_cast<size_t>(x), c.size() - 2);
  const double f = x - static_cast<double>(j);
  double r = 0.0;
  for (int k = 0; k <= parameters_.harmonics; ++k) {
    auto at = [&](size_t i) { return (1.0 - f) * c[j][i] + f * c[j + 1][i]; };
    r += k == 0 ? at(0) : at(2 * k - 1) * std::cos(k * a) + at(2 * k) * std::sin(k * a);
  }
  return std::max(r, 0.0);
}

SurfaceSample RadialDepthVolume::sample(double s, double a) const {
  // r and its derivatives: linear in s between sections, a Fourier series in a.
  const auto& c = parameters_.coefficients;
  const double spacing = parameters_.length / static_cast<double>(c.size() - 1);
  const double x = std::clamp(s / parameters_.length, 0.0, 1.0) * static_cast<double>(c.size() - 1);
  const size_t j = std::min(static_cast<size_t>(x), c.size() - 2);
  const double f = x - static_cast<double>(j);
  double r0 = 0.0, r1 = 0.0, ra = 0.0;  // r at sections j and j + 1; dr/da interpolated
  for (int k = 0; k <= parameters_.harmonics; ++k) {
    if (k == 0) {
      r0 += c[j][0], r1 += c[j + 1][0];
      continue;
    }
    const double ck = std::cos(k * a), sk = std::sin(k * a);
    r0 += c[j][2 * k - 1] * ck + c[j][2 * k] * sk;
    r1 += c[j + 1][2 * k - 1] * ck + c[j + 1][2 * k] * sk;
    ra += k * ((1.0 - f) * (c[j][2 * k] * ck - c[j][2 * k - 1] * sk) + f * (c[j + 1][2 * k] * ck - c[j + 1][2 * k - 1] * sk));
  }
  const double r = (1.0 - f) * r0 + f * r1;
  const bool clamped = r < 0.0;  // radius() clamps at 0: a point on the axis
  const double rs = clamped ? 0.0 : (r1 - r0) / spacing;
  const Vec3 radial = std::cos(a) * parameters_.reference + std::sin(a) * side_;
  const Vec3 turning = -std::sin(a) * parameters_.reference + std::cos(a) * side_;
  const double radiusHere = std::max(r, 0.0);
  return {parameters_.base + s * parameters_.direction + radiusHere * radial,
          parameters_.direction + rs * radial, (clamped ? 0.0 : ra) * radial + radiusHere * turning};
}

Vec3 RadialDepthVolume::surface(double s, double a) const {
  return parameters_.base + s * parameters_.direction +
         radius(s, a) * (std::cos(a) * parameters_.reference + std::sin(a) * side_);
}

void RadialDepthVolume::toAxis(const Vec3& p, double& s, double& a, double& rho) const {
  const Vec3 d = p - parameters_.base;
  s = d.dot(parameters_.direction);
  const Vec3 across = d - s * parameters_.direction;
  rho = across.norm();
  a = std::atan2(across.dot(side_), across.dot(parameters_.reference));
}

bool RadialDepthVolume::contains(const Vec3& p) const {
  double s, a, rho;
  toAxis(p, s, a, rho);
  return s >= 0.0 && s <= parameters_.length && rho <= radius(s, a);
}

SurfacePoint RadialDepthVolume::nearest(const Vec3& p) const { return closest(p, false); }

SurfacePoint RadialDepthVolume::nearestFast(const Vec3& p) const { return closest(p, true); }

SurfacePoint RadialDepthVolume::closest(const Vec3& p, bool fast) const {
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

RadialDepthVolume fitRadialDepth(const TriangleMesh& body, const Vec3& base, const Vec3& direction, double length,
                                 double maxRadius, int sections, int harmonics, int angles) {
  if (sections < 2) throw std::invalid_argument("sections = " + std::to_string(sections) + " must be >= 2");
  if (angles < 2 * harmonics + 1)
    throw std::invalid_argument("angles = " + std::to_string(angles) + " must be >= 2 harmonics + 1");
  RadialDepthParameters p;
  p.base = base;
  p.direction = direction.normalized();
  // Any reference perpendicular to the axis: the world x or z axis, made perpendicular.
  const Vec3 helper = std::abs(p.direction.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitZ();
  p.reference = (helper - helper.dot(p.direction) * p.direction).normalized();
  p.length = length;
  p.harmonics = harmonics;
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
  RadialDepthVolume fitted(p);
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
  return RadialDepthVolume(p);
}

}  // namespace figment
