#include "BodyStudy.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "CsvFile.h"
#include "Statistics.h"
#include "io/MakeHumanFiles.h"
#include "io/TargetLibrary.h"
#include "sim/body/BodyMeasurements.h"

namespace figment::bench {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Female and male, thin to heavy, short to tall: 2 x 3 x 3 bodies.
std::vector<HumanParameters> studyBodies() {
  std::vector<HumanParameters> bodies;
  for (double gender : {0.0, 1.0})
    for (double weight : {0.2, 0.5, 0.8})
      for (double height : {0.2, 0.5, 0.8}) {
        HumanParameters p;
        p.macro.gender = gender;
        p.macro.weight = weight;
        p.macro.height = height;
        bodies.push_back(p);
      }
  return bodies;
}

}  // namespace

int runBodyStudy(const BodyStudyOptions& options) {
  const std::string dir = findMakeHumanData();
  if (dir.empty()) {
    std::fprintf(stderr,
                 "figment-bench: MakeHuman's data not found: run scripts/setup.sh, or set FIGMENT_MAKEHUMAN_DIR\n");
    return 1;
  }
  const auto loadStart = std::chrono::steady_clock::now();
  TargetLibrary library(dir);
  const HumanModel model = loadHumanModel(dir, library);
  const std::vector<HumanParameters> bodies = studyBodies();
  for (const HumanParameters& p : bodies) model.make(p);  // reads every target the study uses
  const double load = secondsSince(loadStart);

  struct Row {
    HumanParameters p;
    double make, measure, stature;
  };
  std::vector<Row> rows;
  std::vector<double> makes, measures, totals;
  for (const HumanParameters& p : bodies) {
    std::vector<double> make, measure;
    BodyMeasurements m;
    for (int r = 0; r < options.repeat; ++r) {
      const auto start = std::chrono::steady_clock::now();
      const TriangleMesh body = model.make(p);
      make.push_back(secondsSince(start));
      const auto measureStart = std::chrono::steady_clock::now();
      m = measureBody(body);
      measure.push_back(secondsSince(measureStart));
    }
    rows.push_back({p, median(make), median(measure), m.stature});
    makes.push_back(rows.back().make);
    measures.push_back(rows.back().measure);
    totals.push_back(rows.back().make + rows.back().measure);
  }
  std::filesystem::create_directories(options.outDir);
  const bool written = writeCsv(options.outDir + "/bodies.csv", [&](std::ostream& csv) -> std::string {
    csv << "gender,weight,height,make_s,measure_s,stature_m\n";
    for (const Row& r : rows)
      csv << r.p.macro.gender << ',' << r.p.macro.weight << ',' << r.p.macro.height << ',' << r.make << ',' << r.measure
          << ',' << r.stature << '\n';
    return "";
  });
  if (!written) return 1;
  std::printf("bodies: %zu, data load %.3f s; median make %.4f s, measure %.4f s, make + measure %.4f s\n",
              bodies.size(), load, median(makes), median(measures), median(totals));
  return 0;
}

}  // namespace figment::bench
