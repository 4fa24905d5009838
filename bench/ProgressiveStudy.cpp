#include "ProgressiveStudy.h"

#include "CsvFile.h"
#include "MethodSpec.h"
#include "SceneGarment.h"
#include "Statistics.h"

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace figment::bench {

namespace {

struct Schedule {
  std::string text;
  double beginShare = 0.0, rate = 0.0;
};

Schedule parseSchedule(const std::string& text) {
  Schedule s{text};
  std::stringstream in(text);
  char colon = 0;
  if (!(in >> s.beginShare >> colon >> s.rate) || colon != ':' || !(s.beginShare >= 0.0 && s.beginShare <= 1.0) ||
      !(s.rate >= 0.0))
    throw std::invalid_argument("schedule \"" + text + "\": expected BEGIN_SHARE:RATE, share in [0, 1], rate >= 0");
  return s;
}

// The script's number of levels: a drape of one step that ends at the coarsest level.
int countLevels(SceneGarment& garment, const std::string& script, std::string& error) {
  ClothEngine& engine = *garment.engine;
  const double maxTime = engine.maxTime.getValue();
  engine.progressiveScript = script.c_str();
  engine.endLevel = 0;
  engine.maxTime = engine.timeStep.getValue();
  const RepeatedDrape probe = garment.drapeRepeatedly(1);
  engine.maxTime = maxTime;
  error = probe.error;
  return probe.run.levels;
}

// One method: the full garment, then each schedule; "" or the error.
std::string studyMethod(SceneGarment& garment, const std::string& script, int levels, const Method& method,
                        const ProgressiveStudyOptions& options, std::ostream& csv) {
  if (std::string error = configure(*garment.engine, method); !error.empty()) return error;
  garment.engine->progressiveScript = "";
  const RepeatedDrape full = garment.drapeRepeatedly(options.repeat);
  if (!full.error.empty()) return method.text + ", full garment: " + full.error;
  std::printf("%-22s full garment: %6d steps %7.3f s wall %s\n", method.text.c_str(), full.run.iterations,
              full.medianWall, full.run.atRest ? "rest" : "moving");
  const double garmentHeight = garment.height();
  for (const std::string& text : options.schedules) {
    const Schedule s = parseSchedule(text);
    garment.engine->progressiveScript = script.c_str();
    garment.engine->splitRate = s.rate;
    garment.engine->endLevel = -1;
    garment.engine->beginLevel = static_cast<int>(std::lround(s.beginShare * levels));
    const RepeatedDrape run = garment.drapeRepeatedly(options.repeat);
    if (!run.error.empty()) {  // a failed configuration is a result too (a blow-up, say)
      std::printf("%-22s %-10s failed: %s\n", method.text.c_str(), text.c_str(), run.error.c_str());
      csv << method.text << ',' << garment.engine->beginLevel.getValue() << ",," << s.rate << ",,,,"
          << full.run.iterations << ',' << full.medianWall << ',' << (full.run.atRest ? 1 : 0) << ",,,,\"failed: "
          << run.error << "\"\n";
      continue;
    }
    double mean = 0.0, largest = 0.0;
    for (size_t i = 0; i < run.positions.size(); ++i) {
      const double d = (run.positions[i] - full.positions[i]).length();
      mean += d, largest = std::max(largest, d);
    }
    mean /= static_cast<double>(run.positions.size());
    const double speedUp = full.medianWall / run.medianWall;
    std::printf("%-22s %-10s begin %4d of %4d: %6d steps %7.3f s wall %-6s %5.2fx  dev mean %6.3f %% max %6.3f %%\n",
                method.text.c_str(), text.c_str(), garment.engine->beginLevel.getValue(), run.run.levels,
                run.run.iterations, run.medianWall, run.run.atRest ? "rest" : "moving", speedUp,
                100.0 * mean / garmentHeight, 100.0 * largest / garmentHeight);
    csv << method.text << ',' << garment.engine->beginLevel.getValue() << ',' << run.run.levels << ',' << s.rate
        << ',' << run.run.iterations << ',' << run.medianWall << ',' << (run.run.atRest ? 1 : 0) << ','
        << full.run.iterations << ',' << full.medianWall << ',' << (full.run.atRest ? 1 : 0) << ',' << speedUp
        << ',' << 100.0 * mean / garmentHeight << ',' << 100.0 * largest / garmentHeight << ",\n";
  }
  garment.engine->progressiveScript = script.c_str();
  return "";
}

}  // namespace

int runProgressiveStudy(const ProgressiveStudyOptions& options) {
  std::vector<Method> methods;
  try {
    for (const std::string& text : options.methods) methods.push_back(parseMethod(text));
    for (const std::string& text : options.schedules) parseSchedule(text);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "figment-bench: %s\n", e.what());
    return 2;
  }
  SceneGarment garment;
  std::string error;
  if (!garment.load(options.scene, error)) {
    std::fprintf(stderr, "figment-bench: %s\n", error.c_str());
    return 1;
  }
  const std::string script = garment.engine->progressiveScript.getValue().getString();
  if (script.empty()) {
    std::fprintf(stderr, "figment-bench: %s: its ClothEngine has no progressiveScript\n", options.scene.c_str());
    return 1;
  }
  const int levels = countLevels(garment, script, error);
  if (!error.empty()) {
    std::fprintf(stderr, "figment-bench: %s\n", error.c_str());
    return 1;
  }
  std::filesystem::create_directories(options.outDir);
  const bool written = writeCsv(options.outDir + "/progressive.csv", [&](std::ostream& csv) -> std::string {
    csv << "method,begin_level,levels,split_rate_per_s,steps,median_wall_s,at_rest,full_steps,full_median_wall_s,"
           "full_at_rest,speed_up,mean_dev_pct_height,max_dev_pct_height,failure\n";
    for (const Method& method : methods)
      if (std::string e = studyMethod(garment, script, levels, method, options, csv); !e.empty()) return e;
    return "";
  });
  if (!written) return 1;
  if (!options.plotScript.empty() && std::filesystem::exists(options.plotScript)) {
    const std::string png = options.outDir + "/progressive.png";
    const std::string command = "/usr/bin/python3 '" + options.plotScript + "' '" + options.outDir +
                                "/progressive.csv' '" + png + "'";
    if (std::system(command.c_str()) == 0) std::printf("%s\n", png.c_str());
    else std::fprintf(stderr, "figment-bench: no chart (needs /usr/bin/python3 with matplotlib)\n");
  }
  return 0;
}

}  // namespace figment::bench
