// The paper's wind (§2): a sinusoidal pressure whose phase changes at random moments
// that depend only on the seed, pushing each section by its exposure to the wind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <stdexcept>

#include "sim/cloth/ClothSolver.h"
#include "sim/cloth/Wind.h"
#include "support/TestMeshes.h"

namespace test_Wind {

using namespace figment;

namespace {

WindParameters steadyWind(double amplitude, double frequency) {
  WindParameters w;
  w.direction = Vec3::UnitZ();
  w.amplitude = amplitude;
  w.frequency = frequency;
  w.meanPhaseInterval = 0.0;
  return w;
}

WindParameters gustyWind(uint64_t seed) {
  WindParameters w = steadyWind(0.2, 1.5);
  w.meanPhaseInterval = 0.3;
  w.seed = seed;
  return w;
}

// A soft 0.3 m x 0.3 m sheet hanging in the x-y plane from its pinned top row (nodes
// 0..8), its normal along z.
constexpr int kGrid = 8;
constexpr int kBottomMiddle = kGrid / 2 + kGrid * (kGrid + 1);

TriangleMesh hangingSheet() {
  return meshes::grid(kGrid, kGrid, 0.3, 0.3);
}

ClothParameters hangingSheetParameters(const WindParameters& wind) {
  ClothParameters p;
  p.material.youngsModulus = 5e4;
  p.timeStep = 6e-4;  // 8e-4 is the largest stable step of this sheet, 1e-3 blows up
  p.wind = wind;
  return p;
}

// Runs the hanging sheet for `seconds`, calling sample(time, positions) after each step.
template <class Sample>
std::vector<Vec3> runHangingSheet(const WindParameters& wind, double seconds, Sample&& sample) {
  const ClothParameters p = hangingSheetParameters(wind);
  ClothSolver solver(hangingSheet(), p, nullptr);
  for (int i = 0; i <= kGrid; ++i) solver.pin(i);
  const int steps = static_cast<int>(std::lround(seconds / p.timeStep));
  for (int k = 0; k < steps; ++k) {
    solver.step();
    sample(solver.time(), solver.positions());
  }
  return solver.positions();
}

std::vector<Vec3> runHangingSheet(const WindParameters& wind, double seconds) {
  return runHangingSheet(wind, seconds, [](double, const std::vector<Vec3>&) {});
}

// The frequency (Hz) in [low, high] where the Hann-windowed spectrum of equally spaced
// samples (interval dt, mean removed) peaks, scanned in steps of 0.002 Hz.
double dominantFrequency(const std::vector<double>& samples, double dt, double low, double high) {
  const size_t n = samples.size();
  double mean = 0.0;
  for (double s : samples) mean += s / n;
  double best = low, bestPower = -1.0;
  for (double f = low; f <= high; f += 0.002) {
    double re = 0.0, im = 0.0;
    for (size_t k = 0; k < n; ++k) {
      const double hann = 0.5 - 0.5 * std::cos(2 * M_PI * k / (n - 1));
      const double value = hann * (samples[k] - mean);
      re += value * std::cos(2 * M_PI * f * k * dt);
      im += value * std::sin(2 * M_PI * f * k * dt);
    }
    if (re * re + im * im > bestPower) {
      bestPower = re * re + im * im;
      best = f;
    }
  }
  return best;
}

}  // namespace

// --- the pressure -------------------------------------------------------------------

TEST(Wind, WithoutPhaseChangesThePressureIsTheSinusoid) {
  const double amplitude = 0.7, frequency = 2.5;
  const Wind wind(steadyWind(amplitude, frequency));
  for (int k = 0; k <= 1000; ++k) {
    const double t = k * 3.7e-3;
    EXPECT_DOUBLE_EQ(wind.pressure(t), amplitude * std::sin(2 * M_PI * frequency * t)) << "t = " << t;
    EXPECT_EQ(wind.phase(t), 0.0);
  }
}

TEST(Wind, EqualSeedsGiveEqualPhaseChangesOtherSeedsOthers) {
  const Wind a(gustyWind(7)), b(gustyWind(7)), c(gustyWind(8));
  int changes = 0, differences = 0;
  double previous = 0.0;
  for (int k = 0; k < 20000; ++k) {  // 20 s
    const double t = k * 1e-3;
    EXPECT_EQ(a.phase(t), b.phase(t));
    EXPECT_EQ(a.pressure(t), b.pressure(t));
    if (a.phase(t) != c.phase(t)) ++differences;
    if (a.phase(t) != previous) ++changes;
    previous = a.phase(t);
  }
  EXPECT_GT(changes, 20) << "the phase changes (about 67 times in 20 s)";
  EXPECT_GT(differences, 10000) << "another seed changes the phase at other moments";
}

TEST(Wind, PhaseChangesArePoissonWithTheMeanInterval) {
  WindParameters w = gustyWind(3);
  w.meanPhaseInterval = 0.5;
  const Wind wind(w);
  int changes = 0;
  double previous = 0.0, phaseSum = 0.0;
  for (int k = 0; k < 200000; ++k) {  // 200 s: 400 changes expected, standard deviation 20
    const double phase = wind.phase(k * 1e-3);
    ASSERT_GE(phase, 0.0);
    ASSERT_LT(phase, 2 * M_PI);
    if (phase != previous) {
      ++changes;
      phaseSum += phase;
    }
    previous = phase;
  }
  EXPECT_NEAR(changes, 400, 60);
  EXPECT_NEAR(phaseSum / changes, M_PI, 0.3) << "new phases are uniform in [0, 2 pi)";
}

TEST(Wind, PhaseChangesDoNotDependOnTheSamplingStep) {
  // One wind sampled every 1 ms, one every 10 ms, one backwards: at the common times
  // all three agree.
  const Wind fine(gustyWind(11)), coarse(gustyWind(11)), backwards(gustyWind(11));
  std::vector<double> atCommonTimes;
  for (int i = 0; i < 1000; ++i)
    for (int k = 0; k < 10; ++k) {
      const double p = fine.pressure(i * 1e-2 + k * 1e-3);
      if (k == 0) atCommonTimes.push_back(p);
    }
  for (int i = 999; i >= 0; --i) ASSERT_EQ(backwards.pressure(i * 1e-2), atCommonTimes[i]) << "t = " << i * 1e-2;
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(coarse.pressure(i * 1e-2), atCommonTimes[i]) << "t = " << i * 1e-2;
}

TEST(Wind, ValidateNamesTheField) {
  auto message = [](const WindParameters& w) -> std::string {
    try {
      w.validate();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  WindParameters w;
  EXPECT_EQ(message(w), "");
  w.amplitude = -1;
  EXPECT_EQ(message(w), "windAmplitude = -1 must be >= 0");
  w = {};
  w.frequency = -2;
  EXPECT_EQ(message(w), "windFrequency = -2 must be >= 0");
  w = {};
  w.meanPhaseInterval = -0.5;
  EXPECT_EQ(message(w), "windPhaseInterval = -0.5 must be >= 0");
  w = {};
  w.direction.y() = NAN;
  EXPECT_EQ(message(w).rfind("windDirection = ", 0), 0u) << message(w);
  ClothParameters p;
  p.wind.amplitude = -3;
  EXPECT_THROW(p.validate(), std::invalid_argument) << "the cloth's parameters check their wind";
}

// --- the force on the cloth ---------------------------------------------------------

TEST(Wind, FaceOnSectionsCatchThePressureTimesTheirExposure) {
  // A flat sheet at rest, no gravity: every node's lumped area carries p |n . w| of
  // pressure, so its acceleration is p |n . w| / (rho h) along the wind.
  const TriangleMesh sheet = meshes::grid(4, 3, 0.2, 0.15);  // normal along z
  // (Measured against the same sheet without wind: the rest shape's elastic forces are
  // rounding errors, not zero.)
  const std::vector<Vec3> still(sheet.vertices.size(), Vec3::Zero());
  ClothParameters p;
  p.gravity = Vec3::Zero();
  std::vector<Vec3> calm;
  ClothModel(sheet, p).accelerations(sheet.vertices, still, 0.0, calm);
  const double t = 0.25;  // a quarter period of 1 Hz: p = amplitude
  for (const Vec3& direction : {Vec3(0, 0, 1), Vec3(0, 1, -1), Vec3(3, 0, 4)}) {
    p.wind = steadyWind(0.1, 1.0);
    p.wind.direction = direction;
    const Vec3 w = direction.normalized();
    const double exposure = std::abs(w.z());
    std::vector<Vec3> a;
    ClothModel(sheet, p).accelerations(sheet.vertices, still, t, a);
    const double expected = 0.1 * exposure / p.material.arealDensity();
    for (size_t i = 0; i < a.size(); ++i)
      EXPECT_LT((a[i] - calm[i] - expected * w).norm(), 1e-9 * expected) << "node " << i << ": " << a[i].transpose();
  }
}

TEST(Wind, EdgeOnSectionsCatchNone) {
  // A sheet stretched in its own plane (elastic forces too) with the wind in that plane.
  const TriangleMesh sheet = meshes::grid(4, 4, 0.2, 0.2);
  std::vector<Vec3> stretched = sheet.vertices;
  for (Vec3& x : stretched) x.x() *= 1.05;
  const std::vector<Vec3> moving(sheet.vertices.size(), Vec3(0.01, -0.02, 0.0));
  ClothParameters calm;
  std::vector<Vec3> without, with;
  ClothModel(sheet, calm).accelerations(stretched, moving, 0.25, without);
  for (const Vec3& direction : {Vec3(1, 0, 0), Vec3(1, -2, 0)}) {
    ClothParameters windy = calm;
    windy.wind = steadyWind(5.0, 1.0);
    windy.wind.direction = direction;
    ClothModel(sheet, windy).accelerations(stretched, moving, 0.25, with);
    EXPECT_EQ(with, without) << "wind along " << direction.transpose();
  }
}

TEST(Wind, AHangingSheetSwaysAtTheWindFrequency) {
  // Phase changes off; 1.5 s to settle, then 4 s of the bottom middle node's motion
  // along the wind.
  for (double frequency : {1.0, 2.5}) {
    const double settle = 1.5, dt = 10 * hangingSheetParameters({}).timeStep;  // every 10th step
    std::vector<double> along;
    double low = 1e9, high = -1e9;
    int step = 0;
    runHangingSheet(steadyWind(0.05, frequency), settle + 4.0, [&](double t, const std::vector<Vec3>& x) {
      if (t <= settle || step++ % 10 != 0) return;
      along.push_back(x[kBottomMiddle].z());
      low = std::min(low, x[kBottomMiddle].z());
      high = std::max(high, x[kBottomMiddle].z());
    });
    const double measured = dominantFrequency(along, dt, 0.2, 10.0);
    RecordProperty("dominant_frequency_" + std::to_string(frequency), std::to_string(measured));
    std::cout << std::setprecision(4) << "wind " << frequency << " Hz: dominant " << measured << " Hz, sway "
              << (high - low) * 1e3 << " mm peak to peak\n";
    EXPECT_NEAR(measured, frequency, 0.05 * frequency);
    EXPECT_GT(high - low, 1e-3) << "the motion is clear";
    EXPECT_LT(high - low, 0.1) << "and small";
  }
}

TEST(Wind, EqualSeedsRepeatTheMotionBitForBitOtherSeedsChangeIt) {
  const std::vector<Vec3> first = runHangingSheet(gustyWind(5), 1.5);
  const std::vector<Vec3> again = runHangingSheet(gustyWind(5), 1.5);
  const std::vector<Vec3> other = runHangingSheet(gustyWind(6), 1.5);
  EXPECT_EQ(first, again);
  double largest = 0.0;
  for (size_t i = 0; i < first.size(); ++i) largest = std::max(largest, (first[i] - other[i]).norm());
  EXPECT_GT(largest, 1e-3) << "m: another seed moves the sheet otherwise";
}

}  // namespace test_Wind
