#include "sim/volumes/RadialDepthShaping.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/body/BodySlices.h"

namespace figment {

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

// Per section of `fitted`, how much its constant term must grow for every point of
// `points` on the axis to be inside: each point's shortfall, times 1.0001 plus `pad` (m),
// raises both sections around it (linear interpolation: raising both raises r there by
// as much). All zero when every point is inside.
std::vector<double> sectionShortfalls(const RadialDepth& fitted, const std::vector<Vec3>& points, double pad) {
  const double length = fitted.parameters().length;
  const int sections = static_cast<int>(fitted.parameters().coefficients.size());
  std::vector<double> raise(sections, 0.0);
  for (const Vec3& v : points) {
    double s, a, rho;
    fitted.toAxis(v, s, a, rho);
    if (s < 0.0 || s > length) continue;
    const double shortfall = rho - fitted.radius(s, a);
    if (shortfall <= 0.0) continue;
    const double x = s / length * (sections - 1);
    const int j = std::min(static_cast<int>(x), sections - 2);
    raise[j] = std::max(raise[j], shortfall * 1.0001 + pad);
    raise[j + 1] = std::max(raise[j + 1], shortfall * 1.0001 + pad);
  }
  return raise;
}

void raiseSections(RadialDepthParameters& p, const std::vector<double>& raise) {
  for (size_t j = 0; j < raise.size(); ++j) p.coefficients[j][0] += raise[j];
}

// The triangles of `body` whose centroid projects onto the axis of `p` and lies within
// `maxRadius` of it, in the axis frame: x along reference, y along the axis, z along side.
TriangleMesh partInAxisFrame(const TriangleMesh& body, const RadialDepthParameters& p, double maxRadius) {
  const Vec3 side = p.direction.cross(p.reference);
  TriangleMesh part;
  std::vector<int> local(body.vertices.size(), -1);
  for (const Triangle& t : body.triangles) {
    const Vec3 centroid = (body.vertices[t[0]] + body.vertices[t[1]] + body.vertices[t[2]]) / 3.0 - p.base;
    const double along = centroid.dot(p.direction);
    if (along < 0.0 || along > p.length || (centroid - along * p.direction).norm() > maxRadius) continue;
    Triangle kept;
    for (int k = 0; k < 3; ++k) {
      if (local[t[k]] < 0) {
        local[t[k]] = static_cast<int>(part.vertices.size());
        const Vec3 d = body.vertices[t[k]] - p.base;
        part.vertices.push_back(Vec3(d.dot(p.reference), d.dot(p.direction), d.dot(side)));
      }
      kept[k] = local[t[k]];
    }
    part.triangles.push_back(kept);
  }
  if (part.triangles.empty()) throw std::invalid_argument("no triangle of the body lies along the axis");
  return part;
}

// Section j of `part` (in the axis frame): the farthest section point per angular bin,
// all -1 when the section is empty.
std::vector<double> farthestPerBin(const TriangleMesh& part, double length, int sections, int j, int angles) {
  const double margin = 1e-4 * length;  // end sections just inside, where the surface is cut
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
  return farthest;
}

// The Fourier terms of the depths per uniform bin (there the discrete transform is the
// least-squares fit); all zero for an empty section.
std::vector<double> fourierTerms(const std::vector<double>& farthest, int harmonics) {
  const int angles = static_cast<int>(farthest.size());
  std::vector<double> c(2 * harmonics + 1, 0.0);
  if (farthest[0] < 0.0) return c;
  for (int b = 0; b < angles; ++b) {
    const double angle = -M_PI + (b + 0.5) * 2 * M_PI / angles;
    c[0] += farthest[b] / angles;
    for (int k = 1; k <= harmonics; ++k) {
      c[2 * k - 1] += 2.0 * farthest[b] * std::cos(k * angle) / angles;
      c[2 * k] += 2.0 * farthest[b] * std::sin(k * angle) / angles;
    }
  }
  return c;
}

// A point's row in the envelope fit: its section pair j, j + 1, the interpolation
// weight f, its radial depth and the Fourier basis at its angle.
struct Row {
  int j;
  double f, rho;
  std::vector<double> basis;
};

std::vector<Row> pointRows(const std::vector<Vec3>& points, const RadialDepthParameters& p, int sections) {
  const Vec3 side = p.direction.cross(p.reference);
  const int harmonics = p.harmonics, terms = 2 * harmonics + 1;
  std::vector<Row> rows;
  rows.reserve(points.size());
  for (const Vec3& v : points) {
    const Vec3 d = v - p.base;
    const double s = std::clamp(d.dot(p.direction), 0.0, p.length);
    const Vec3 across = d - d.dot(p.direction) * p.direction;
    const double a = std::atan2(across.dot(side), across.dot(p.reference));
    const double x = s / p.length * (sections - 1);
    Row r{std::min(static_cast<int>(x), sections - 2), 0.0, across.norm(), std::vector<double>(terms)};
    r.f = x - r.j;
    r.basis[0] = 1.0;
    for (int k = 1; k <= harmonics; ++k) r.basis[2 * k - 1] = std::cos(k * a), r.basis[2 * k] = std::sin(k * a);
    rows.push_back(std::move(r));
  }
  return rows;
}

// Smoothness: second differences along the axis and k^4-weighted harmonics, a small
// multiple of the data's weight (`pointCount` points).
Eigen::MatrixXd smoothnessPenalty(int sections, int harmonics, size_t pointCount) {
  const int terms = 2 * harmonics + 1, unknowns = sections * terms;
  Eigen::MatrixXd penalty = Eigen::MatrixXd::Zero(unknowns, unknowns);
  const double scale = 1e-3 * static_cast<double>(pointCount) / sections;
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
  return penalty;
}

// The weighted least-squares solution for `rows`: all sections' coefficients, `terms`
// per section.
Eigen::VectorXd weightedSolution(const std::vector<Row>& rows, const std::vector<double>& weight,
                                 const Eigen::MatrixXd& penalty, int terms) {
  Eigen::MatrixXd normal = penalty;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(penalty.rows());
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
  return normal.ldlt().solve(rhs);
}

// The envelope: solved again with each row that falls short weighing `outsideWeight`,
// until the weights settle (at most 12 solves).
Eigen::VectorXd envelopeSolution(const std::vector<Row>& rows, const Eigen::MatrixXd& penalty, int terms,
                                 double outsideWeight) {
  std::vector<double> weight(rows.size(), 1.0);
  Eigen::VectorXd solution = Eigen::VectorXd::Zero(penalty.rows());
  for (int iteration = 0; iteration < 12; ++iteration) {
    solution = weightedSolution(rows, weight, penalty, terms);
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
  return solution;
}

// Grows the constant terms of `p` until every point of `enclose` on the axis is inside
// (at most three passes).
void encloseBySection(RadialDepthParameters& p, const std::vector<Vec3>& enclose) {
  for (int pass = 0; pass < 3; ++pass) {
    const std::vector<double> raise = sectionShortfalls(RadialDepth(p), enclose, 1e-9);
    if (std::all_of(raise.begin(), raise.end(), [](double r) { return r == 0.0; })) return;
    raiseSections(p, raise);
  }
}

}  // namespace

RadialDepth shapeRadialDepth(const TriangleMesh& body, const Vec3& base, const Vec3& direction, double length,
                             double maxRadius, int sections, int harmonics, int angles) {
  if (sections < 2) throw std::invalid_argument("sections = " + std::to_string(sections) + " must be >= 2");
  if (angles < 2 * harmonics + 1)
    throw std::invalid_argument("angles = " + std::to_string(angles) + " must be >= 2 harmonics + 1");
  RadialDepthParameters p = axisFrame(base, direction, length, harmonics);
  const TriangleMesh part = partInAxisFrame(body, p, maxRadius);
  p.coefficients.resize(sections);
  for (int j = 0; j < sections; ++j)
    p.coefficients[j] = fourierTerms(farthestPerBin(part, length, sections, j, angles), harmonics);
  // Enclosure: the part's vertices back in the world.
  const Vec3 side = p.direction.cross(p.reference);
  std::vector<Vec3> vertices;
  vertices.reserve(part.vertices.size());
  for (const Vec3& v : part.vertices)
    vertices.push_back(base + v.x() * p.reference + v.y() * p.direction + v.z() * side);
  raiseSections(p, sectionShortfalls(RadialDepth(p), vertices, 0.0));
  return RadialDepth(p);
}

RadialDepth shapeRadialDepthToPoints(const std::vector<Vec3>& points, const std::vector<Vec3>& enclose,
                                     const Vec3& base, const Vec3& direction, double length, int sections,
                                     int harmonics, double outsideWeight) {
  if (sections < 2) throw std::invalid_argument("sections = " + std::to_string(sections) + " must be >= 2");
  if (points.empty()) throw std::invalid_argument("no points to fit");
  RadialDepthParameters p = axisFrame(base, direction, length, harmonics);
  const int terms = 2 * harmonics + 1;
  const Eigen::VectorXd solution = envelopeSolution(
      pointRows(points, p, sections), smoothnessPenalty(sections, harmonics, points.size()), terms, outsideWeight);
  p.coefficients.assign(sections, std::vector<double>(terms));
  for (int j = 0; j < sections; ++j)
    for (int i = 0; i < terms; ++i) p.coefficients[j][i] = solution[j * terms + i];
  encloseBySection(p, enclose);
  return RadialDepth(p);
}

}  // namespace figment
