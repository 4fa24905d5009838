#include "sim/fitting/AxisSearch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace figment {

namespace {

using Genes = std::array<double, 4>;  // tilt u, tilt v (rad), shift du, dv (m)

struct Member {
  Genes genes{};
  double cost = 0.0;
};

Axis axisOf(const Axis& start, const Vec3& e1, const Vec3& e2, const Genes& g) {
  const Vec3 direction = (start.direction + std::tan(g[0]) * e1 + std::tan(g[1]) * e2).normalized();
  return {start.origin + g[2] * e1 + g[3] * e2, direction};
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
  const Genes limit = {options.maxTilt, options.maxTilt, options.maxShift, options.maxShift};

  std::mt19937 random(options.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> step(0.0, 0.3);
  AxisSearchResult result;
  auto evaluate = [&](Member& m) {
    m.cost = cost(axisOf(base, e1, e2, m.genes));
    ++result.evaluations;
  };

  std::vector<Member> population(options.population);
  for (size_t i = 1; i < population.size(); ++i)
    for (int k = 0; k < 4; ++k) population[i].genes[k] = (2.0 * unit(random) - 1.0) * limit[k];
  for (Member& m : population) evaluate(m);

  const int n = options.population;
  const int mutants = std::max(1, static_cast<int>(std::lround(options.mutationShare * n)));
  const int crossovers = std::min(n - 1 - mutants, static_cast<int>(std::lround(options.crossoverShare * n)));
  const int parents = std::max(1, static_cast<int>(std::lround(options.parentShare * n)));
  auto byCost = [](const Member& a, const Member& b) { return a.cost < b.cost; };
  // A parent among the first `among`, biased to the better ones.
  auto pick = [&](int among) {
    const double u = unit(random);
    return std::min(among - 1, static_cast<int>(u * u * among));
  };
  for (int generation = 0; generation < options.generations; ++generation) {
    std::stable_sort(population.begin(), population.end(), byCost);
    for (int i = n - mutants; i < n; ++i) {
      Member child = population[pick(n - mutants)];
      const int gene = static_cast<int>(unit(random) * 4) % 4;
      child.genes[gene] = std::clamp(child.genes[gene] + step(random) * limit[gene], -limit[gene], limit[gene]);
      population[i] = child;
      evaluate(population[i]);
    }
    for (int i = n - mutants - crossovers; i < n - mutants; ++i) {
      Member child;
      for (int k = 0; k < 4; ++k) child.genes[k] = population[pick(parents)].genes[k];
      population[i] = child;
      evaluate(population[i]);
    }
  }
  const Member& best = *std::min_element(population.begin(), population.end(), byCost);
  result.axis = axisOf(base, e1, e2, best.genes);
  result.cost = best.cost;
  return result;
}

}  // namespace figment
