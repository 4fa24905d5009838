#include "sim/volumes/CapsuleShaping.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "sim/core/PrincipalAxes.h"

namespace figment {

namespace {

CapsuleParameters parametersOf(const std::vector<double>& genes) {
  std::array<double, 12> values;
  std::copy(genes.begin(), genes.end(), values.begin());
  return CapsuleParameters::fromValues(values);
}

// The capsule's 12 values as genes from `start`: their limits and mutation steps for a
// part of this size (m) around its centre, and the cost of the options.
GeneticProblem capsuleProblem(const CapsuleParameters& start, double size, const std::vector<Vec3>& points,
                              const CapsuleShapingOptions& options) {
  const std::array<double, 12> values = start.values();
  const Vec3 centre(start.ox, start.oy, start.oz);
  GeneticProblem problem;
  problem.start.assign(values.begin(), values.end());
  problem.low = {0,
                 0,
                 -1.5,
                 -1.5,
                 0.01 * size,
                 0.01 * size,
                 0.01 * size,
                 centre.x() - size,
                 centre.y() - size,
                 centre.z() - size,
                 -M_PI,
                 -M_PI};
  problem.high = {
      1,    1,   1.5, 1.5, 3 * size, 3 * size, 3 * size, centre.x() + size, centre.y() + size, centre.z() + size,
      M_PI, M_PI};
  problem.step = {0.1,         0.1,         0.1,         0.1,         0.03 * size, 0.03 * size,
                  0.03 * size, 0.01 * size, 0.01 * size, 0.01 * size, 0.03,        0.1};
  problem.cost = [&points, options](const std::vector<double>& genes) {
    const CapsuleParameters c = parametersOf(genes);
    return options.costAfterEnclosure ? enclosedCapsuleCost(c, points)
                                      : capsuleCost(Capsule(c), points, options.outsideWeight);
  };
  return problem;
}

// The options' shares as counts of members (rounded down; at least 4 members and one
// parent).
GeneticSchedule scheduleOf(const CapsuleShapingOptions& options) {
  GeneticSchedule schedule;
  const int n = std::max(options.population, 4);
  schedule.population = n;
  schedule.generations = options.generations;
  schedule.mutants = static_cast<int>(options.mutationShare * n);
  schedule.crossovers = static_cast<int>(options.crossoverShare * n);
  schedule.parents = std::max(1, static_cast<int>(options.parentShare * n));
  schedule.mutationDeviation = 1.0;  // of the step
  schedule.seed = options.seed;
  return schedule;
}

}  // namespace

// The default capsule set on the points: centred, along their principal axis, as big
// as their extents.
CapsuleParameters startingCapsule(const std::vector<Vec3>& points) {
  const PrincipalAxes principal = principalAxes(points);
  const Vec3& mean = principal.mean;
  Vec3 axis = principal.axes.col(2);  // the largest spread's
  if (axis.y() < 0.0) axis = -axis;
  CapsuleParameters c;
  c.r1 = c.r2 = 0.5;
  c.tiltOnto(axis);
  const Eigen::Matrix3d R = c.tilt();
  Vec3 low = Vec3::Constant(1e300), high = Vec3::Constant(-1e300);
  for (const Vec3& p : points) {
    const Vec3 local = R.transpose() * (p - mean);
    low = low.cwiseMin(local), high = high.cwiseMax(local);
  }
  const Vec3 extent = (high - low).cwiseMax(1e-6);
  const Vec3 centre = mean + R * (0.5 * (low + high));
  c.x = extent.x(), c.y = extent.y(), c.z = extent.z();
  c.ox = centre.x(), c.oy = centre.y(), c.oz = centre.z();
  return c;
}

double growToEnclose(CapsuleParameters& c, const std::vector<Vec3>& points) {
  auto enclosesAt = [&](double s) {
    CapsuleParameters grown = c;
    grown.x *= s, grown.y *= s, grown.z *= s;
    const Capsule capsule(grown);
    for (const Vec3& p : points)
      if (!capsule.contains(p)) return false;
    return true;
  };
  double low = 1.0, high = 1.0;
  while (!enclosesAt(high)) low = high, high *= 1.25;
  if (high == 1.0) return 1.0;
  while (high / low > 1.001) {
    const double mid = 0.5 * (low + high);
    (enclosesAt(mid) ? high : low) = mid;
  }
  c.x *= high, c.y *= high, c.z *= high;
  return high;
}

double capsuleCost(const Capsule& capsule, const std::vector<Vec3>& points, double outsideWeight) {
  double total = 0.0;
  for (const Vec3& p : points) {
    const Vec3 u = capsule.toUnit(p);  // once: the cost runs for every member and vertex
    const double squared = (capsule.fromUnit(capsule.unitProjection(u)) - p).squaredNorm();
    total += capsule.containsUnit(u) ? squared : outsideWeight * squared;
  }
  return total / static_cast<double>(points.size());
}

double unitGauge(const Capsule& capsule, const Vec3& u) {
  const CapsuleParameters& c = capsule.parameters();
  const double rho = std::sqrt(u.x() * u.x() + u.z() * u.z());
  const double y = std::abs(u.y());
  const double h = 0.5 * (u.y() >= 0.0 ? c.r2 : c.r1), top = 0.5 - h;  // the end's half-height, its start
  const double cylinder = 2.0 * rho;
  if (y <= top * cylinder) return cylinder;
  // On the end: (rho / s)^2 / 0.25 + ((y / s - top) / h)^2 = 1, the smallest positive s.
  if (h <= 0.0) return y / top;
  const double a = top * top - h * h, b = -2.0 * y * top, k = y * y + 4.0 * h * h * rho * rho;
  if (std::abs(a) < 1e-12) return k / (-b);
  const double root = std::sqrt(std::max(0.0, b * b - 4.0 * a * k));
  const double s1 = (-b - root) / (2.0 * a), s2 = (-b + root) / (2.0 * a);
  const double low = std::min(s1, s2), high = std::max(s1, s2);
  return low > 0.0 ? low : high;
}

double enclosedCapsuleCost(const CapsuleParameters& parameters, const std::vector<Vec3>& points) {
  // The growth in fixed-point steps: grown by the largest gauge, the taper moves the
  // points' unit coordinates a little, so measure again (three passes settle it).
  CapsuleParameters grown = parameters;
  for (int pass = 0; pass < 3; ++pass) {
    const Capsule capsule(grown);
    double grow = 0.0;
    for (const Vec3& p : points) grow = std::max(grow, unitGauge(capsule, capsule.toUnit(p)));
    if (!(grow > 0.0) || std::abs(grow - 1.0) < 1e-3) break;
    grown.x *= grow, grown.y *= grow, grown.z *= grow;
  }
  return capsuleCost(Capsule(grown), points, 1.0);
}

CapsuleShaping shapeCapsule(const std::vector<Vec3>& points, const CapsuleShapingOptions& options) {
  if (points.size() < 4) throw std::invalid_argument("a capsule needs at least 4 points to fit");
  const CapsuleParameters start = startingCapsule(points);
  const double size = std::max({start.x, start.y, start.z});
  if (!(size > 1e-6)) throw std::invalid_argument("the points to fit have no extent");
  const GeneticResult best = geneticSearch(capsuleProblem(start, size, points, options), scheduleOf(options));
  CapsuleShaping shaped;
  shaped.parameters = parametersOf(best.genes);
  shaped.cost = best.cost;
  if (options.enclose) shaped.enclosureScale = growToEnclose(shaped.parameters, points);
  return shaped;
}

}  // namespace figment
