// The filtered conjugate-gradient solve: free directions satisfy the equations, the
// constrained ones take their prescribed values, and the answer does not depend on the
// thread count (the loop runs in one parallel region above kParallelSolveNodes nodes).
#include <gtest/gtest.h>
#include <omp.h>

#include <random>

#include "sim/cloth/ParallelLoops.h"
#include "sim/cloth/implicit/FilteredPcg.h"

using namespace figment;

namespace {
constexpr int kSide = 24;  // a 24 x 24 chain of nodes: 576 > kParallelSolveNodes

// Mass plus a stiff spring Laplacian between grid neighbours, with random 3x3 couplings
// (symmetric, positive definite): about what a step's matrix looks like.
BlockSparseMatrix springGrid(std::mt19937_64& random) {
  const int n = kSide * kSide;
  std::vector<std::vector<int>> columns(n);
  auto link = [&](int i, int j) { columns[i].push_back(j), columns[j].push_back(i); };
  for (int r = 0; r < kSide; ++r)
    for (int c = 0; c < kSide; ++c) {
      if (c + 1 < kSide) link(r * kSide + c, r * kSide + c + 1);
      if (r + 1 < kSide) link(r * kSide + c, (r + 1) * kSide + c);
    }
  BlockSparseMatrix A(columns);
  std::normal_distribution<double> normal;
  for (int i = 0; i < n; ++i) A.block(A.find(i, i)) = 1e-3 * Block3::Identity();
  for (int i = 0; i < n; ++i)
    for (int j : columns[i]) {
      if (j < i) continue;
      const Vec3 d(normal(random), normal(random), normal(random));
      const Block3 spring = 50.0 * (Block3::Identity() + d * d.transpose());
      A.block(A.find(i, j)) -= spring, A.block(A.find(j, i)) -= spring;
      A.block(A.find(i, i)) += spring, A.block(A.find(j, j)) += spring;
    }
  return A;
}

struct Problem {
  BlockSparseMatrix A;
  std::vector<Vec3> b;
  NodeFilter filter;
};

Problem problem() {
  std::mt19937_64 random(17);
  Problem p{springGrid(random), {}, {}};
  const int n = p.A.rows();
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  p.b.resize(n);
  for (Vec3& value : p.b) value = Vec3(uniform(random), uniform(random), uniform(random));
  p.filter.reset(n);
  for (int i = 0; i < n; i += 7) {  // every 7th node slides on a plane, every 31st is fixed
    p.filter.kind[i] = NodeFilter::Sliding;
    p.filter.normal[i] = Vec3(uniform(random), 1.0, uniform(random)).normalized();
    p.filter.prescribed[i] = 0.3 * p.filter.normal[i];
  }
  for (int i = 0; i < n; i += 31) {
    p.filter.kind[i] = NodeFilter::Fixed;
    p.filter.prescribed[i] = Vec3(0.1, -0.2, 0.05);
  }
  return p;
}

std::vector<Vec3> solveWithThreads(const Problem& p, int threads, PcgReport& report, bool twoLevel = true) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  FilteredPcg pcg = twoLevel ? FilteredPcg(p.A) : FilteredPcg();
  std::vector<Vec3> y;
  report = pcg.solve(p.A, p.b, p.filter, PcgStop{1e-10, 5000}, y);
  omp_set_num_threads(before);
  return y;
}
}  // namespace

TEST(FilteredPcg, SolvesTheFreeDirectionsAndKeepsThePrescribedOnes) {
  const Problem p = problem();
  ASSERT_GT(p.A.rows(), kParallelSolveNodes);
  PcgReport report;
  const std::vector<Vec3> y = solveWithThreads(p, 2, report);
  EXPECT_TRUE(report.converged) << report.iterations << " iterations";
  std::vector<Vec3> Ay;
  p.A.multiply(y, Ay);
  double worst = 0.0, scale = 0.0;
  for (int i = 0; i < p.A.rows(); ++i) {
    worst = std::max(worst, p.filter.apply(i, Ay[i] - p.b[i]).norm());
    scale = std::max(scale, p.b[i].norm());
    const Vec3 constrained = y[i] - p.filter.apply(i, y[i]);
    EXPECT_LT((constrained - p.filter.prescribed[i]).norm(), 1e-12) << "node " << i;
  }
  EXPECT_LT(worst, 1e-6 * scale);
}

TEST(FilteredPcg, OneThreadGivesTheAnswerOfTwoBitForBit) {
  const Problem p = problem();
  PcgReport one, two;
  const std::vector<Vec3> a = solveWithThreads(p, 1, one), b = solveWithThreads(p, 2, two);
  EXPECT_EQ(one.iterations, two.iterations);
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << "node " << i;
}

TEST(FilteredPcg, TheCoarseCorrectionGivesTheSameAnswerInFewerIterations) {
  const Problem p = problem();
  PcgReport jacobi, twoLevel;
  const std::vector<Vec3> a = solveWithThreads(p, 1, jacobi, false), b = solveWithThreads(p, 1, twoLevel, true);
  EXPECT_TRUE(jacobi.converged);
  EXPECT_TRUE(twoLevel.converged);
  double scale = 0.0, worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    scale = std::max(scale, a[i].norm()), worst = std::max(worst, (a[i] - b[i]).norm());
  EXPECT_LT(worst, 1e-6 * scale);
  EXPECT_LT(twoLevel.iterations, 0.6 * jacobi.iterations) << jacobi.iterations << " block Jacobi";
}

