#pragma once
// The genetic algorithm that shapes the paper's collision volumes: §3.1 fits capsules by "a form of genetic
// optimization algorithm" (sort by cost, mutate the bottom of the population, cross over
// the band above it, parents biased to low cost), and §3.2 finds the radial depth
// volume's axis by "a combination of analytic and iterative (genetic) techniques". A
// real-valued search over N genes within bounds, minimising a cost; one search serves
// both (sim/volumes/CapsuleShaping.h, sim/volumes/AxisSearch.h), which differ only in their
// problem and schedule.
//
// Based on: D. E. Goldberg, Genetic Algorithms in Search, Optimization and Machine
// Learning, Addison-Wesley 1989 (the paper's [8]); J. Louchet's evolutionary algorithm
// as the paper adapts it ([16, 17]): real-valued genes, a normal mutation step.
//
//   start       member 0 is `start`; the others are copies of it, or, with a `spread`,
//               start_k + (2u - 1) spread_k per gene (u uniform in [0, 1), member by
//               member, gene by gene); then every member's cost, in order;
//   generation  the population is sorted by cost (stable), then
//     mutation    the worst `mutants` become copies of parents picked among the others,
//                 each with one gene k (u G, G genes) moved by step_k times a normal draw
//                 of deviation `mutationDeviation`, clamped to [low_k, high_k];
//     crossover   the `crossovers` above them become children whose every gene comes
//                 from a parent picked among the best `parents` (picked gene by gene);
//   picking     among the first m members, index floor(u^2 m): biased to low cost;
//   result      the lowest-cost member (the first of equals). The best member is never
//               replaced, so the result costs no more than the best start.
// A seeded std::mt19937 draws every random number: a search repeats exactly.

#include <cstdint>
#include <functional>
#include <vector>

namespace figment {

struct GeneticProblem {
  std::vector<double> start;                               // member 0's genes
  std::vector<double> low, high;                           // bounds a mutation clamps to, per gene
  std::vector<double> step;                                // per gene: a mutation's scale
  std::vector<double> spread;                              // per gene, or empty: every member starts at `start`
  std::function<double(const std::vector<double>&)> cost;  // lower is better
};

struct GeneticSchedule {
  int population = 10;
  int generations = 6;
  int mutants = 3;                 // replaced by mutation each generation, < population
  int crossovers = 3;              // replaced by crossover each generation
  int parents = 3;                 // crossover parents among the best, >= 1
  double mutationDeviation = 1.0;  // of the normal draw that times step_k moves gene k
  uint32_t seed = 1;
};

// A search's size as the paper gives it, in shares of the population; each fit turns
// them into a GeneticSchedule's counts by its own rounding.
struct GeneticShares {
  int population = 10;
  int generations = 6;
  double mutationShare = 0.3;   // of the population, replaced by mutation each generation
  double crossoverShare = 0.3;  // replaced by crossover each generation
  double parentShare = 0.3;     // crossover parents among the best
  uint32_t seed = 1;
};

struct GeneticResult {
  std::vector<double> genes;
  double cost = 0.0;
  int evaluations = 0;  // of the cost
};

// Throws std::invalid_argument when the problem's gene vectors disagree in size or the
// schedule's counts are out of range (mutants + crossovers <= population).
GeneticResult geneticSearch(const GeneticProblem& problem, const GeneticSchedule& schedule);

}  // namespace figment
