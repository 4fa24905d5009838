#include "ProgressiveStudy.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "CsvFile.h"
#include "MethodSpec.h"
#include "SceneGarment.h"
#include "Statistics.h"
#include "TemporaryScript.h"
#include "sim/progressive/ProgressiveDrape.h"

namespace figment::bench {

namespace {

// The script's number of levels: a drape of one coarse step that ends at the coarsest level.
int countLevels(SceneGarment& garment, const std::string& script, std::string& error) {
  ClothEngine& engine = *garment.engine;
  const double maxTime = engine.maxTime.getValue();
  engine.progressiveScript = script.c_str();
  engine.endLevel = 0;
  engine.maxTime = kMaxStepGrowth * engine.timeStepSeconds();  // a coarse level's step may be longer
  const RepeatedDrape probe = garment.drapeRepeatedly(1);
  engine.maxTime = maxTime;
  error = probe.error;
  return probe.report.levels;
}

// Drapes with the engine's fields at each of the time steps; medians over them.
struct Drapes {
  std::vector<std::vector<SbVec3f>> positions;  // one per time step
  std::vector<double> wall, steps, simulated;
  std::vector<double> endLevelAt, meanMoveAfter, maxMoveAfter;  // s, m (progressive drapes)
  int rested = 0, levels = 0;
  std::string error;
};

Drapes drapeAtEachStep(SceneGarment& garment, double timeStep, const std::vector<double>& factors) {
  Drapes out;
  for (double factor : factors) {
    garment.engine->timeStep = factor * timeStep;
    const RepeatedDrape run = garment.drapeRepeatedly(1);
    if (!(out.error = run.error).empty()) break;
    out.positions.push_back(run.positions);
    out.wall.push_back(run.medianWall), out.steps.push_back(run.report.run.iterations);
    out.simulated.push_back(run.report.run.simulatedTime);
    out.rested += run.report.run.atRest;
    out.levels = run.report.levels;
    out.endLevelAt.push_back(run.report.settling.arrival);
    out.meanMoveAfter.push_back(run.report.settling.meanMove);
    out.maxMoveAfter.push_back(run.report.settling.maxMove);
  }
  garment.engine->timeStep = timeStep;
  return out;
}

// Median deviation of each drape of `a` from the drape of `b` at the same time step.
std::pair<double, double> medianDeviation(const SceneGarment& garment, const Drapes& a, const Drapes& b) {
  std::vector<double> mean, largest;
  for (size_t i = 0; i < a.positions.size(); ++i) {
    const auto [m, l] = garment.deviationPercent(a.positions[i], b.positions[i]);
    mean.push_back(m), largest.push_back(l);
  }
  return {median(mean), median(largest)};
}

// How far the whole garment's drapes at the time steps lie from each other (median).
double floorOf(const SceneGarment& garment, const Drapes& full) {
  std::vector<double> d;
  for (size_t i = 0; i < full.positions.size(); ++i)
    for (size_t j = i + 1; j < full.positions.size(); ++j)
      d.push_back(garment.deviationPercent(full.positions[i], full.positions[j]).first);
  return d.empty() ? 0.0 : median(d);
}

// One method: the full garment, then each schedule; "" or the error.
std::string studyMethod(SceneGarment& garment, const std::string& script, int levels, const Method& method,
                        const ProgressiveStudyOptions& options, std::ostream& csv) {
  configure(*garment.engine, method);
  garment.engine->progressiveScript = "";
  const Drapes full = drapeAtEachStep(garment, method.drape.timeStep, options.stepFactors);
  if (!full.error.empty()) return method.text + ", full garment: " + full.error;
  const double fullWall = median(full.wall), floor = floorOf(garment, full);
  const size_t runs = options.stepFactors.size();
  std::printf("%-22s full garment: %6.0f steps %7.3f s wall, %d/%zu rested; floor %.3f %%\n", method.text.c_str(),
              median(full.steps), fullWall, full.rested, runs, floor);
  for (const std::string& text : options.schedules) {
    const Schedule s = parseSchedule(text);
    garment.engine->progressiveScript = script.c_str();
    garment.engine->splitRate = s.rate;
    garment.engine->endLevel = -1;
    garment.engine->beginLevel = static_cast<int>(std::lround(s.beginShare * levels));
    const Drapes run = drapeAtEachStep(garment, method.drape.timeStep, options.stepFactors);
    csv << options.scene << ',' << method.text << ',' << runs << ',' << garment.engine->beginLevel.getValue() << ','
        << levels << ',' << s.rate << ',';
    if (!run.error.empty()) {  // a failed configuration is a result too (a blow-up, say)
      std::printf("%-22s %-10s failed: %s\n", method.text.c_str(), text.c_str(), run.error.c_str());
      csv << ",,," << median(full.steps) << ',' << fullWall << ',' << full.rested << ",,,," << floor
          << ",,,,,,\"failed: " << run.error << "\"\n";
      continue;
    }
    const auto [mean, largest] = medianDeviation(garment, run, full);
    const double wall = median(run.wall);
    const double arrival = median(run.endLevelAt);
    std::printf(
        "%-22s %-10s begin %4d of %4d: %6.0f steps %7.3f s wall, %d/%zu rested %5.2fx  dev mean %6.3f %% "
        "max %6.3f %%; full detail at %.2f s, moved %.1f mm mean %.1f mm max after it\n",
        method.text.c_str(), text.c_str(), garment.engine->beginLevel.getValue(), levels, median(run.steps), wall,
        run.rested, runs, fullWall / wall, mean, largest, arrival, 1e3 * median(run.meanMoveAfter),
        1e3 * median(run.maxMoveAfter));
    std::fflush(stdout);
    csv << median(run.steps) << ',' << wall << ',' << run.rested << ',' << median(full.steps) << ',' << fullWall << ','
        << full.rested << ',' << fullWall / wall << ',' << mean << ',' << largest << ',' << floor << ',' << arrival
        << ',' << median(full.simulated) << ',' << median(run.simulated) << ',' << 1e3 * median(run.meanMoveAfter)
        << ',' << 1e3 * median(run.maxMoveAfter) << ",\n";
  }
  return "";
}

}  // namespace

int runProgressiveStudy(const ProgressiveStudyOptions& options) {
  std::vector<Method> methods;
  if (!parsesOrReports([&] {
        for (const std::string& text : options.methods) methods.push_back(parseMethod(text));
        for (const std::string& text : options.schedules) parseSchedule(text);
      }))
    return 2;
  SceneGarment garment;
  if (!garment.loadOrReport(options.scene)) return 1;
  std::string error;
  // The scene's script, or one made now (to coarseShare of the sections).
  std::string script = garment.engine->progressiveScript.getValue().getString();
  std::optional<TemporaryScript> made;
  if (script.empty()) {
    try {
      made.emplace(garment.engine->restGarment(), options.coarseShare);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "figment-bench: %s: %s\n", options.scene.c_str(), e.what());
      return 1;
    }
    script = made->path();
  }
  const int levels = countLevels(garment, script, error);
  if (!error.empty()) {
    std::fprintf(stderr, "figment-bench: %s\n", error.c_str());
    return 1;
  }
  std::filesystem::create_directories(options.outDir);
  const bool written = writeCsv(options.outDir + "/progressive.csv", [&](std::ostream& csv) -> std::string {
    // Steps, walls and deviations are medians over the time steps (the method's times each
    // factor); *rested count the drapes at rest within maxTime; floor: the full garment's
    // drapes' median deviation from each other.
    csv << "scene,method,time_steps,begin_level,levels,split_rate_per_s,steps,median_wall_s,rested,full_steps,"
           "full_median_wall_s,full_rested,speed_up,mean_dev_pct_height,max_dev_pct_height,floor_mean_dev_pct_height,"
           "full_detail_at_s,full_rest_s,rest_s,moved_after_full_detail_mean_mm,moved_after_full_detail_max_mm,"
           "failure\n";
    for (const Method& method : methods)
      if (std::string e = studyMethod(garment, script, levels, method, options, csv); !e.empty()) return e;
    return "";
  });
  // The scene's own script again: a made one goes with `made`, and an engine left naming
  // it would complain of a missing file when the scene is let go.
  garment.engine->progressiveScript = made ? "" : script.c_str();
  if (!written) return 1;
  chartCsv(options.plotScript, options.outDir + "/progressive.csv", options.outDir + "/progressive.png");
  return 0;
}

}  // namespace figment::bench
