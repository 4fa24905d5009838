#include "sim/volumes/AxisSearch.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace figment {

namespace {

// Genes: tilt u, tilt v (rad), shift du, dv (m).
Axis axisOf(const Axis& start, const Vec3& e1, const Vec3& e2, const std::vector<double>& g) {
  const Vec3 direction = (start.direction + std::tan(g[0]) * e1 + std::tan(g[1]) * e2).normalized();
  return {start.origin + g[2] * e1 + g[3] * e2, direction};
}

// The options' shares as counts of members (rounded to nearest; at least one mutant and
// one parent; the best member always kept).
GeneticSchedule scheduleOf(const AxisSearchOptions& options) {
  GeneticSchedule schedule;
  const int n = options.population;
  schedule.population = n;
  schedule.generations = options.generations;
  schedule.mutants = std::max(1, static_cast<int>(std::lround(options.mutationShare * n)));
  schedule.crossovers = std::min(n - 1 - schedule.mutants, static_cast<int>(std::lround(options.crossoverShare * n)));
  schedule.parents = std::max(1, static_cast<int>(std::lround(options.parentShare * n)));
  schedule.mutationDeviation = 0.3;  // of the limit
  schedule.seed = options.seed;
  return schedule;
}

}  // namespace

AxisSearchResult searchAxis(const Axis& start, const std::function<double(const Axis&)>& cost,
                            const AxisSearchOptions& options) {
  if (!(start.direction.norm() > 0.0)) throw std::invalid_argument("axis direction must not be zero");
  if (options.population < 2) throw std::invalid_argument("population must be >= 2");
  if (options.generations < 0) throw std::invalid_argument("generations must be >= 0");
  const Axis base{start.origin, start.direction.normalized()};
  // Two directions perpendicular to the axis.
  const Vec3 helper = std::abs(base.direction.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = base.direction.cross(helper).normalized();
  const Vec3 e2 = base.direction.cross(e1);
  const std::vector<double> limit = {options.maxTilt, options.maxTilt, options.maxShift, options.maxShift};
  GeneticProblem problem;
  problem.start.assign(4, 0.0);
  for (double l : limit) problem.low.push_back(-l);
  problem.high = problem.step = problem.spread = limit;
  problem.cost = [&](const std::vector<double>& genes) { return cost(axisOf(base, e1, e2, genes)); };
  const GeneticResult found = geneticSearch(problem, scheduleOf(options));
  return {axisOf(base, e1, e2, found.genes), found.cost, found.evaluations};
}

}  // namespace figment
