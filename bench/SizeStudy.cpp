#include "SizeStudy.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "CsvFile.h"
#include "MethodSpec.h"
#include "SceneGarment.h"
#include "Statistics.h"
#include "TemporaryScript.h"
#include "sim/progressive/Resampling.h"

namespace figment::bench {

namespace {

// The garment resampled to a size, with its progressive mesh.
struct SizedGarment {
  SizedGarment(const TriangleMesh& base, int sections, double coarseShare)
      : mesh(asSceneHoldsIt(resampled(base, sections))), script(mesh, coarseShare) {}
  TriangleMesh mesh;
  TemporaryScript script;
};

struct Drapes {
  std::vector<double> fullWall, wall, fullSteps, steps, meanDev, maxDev, floorDev;
  int fullRested = 0, rested = 0;
  std::string failure;
};

// The garment whole, then progressively, at each of the options' time steps.
Drapes drapeAtEachStep(SceneGarment& garment, const SizedGarment& sized, double timeStep,
                       const SizeStudyOptions& options) {
  ClothEngine& engine = *garment.engine;
  Drapes out;
  std::vector<std::vector<SbVec3f>> whole;
  for (double factor : options.stepFactors) {
    engine.timeStep = factor * timeStep;
    engine.progressiveScript = "";
    const RepeatedDrape full = garment.drapeRepeatedly(1);
    engine.progressiveScript = sized.script.path().c_str();
    engine.beginLevel = 0;
    engine.endLevel = -1;
    engine.splitRate = sized.script.levels() / options.splitTime;
    const RepeatedDrape progressive = garment.drapeRepeatedly(1);
    out.failure = !full.error.empty()          ? "whole: " + full.error
                  : !progressive.error.empty() ? "progressive: " + progressive.error
                                               : "";
    if (!out.failure.empty()) break;
    out.fullWall.push_back(full.medianWall), out.wall.push_back(progressive.medianWall);
    out.fullSteps.push_back(full.report.run.iterations), out.steps.push_back(progressive.report.run.iterations);
    out.fullRested += full.report.run.atRest, out.rested += progressive.report.run.atRest;
    const auto [mean, largest] = garment.deviationPercent(progressive.positions, full.positions);
    out.meanDev.push_back(mean), out.maxDev.push_back(largest);
    whole.push_back(full.positions);
  }
  engine.timeStep = timeStep;
  engine.progressiveScript = "";  // the script goes with `sized`
  for (size_t i = 0; out.failure.empty() && i < whole.size(); ++i)
    for (size_t j = i + 1; j < whole.size(); ++j)
      out.floorDev.push_back(garment.deviationPercent(whole[i], whole[j]).first);
  return out;
}

// One size: its row of the CSV; "" or the error.
std::string studySize(SceneGarment& garment, const TriangleMesh& base, int sections, double timeStep,
                      const SizeStudyOptions& options, std::ostream& csv) {
  const auto start = std::chrono::steady_clock::now();
  const SizedGarment sized(base, sections, options.coarseShare);
  const double preparation = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  garment.replaceGarment(sized.mesh);
  const Drapes d = drapeAtEachStep(garment, sized, timeStep, options);
  const int triangles = static_cast<int>(sized.mesh.triangles.size());
  const size_t runs = options.stepFactors.size();
  csv << triangles << ',' << sized.mesh.vertices.size() << ',' << options.method << ',' << runs << ','
      << sized.script.coarseSections() << ',' << sized.script.levels() << ','
      << sized.script.levels() / options.splitTime << ',';
  if (!d.failure.empty()) {
    std::printf("%6d sections: failed: %s\n", triangles, d.failure.c_str());
    csv << ",,,,,,,,,,,\"" << d.failure << "\"\n";
    return "";
  }
  const double fullWall = median(d.fullWall), wall = median(d.wall);
  const double floorDev = d.floorDev.empty() ? 0.0 : median(d.floorDev);
  std::printf(
      "%6d sections (%5d nodes): whole %5.0f steps %8.3f s, %zu/%zu rested | from %5d: %5.0f steps %8.3f s, "
      "%d/%zu rested %5.2fx dev mean %6.3f %% max %6.3f %%, floor %6.3f %% (prepared in %.2f s)\n",
      triangles, static_cast<int>(sized.mesh.vertices.size()), median(d.fullSteps), fullWall,
      static_cast<size_t>(d.fullRested), runs, sized.script.coarseSections(), median(d.steps), wall, d.rested, runs,
      fullWall / wall, median(d.meanDev), median(d.maxDev), floorDev, preparation);
  std::fflush(stdout);
  csv << median(d.fullSteps) << ',' << fullWall << ',' << d.fullRested << ',' << median(d.steps) << ',' << wall << ','
      << d.rested << ',' << fullWall / wall << ',' << median(d.meanDev) << ',' << median(d.maxDev) << ',' << floorDev
      << ',' << preparation << ",\n";
  return "";
}

}  // namespace

int runSizeStudy(const SizeStudyOptions& options) {
  Method method;
  if (!parsesOrReports([&] { method = parseMethod(options.method); })) return 2;
  SceneGarment garment;
  if (!garment.loadOrReport(options.scene)) return 1;
  std::string error;
  configure(*garment.engine, method);
  garment.engine->maxTime = options.maxTime;
  const TriangleMesh base = garment.engine->restGarment();
  std::filesystem::create_directories(options.outDir);
  const bool written = writeCsv(options.outDir + "/sizes.csv", [&](std::ostream& csv) -> std::string {
    // Steps, walls and deviations are medians over the time steps; *_rested count the
    // drapes that came to rest within maxTime.
    csv << "sections,nodes,method,time_steps,coarse_sections,levels,split_rate_per_s,full_steps,full_median_wall_s,"
           "full_rested,steps,median_wall_s,rested,speed_up,mean_dev_pct_height,max_dev_pct_height,"
           "floor_mean_dev_pct_height,preparation_s,failure\n";
    for (int sections : options.sizes)
      if (std::string e = studySize(garment, base, sections, method.drape.timeStep, options, csv); !e.empty()) return e;
    return "";
  });
  if (!written) return 1;
  chartCsv(options.plotScript, options.outDir + "/sizes.csv", options.outDir + "/sizes.png");
  return 0;
}

}  // namespace figment::bench
