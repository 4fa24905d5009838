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
  const std::vector<double>&c0 = c[j], &c1 = c[j + 1];
  // cos k a, sin k a by the angle-addition recurrence: one cos and one sin in all.
  const double ca = std::cos(a), sa = std::sin(a);
  double ck = 1.0, sk = 0.0, r = (1.0 - f) * c0[0] + f * c1[0];
  for (int k = 1; k <= parameters_.harmonics; ++k) {
    const double next = ck * ca - sk * sa;
    sk = sk * ca + ck * sa, ck = next;
    r += ((1.0 - f) * c0[2 * k - 1] + f * c1[2 * k - 1]) * ck + ((1.0 - f) * c0[2 * k] + f * c1[2 * k]) * sk;
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
  const double cosA = std::cos(a), sinA = std::sin(a);
  double ck = 1.0, sk = 0.0;
  for (int k = 0; k <= parameters_.harmonics; ++k) {
    if (k == 0) {
      r0 += c[j][0], r1 += c[j + 1][0];
      continue;
    }
    const double next = ck * cosA - sk * sinA;
    sk = sk * cosA + ck * sinA, ck = next;
    r0 += c[j][2 * k - 1] * ck + c[j][2 * k] * sk;
    r1 += c[j + 1][2 * k - 1] * ck + c[j + 1][2 * k] * sk;
    ra += k * ((1.0 - f) * (c[j][2 * k] * ck - c[j][2 * k - 1] * sk) + f * (c[j + 1][2 * k] * ck - c[j + 1][2 * k - 1] * sk));
  }
  const double r = (1.0 - f) * r0 + f * r1;
  const bool clamped = r < 0.0;  // radius() clamps at 0: a point on the axis
  const double rs = clamped ? 0.0 : (r1 - r0) / spacing;
  const Vec3 radial = cosA * parameters_.reference + sinA * side_;
  const Vec3 turning = -sinA * parameters_.reference + cosA * side_;
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

namespace figment {

namespace {

// Grows the constant terms of `p` until every point of `enclose` on the axis is inside.
void encloseBySection(RadialDepthParameters& p, const std::vector<Vec3>& enclose) {
  const int sections = static_cast<int>(p.coefficients.size());
  for (int pass = 0; pass < 3; ++pass) {
    const RadialDepthVolume fitted(p);
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

RadialDepthVolume fitRadialDepthToPoints(const std::vector<Vec3>& points, const std::vector<Vec3>& enclose,
                                         const Vec3& base, const Vec3& direction, double length, int sections,
                                         int harmonics, double outsideWeight) {
  if (sections < 2) throw std::invalid_argument("sections = " + std::to_string(sections) + " must be >= 2");
  if (points.empty()) throw std::invalid_argument("no points to fit");
  RadialDepthParameters p;
  p.base = base;
  p.direction = direction.normalized();
  const Vec3 helper = std::abs(p.direction.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitZ();
  p.reference = (helper - helper.dot(p.direction) * p.direction).normalized();
  p.length = length;
  p.harmonics = harmonics;
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
  return RadialDepthVolume(p);
}

}  // namespace figment
