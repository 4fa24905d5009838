// The genetic search both fits share: it finds a bowl's minimum, keeps its best member
// (never worse than the start), stays within its bounds, repeats with its seed, counts
// its evaluations and refuses a schedule it cannot run.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "sim/volumes/GeneticSearch.h"

using namespace figment;

namespace {

// A bowl in three genes with its minimum (zero) at (0.3, -0.2, 0.1).
GeneticProblem bowl() {
  GeneticProblem problem;
  problem.start = {0.0, 0.0, 0.0};
  problem.low = {-1.0, -1.0, -1.0};
  problem.high = {1.0, 1.0, 1.0};
  problem.step = {0.1, 0.1, 0.1};
  problem.spread = {1.0, 1.0, 1.0};
  problem.cost = [](const std::vector<double>& g) {
    const double a = g[0] - 0.3, b = g[1] + 0.2, c = g[2] - 0.1;
    return a * a + b * b + c * c;
  };
  return problem;
}

GeneticSchedule schedule(int generations, uint32_t seed = 1) {
  GeneticSchedule s;
  s.population = 20;
  s.generations = generations;
  s.mutants = 6, s.crossovers = 6, s.parents = 6;
  s.seed = seed;
  return s;
}

}  // namespace

TEST(GeneticSearch, FindsABowlsMinimumWithinItsBounds) {
  const GeneticResult found = geneticSearch(bowl(), schedule(200));
  EXPECT_LT(found.cost, 1e-4);
  EXPECT_NEAR(found.genes[0], 0.3, 0.01);
  EXPECT_NEAR(found.genes[1], -0.2, 0.01);
  EXPECT_NEAR(found.genes[2], 0.1, 0.01);
  EXPECT_EQ(found.evaluations, 20 + 200 * (6 + 6));
}

TEST(GeneticSearch, NeverEndsWorseThanItsStartAndRepeatsWithItsSeed) {
  GeneticProblem fromStart = bowl();
  fromStart.spread.clear();  // every member starts at the start
  const double startCost = fromStart.cost(fromStart.start);
  const GeneticResult a = geneticSearch(fromStart, schedule(5));
  EXPECT_LE(a.cost, startCost);
  const GeneticResult again = geneticSearch(fromStart, schedule(5));
  EXPECT_EQ(again.genes, a.genes);
  EXPECT_EQ(again.cost, a.cost);
  EXPECT_NE(geneticSearch(fromStart, schedule(5, 2)).genes, a.genes);
}

TEST(GeneticSearch, RefusesWhatItCannotRun) {
  GeneticProblem mismatched = bowl();
  mismatched.step.pop_back();
  EXPECT_THROW(geneticSearch(mismatched, schedule(1)), std::invalid_argument);
  GeneticSchedule allMutants = schedule(1);
  allMutants.mutants = allMutants.population;
  EXPECT_THROW(geneticSearch(bowl(), allMutants), std::invalid_argument);
  GeneticSchedule tooMany = schedule(1);
  tooMany.crossovers = tooMany.population;
  EXPECT_THROW(geneticSearch(bowl(), tooMany), std::invalid_argument);
}
