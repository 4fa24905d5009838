#include "StabilityStudy.h"

#include <Inventor/errors/SoDebugError.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>

#include "CsvFile.h"
#include "SceneGarment.h"

namespace figment::bench {

namespace {

struct Configuration {
  int integrator;  // ClothEngine::Integrator
  bool strainClamp;
  int limiter;  // ClothEngine::AccelerationLimiter
};

const char* integratorKey(int integrator) {
  return integrator == ClothEngine::EULER ? "euler" : integrator == ClothEngine::SYMPLECTIC ? "symplectic" : "heun";
}
const char* limiterKey(int limiter) {
  return limiter == ClothEngine::CLAMP ? "clamp" : limiter == ClothEngine::TANH ? "tanh" : "none";
}

std::vector<Configuration> configurations(bool quick, const std::vector<std::string>& integrators) {
  std::vector<Configuration> all;
  if (quick) {
    all = {{ClothEngine::HEUN, false, ClothEngine::NONE},
           {ClothEngine::HEUN, true, ClothEngine::CLAMP},
           {ClothEngine::SYMPLECTIC, false, ClothEngine::NONE},
           {ClothEngine::EULER, false, ClothEngine::NONE}};
  } else {
    for (int integrator : {ClothEngine::EULER, ClothEngine::SYMPLECTIC, ClothEngine::HEUN})
      for (bool clamp : {false, true})
        for (int limiter : {ClothEngine::NONE, ClothEngine::CLAMP, ClothEngine::TANH})
          all.push_back({integrator, clamp, limiter});
  }
  if (integrators.empty()) return all;
  std::erase_if(all, [&](const Configuration& c) {
    return std::find(integrators.begin(), integrators.end(), integratorKey(c.integrator)) == integrators.end();
  });
  return all;
}

std::vector<double> timeSteps(bool quick) {
  if (quick) return {5e-5, 1.5e-4, 5e-4, 2e-3, 2e-2};
  return {1e-5, 2e-5, 5e-5, 1e-4, 1.5e-4, 2e-4, 3e-4, 5e-4, 1e-3, 2e-3, 5e-3, 1e-2, 2e-2};
}

void silence(const SoError*, void*) {}  // failures are recorded, not printed

struct Deviation {
  double mean = 0.0, max = 0.0;
};
Deviation deviation(const std::vector<SbVec3f>& a, const std::vector<SbVec3f>& b) {
  Deviation d;
  for (size_t i = 0; i < a.size(); ++i) {
    const double distance = (a[i] - b[i]).length();
    d.mean += distance;
    d.max = std::max(d.max, distance);
  }
  d.mean /= static_cast<double>(a.size());
  return d;
}

void configure(ClothEngine& engine, const StabilityStudyOptions& options, const Configuration& c, double dt) {
  engine.integrator.setValue(c.integrator);
  engine.strainLimit.setValue(c.strainClamp ? options.strainLimit : 0.0);
  engine.accelerationLimiter.setValue(c.limiter);
  engine.accelerationLimit.setValue(options.accelerationLimit);
  engine.timeStep.setValue(dt);
}

// The garment's rest height, m.
double restHeight(const std::vector<SbVec3f>& rest) {
  float low = std::numeric_limits<float>::max(), high = -low;
  for (const SbVec3f& p : rest) low = std::min(low, p[1]), high = std::max(high, p[1]);
  return high - low;
}

// What the sweep compares every run with.
struct Reference {
  std::vector<SbVec3f> positions;
  double height = 0.0;  // m, of the rest shape
};

// Drapes configuration `c` at `dt` and writes its CSV line; whether it stayed stable,
// and its deviation from the reference.
std::pair<bool, Deviation> runOne(SceneGarment& garment, const StabilityStudyOptions& options, const Configuration& c,
                                  double dt, const Reference& reference, std::ostream& csv) {
  ClothEngine& engine = *garment.engine;
  configure(engine, options, c, dt);
  const std::vector<SbVec3f> draped = garment.drape();
  const figment::DrapeReport& report = engine.lastRun();
  const bool failed = !engine.lastError().empty();
  const double strain = failed ? std::numeric_limits<double>::infinity() : garment.maxEdgeStrain(draped);
  const bool stable = !failed && strain < 0.2;
  const Deviation d = failed ? Deviation{NAN, NAN} : deviation(draped, reference.positions);
  char line[512];
  std::snprintf(line, sizeof line, "%s,%d,%s,%g,%d,%d,%.4f,%.6g,%.6g,%.4f,%.4g,%d,%.4f,%g,%g,%.4g,%.4g\n",
                integratorKey(c.integrator), c.strainClamp ? 1 : 0, limiterKey(c.limiter), dt, stable ? 1 : 0,
                report.run.atRest ? 1 : 0, report.wallSeconds, d.mean, d.max, reference.height, strain,
                report.run.iterations, report.run.simulatedTime, c.strainClamp ? options.strainLimit : 0.0,
                c.limiter == ClothEngine::NONE ? 0.0 : options.accelerationLimit, report.run.clampedSectionShare,
                report.run.limitedNodeShare);
  csv << line;
  csv.flush();
  return {stable, d};
}

// Every configuration over every step: the CSV, and a summary line per configuration.
void sweep(SceneGarment& garment, const StabilityStudyOptions& options, const std::vector<double>& steps,
           const Reference& reference, std::ostream& csv) {
  csv << "integrator,strain_clamp,limiter,dt,stable,at_rest,wall_s,mean_dev_m,max_dev_m,garment_height_m,"
         "max_edge_strain,iterations,simulated_s,strain_limit,acceleration_limit_g,clamped_section_share,"
         "limited_node_share\n";
  for (const Configuration& c : configurations(options.quick, options.integrators)) {
    double largestStable = 0.0;
    Deviation atLargest;
    for (double dt : steps) {
      const auto [stable, d] = runOne(garment, options, c, dt, reference, csv);
      if (stable && dt > largestStable) largestStable = dt, atLargest = d;
    }
    std::printf("%-10s clamp %d limiter %-5s  largest stable dt %-7g mean dev %.3g mm (%.3f %% of height)\n",
                integratorKey(c.integrator), c.strainClamp ? 1 : 0, limiterKey(c.limiter), largestStable,
                1000 * atLargest.mean, 100 * atLargest.mean / reference.height);
  }
}

void plot(const StabilityStudyOptions& options, const std::string& csvPath) {
  std::cout.flush();
  chartCsv(options.plotScript, csvPath, options.outDir + "/stability.png");
}

}  // namespace

int runStabilityStudy(const StabilityStudyOptions& options) {
  SceneGarment garment;
  if (!garment.loadOrReport(options.scene)) return 1;
  SoDebugError::setHandlerCallback(silence, nullptr);
  ClothEngine& engine = *garment.engine;
  if (options.quick) engine.maxTime.setValue(0.3);
  std::vector<double> steps = options.timeSteps.empty() ? timeSteps(options.quick) : options.timeSteps;
  std::sort(steps.begin(), steps.end());
  // The converged reference: the paper's method, no stability measures, the smallest step.
  configure(engine, options, {ClothEngine::HEUN, false, ClothEngine::NONE}, steps.front());
  const Reference reference{garment.drape(), restHeight(garment.rest)};
  if (!engine.lastError().empty()) {
    std::cerr << "figment-bench: the reference run failed: " << engine.lastError() << "\n";
    return 1;
  }
  std::cout << "reference: Heun at dt " << steps.front() << " s, " << engine.lastRun().run.simulatedTime
            << " s simulated, " << engine.lastRun().wallSeconds << " s wall\n";

  std::filesystem::create_directories(options.outDir);
  const std::string csvPath = options.outDir + "/stability.csv";
  const bool written = writeCsv(csvPath, [&](std::ostream& csv) -> std::string {
    sweep(garment, options, steps, reference, csv);
    return "";
  });
  if (!written) return 1;
  garment.release();
  plot(options, csvPath);
  return 0;
}

}  // namespace figment::bench
