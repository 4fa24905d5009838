#include "sim/volumes/GeneticSearch.h"

#include <algorithm>
#include <random>
#include <stdexcept>

namespace figment {

namespace {

struct Member {
  std::vector<double> genes;
  double cost = 0.0;
};

void validate(const GeneticProblem& problem, const GeneticSchedule& schedule) {
  const size_t genes = problem.start.size();
  if (genes == 0) throw std::invalid_argument("a genetic search needs at least one gene");
  if (problem.low.size() != genes || problem.high.size() != genes || problem.step.size() != genes ||
      (!problem.spread.empty() && problem.spread.size() != genes))
    throw std::invalid_argument("the genes' start, bounds, steps and spread must have one value per gene");
  if (!problem.cost) throw std::invalid_argument("a genetic search needs a cost");
  if (schedule.population < 2) throw std::invalid_argument("population must be >= 2");
  if (schedule.generations < 0) throw std::invalid_argument("generations must be >= 0");
  if (schedule.mutants < 0 || schedule.mutants >= schedule.population)
    throw std::invalid_argument("mutants must be in [0, population)");
  if (schedule.crossovers < 0 || schedule.mutants + schedule.crossovers > schedule.population)
    throw std::invalid_argument("crossovers must be in [0, population - mutants]");
  if (schedule.parents < 1 || schedule.parents > schedule.population)
    throw std::invalid_argument("parents must be in [1, population]");
}

// The search's state: the problem, the schedule, the population and the random draws.
class Search {
 public:
  Search(const GeneticProblem& problem, const GeneticSchedule& schedule)
      : problem_(problem), schedule_(schedule), random_(schedule.seed), normal_(0.0, schedule.mutationDeviation) {}

  void start() {
    population_.assign(schedule_.population, Member{problem_.start, 0.0});
    if (!problem_.spread.empty())
      for (size_t i = 1; i < population_.size(); ++i)
        for (size_t k = 0; k < genes(); ++k)
          population_[i].genes[k] = problem_.start[k] + (2.0 * unit_(random_) - 1.0) * problem_.spread[k];
    for (Member& m : population_) evaluate(m);
  }

  void generation() {
    std::stable_sort(population_.begin(), population_.end(), byCost);
    const int n = schedule_.population, mutants = schedule_.mutants;
    for (int i = n - mutants; i < n; ++i) population_[i] = mutant(pick(n - mutants));
    for (int i = n - mutants - schedule_.crossovers; i < n - mutants; ++i) population_[i] = crossover();
  }

  GeneticResult result() const {
    const Member& best = *std::min_element(population_.begin(), population_.end(), byCost);
    return {best.genes, best.cost, evaluations_};
  }

 private:
  static bool byCost(const Member& a, const Member& b) { return a.cost < b.cost; }
  size_t genes() const { return problem_.start.size(); }

  void evaluate(Member& m) {
    m.cost = problem_.cost(m.genes);
    ++evaluations_;
  }

  // A member among the first `among`, biased to the better ones.
  int pick(int among) {
    const double u = unit_(random_);
    return std::min(among - 1, static_cast<int>(u * u * among));
  }

  // A copy of member `parent` with one gene moved.
  Member mutant(int parent) {
    Member child = population_[parent];
    const int g = static_cast<int>(genes());
    const int k = static_cast<int>(unit_(random_) * g) % g;
    child.genes[k] =
        std::clamp(child.genes[k] + normal_(random_) * problem_.step[k], problem_.low[k], problem_.high[k]);
    evaluate(child);
    return child;
  }

  Member crossover() {
    Member child{std::vector<double>(genes()), 0.0};
    for (size_t k = 0; k < genes(); ++k) child.genes[k] = population_[pick(schedule_.parents)].genes[k];
    evaluate(child);
    return child;
  }

  const GeneticProblem& problem_;
  const GeneticSchedule& schedule_;
  std::mt19937 random_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
  std::normal_distribution<double> normal_;
  std::vector<Member> population_;
  int evaluations_ = 0;
};

}  // namespace

GeneticResult geneticSearch(const GeneticProblem& problem, const GeneticSchedule& schedule) {
  validate(problem, schedule);
  Search search(problem, schedule);
  search.start();
  for (int generation = 0; generation < schedule.generations; ++generation) search.generation();
  return search.result();
}

}  // namespace figment