namespace {
// The problem's right-hand side moved a little: b' = 1.05 b plus 1e-4 of noise (the
// scale alone the guess's factor takes up exactly).
std::vector<Vec3> nearby(const std::vector<Vec3>& b) {
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Vec3> moved(b.size());
  for (size_t i = 0; i < b.size(); ++i)
    moved[i] = 1.05 * b[i] + 1e-4 * Vec3(uniform(random), uniform(random), uniform(random));
  return moved;
}

// The largest difference between two answers, as a share of a's largest node.
double relativeDifference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double worst = 0.0, scale = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    scale = std::max(scale, a[i].norm()), worst = std::max(worst, (a[i] - b[i]).norm());
  return worst / scale;
}
}  // namespace

// A step's solve warm-started from the last step's answer (PcgStart::Guess): the same
// answer to the stop's accuracy, in fewer iterations than from zero. Its constrained
// part is the prescribed one, whatever the guess held there.
TEST(FilteredPcg, AGuessFromANearbySystemReachesTheSameAnswerInFewerIterations) {
  Problem p = problem();
  const PcgStop stop{1e-6, 5000};
  FilteredPcg pcg(p.A);
  std::vector<Vec3> last;
  ASSERT_TRUE(pcg.solve(p.A, p.b, p.filter, stop, last).converged);
  p.b = nearby(p.b);
  std::vector<Vec3> cold, warm = last;
  // Off in the constrained directions only: along a sliding node's normal, anywhere for
  // a fixed one.
  for (size_t i = 0; i < warm.size(); i += 7) warm[i] += 3.0 * p.filter.normal[i];
  for (size_t i = 0; i < warm.size(); i += 31) warm[i] += Vec3(3.0, -2.0, 1.0);
  const PcgReport fromZero = pcg.solve(p.A, p.b, p.filter, stop, cold);
  const PcgReport fromGuess = pcg.solve(p.A, p.b, p.filter, stop, warm, PcgStart::Guess);
  ASSERT_TRUE(fromZero.converged);
  ASSERT_TRUE(fromGuess.converged);
  // Scaled by 1.05 the guess is off by the noise alone: its residual starts near 1e-4 of
  // the right-hand side's, two thirds of the way (in orders) to the stop's 1e-6.
  EXPECT_LT(fromGuess.iterations, 0.8 * fromZero.iterations) << fromZero.iterations << " from zero";
  // Two answers each within 1e-6 relative residual: apart by far less than 1e-3.
  EXPECT_LT(relativeDifference(cold, warm), 1e-3);
  for (int i = 0; i < p.A.rows(); ++i) {
    const Vec3 constrained = warm[i] - p.filter.apply(i, warm[i]);
    EXPECT_LT((constrained - p.filter.prescribed[i]).norm(), 1e-12) << "node " << i;
  }
}

// A guess that points nowhere near the answer is scaled along itself to the least error
// energy, so it never starts farther off than zero does: about as many iterations.
TEST(FilteredPcg, APoorGuessCostsAboutWhatAStartFromZeroCosts) {
  const Problem p = problem();
  const PcgStop stop{1e-6, 5000};
  FilteredPcg pcg(p.A);
  std::mt19937_64 random(23);
  std::uniform_real_distribution<double> uniform(-100.0, 100.0);
  std::vector<Vec3> cold, poor(p.A.rows());
  for (Vec3& value : poor) value = Vec3(uniform(random), uniform(random), uniform(random));
  const PcgReport fromZero = pcg.solve(p.A, p.b, p.filter, stop, cold);
  const PcgReport fromPoor = pcg.solve(p.A, p.b, p.filter, stop, poor, PcgStart::Guess);
  ASSERT_TRUE(fromPoor.converged);
  // CG's error energy falls monotonically from its start: no worse a start, no more
  // than a few iterations' difference (rounding).
  EXPECT_LE(fromPoor.iterations, fromZero.iterations + 3) << fromZero.iterations << " from zero";
  EXPECT_LT(relativeDifference(cold, poor), 1e-3);
}

// The coarse matrix kept from another system (CoarseMatrix::Keep) leaves the
// preconditioner positive definite: the solve reaches the answer a fresh one reaches.
TEST(FilteredPcg, AKeptCoarseMatrixOfAnotherSystemReachesTheSameAnswer) {
  const Problem p = problem();
  const PcgStop stop{1e-8, 5000};
  BlockSparseMatrix softer = p.A;  // the next system: a stiffer mass term, as at a smaller step
  for (int i = 0; i < softer.rows(); ++i) softer.block(softer.find(i, i)) += 20.0 * Block3::Identity();
  FilteredPcg kept(p.A), built(p.A);
  std::vector<Vec3> first, a, b;
  kept.solve(p.A, p.b, p.filter, stop, first);
  const PcgReport keptReport = kept.solve(softer, p.b, p.filter, stop, a, PcgStart::Zero, CoarseMatrix::Keep);
  const PcgReport builtReport = built.solve(softer, p.b, p.filter, stop, b);
  ASSERT_TRUE(keptReport.converged);
  ASSERT_TRUE(builtReport.converged);
  EXPECT_LT(relativeDifference(b, a), 1e-5);
  // And it is the last one built, not this system's: not the same iterations bit for bit.
  EXPECT_GT(relativeDifference(b, a), 0.0);
}
