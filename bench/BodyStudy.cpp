#include "BodyStudy.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "CsvFile.h"
#include "Statistics.h"
#include "io/MakeHumanFiles.h"
#include "io/MakeHumanLibrary.h"
#include "io/MakeHumanRig.h"
#include "io/SizeChartFile.h"
#include "sim/body/SkinParts.h"
#include "sim/collision/SelfIntersections.h"
#include "sim/garment/SizeGrading.h"

namespace figment::bench {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// s of CPU this thread has used: on a shared machine, the one core's time the wall clock
// hides among the neighbours'.
double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Row {
  ChartSize set;
  double seconds = 0;     // made + measured, wall, median of the repeats
  double cpuSeconds = 0;  // the same in this thread's CPU time
  double worstError = 0;  // m, the largest |achieved - typed|
  int iterations = 0;
  double checkSeconds = 0;  // CPU: the crossing check
  size_t crossings = 0;     // triangle pairs, folds within a part included
  std::string parts;        // the part pairs that cross and do not in the base mesh, "left thigh x right thigh; ..."
  std::string refused;      // the refusal's one line, when it refused
};

// What the study checks each body against: the skin's parts and which of them cross in the base mesh.
struct Reference {
  std::vector<int> parts;
  std::vector<std::pair<int, int>> crossing;
};

std::string newPartCrossings(const std::vector<TrianglePair>& pairs, const Reference& base) {
  std::string out;
  for (const auto& [a, b] : crossingLabels(pairs, base.parts))
    if (std::find(base.crossing.begin(), base.crossing.end(), std::pair(a, b)) == base.crossing.end())
      out += (out.empty() ? "" : "; ") + skinPartNames()[size_t(a)] + " x " + skinPartNames()[size_t(b)];
  return out;
}

Row study(MakeHumanLibrary& human, const ChartSize& set, const Reference& base, int repeat) {
  Row row;
  row.set = set;
  std::vector<double> times, cpu;
  MeasuredBody made;
  try {
    for (int r = 0; r < repeat; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      const double c0 = threadSeconds();
      made = human.measuredBody(set);
      cpu.push_back(threadSeconds() - c0);
      times.push_back(secondsSince(t0));
    }
  } catch (const UnreachableMeasurement& e) {
    row.refused = e.what();
    return row;
  }
  row.seconds = median(times);
  row.cpuSeconds = median(cpu);
  row.iterations = made.iterations;
  for (const MeasurementGoal& goal : MakeHumanLibrary::goals(set))
    row.worstError = std::max(row.worstError, std::abs(made.achieved.byName(goal.key) - goal.value));
  const double c0 = threadSeconds();
  const std::vector<TrianglePair> pairs = selfIntersections(made.body);
  row.checkSeconds = threadSeconds() - c0;
  row.crossings = pairs.size();
  row.parts = newPartCrossings(pairs, base);
  return row;
}

bool writeRows(const std::string& path, const std::vector<Row>& rows) {
  return writeCsv(path, [&](std::ostream& csv) -> std::string {
    csv << "sex,size,number,stature_m,bust_m,waist_m,hip_m,make_measure_s,make_measure_cpu_s,iterations,worst_error_m,"
           "check_cpu_s,crossing_pairs,"
           "new_part_crossings,refused\n";
    for (const Row& r : rows)
      csv << sexName(r.set.sex) << ',' << r.set.name << ',' << r.set.number << ',' << r.set.stature << ',' << r.set.bust
          << ',' << r.set.waist << ',' << r.set.hip << ',' << r.seconds << ',' << r.cpuSeconds << ',' << r.iterations
          << ',' << r.worstError << ',' << r.checkSeconds << ',' << r.crossings << ",\"" << r.parts << "\",\""
          << r.refused << "\"\n";
    return "";
  });
}

int runSets(MakeHumanLibrary& human, const BodyStudyOptions& options) {
  const auto loadStart = std::chrono::steady_clock::now();
  const HumanModel& model = human.model();
  const std::vector<ChartSize> sets = bodyCheckSets(readSizeChart(defaultSizeChartPath()));
  for (const double gender : {0.0, 1.0})
    for (const double s : {0.0, 0.5, 1.0}) {  // reads the targets the fits blend
      HumanParameters p;
      p.macro.gender = gender, p.macro.weight = s, p.macro.muscle = s, p.macro.height = s;
      model.make(p);
    }
  const double load = secondsSince(loadStart);
  Reference base;
  base.parts = skinTriangleParts(readHumanRig(human.dir(), model.base().fileVertexCount), model.base());
  const std::vector<TrianglePair> baseCrossings = selfIntersections(model.base().skin);
  base.crossing = crossingLabels(baseCrossings, base.parts);

  std::vector<Row> rows;
  std::vector<double> times, cpu, checks;
  size_t refused = 0, crossing = 0;
  for (const ChartSize& set : sets) {
    rows.push_back(study(human, set, base, options.repeat));
    const Row& r = rows.back();
    if (!r.refused.empty()) std::printf("%s %s: %s\n", sexName(set.sex), set.name.c_str(), r.refused.c_str());
    if (r.refused.empty()) times.push_back(r.seconds), cpu.push_back(r.cpuSeconds), checks.push_back(r.checkSeconds);
    refused += !r.refused.empty();
    crossing += !r.parts.empty();
    if (!r.parts.empty())
      std::printf("%s %s %.2f m: %s\n", sexName(set.sex), set.name.c_str(), set.stature, r.parts.c_str());
  }
  std::filesystem::create_directories(options.outDir);
  if (!writeRows(options.outDir + "/bodies.csv", rows)) return 1;
  std::printf(
      "bodies: %zu sets, %zu refused, %zu with parts crossing that do not in the base mesh (base mesh: %zu crossing "
      "pairs); data load "
      "%.3f s; make + measure median %.3f s, p90 %.3f s (CPU: median %.3f s, p90 %.3f s); crossing check median %.3f s "
      "CPU\n",
      sets.size(), refused, crossing, baseCrossings.size(), load, times.empty() ? 0.0 : median(times),
      times.empty() ? 0.0 : quantile(times, 0.9), cpu.empty() ? 0.0 : median(cpu),
      cpu.empty() ? 0.0 : quantile(cpu, 0.9), checks.empty() ? 0.0 : median(checks));
  return 0;
}

}  // namespace

int runBodyStudy(const BodyStudyOptions& options) {
  MakeHumanLibrary human;
  if (human.dir().empty()) {
    std::fprintf(stderr, "figment-bench: %s\n", kMakeHumanDataMissing);
    return 1;
  }
  try {
    return runSets(human, options);
  } catch (const std::exception& error) {  // a chart, a data file or a body it cannot read
    std::fprintf(stderr, "figment-bench: %s\n", error.what());
    return 1;
  }
}

}  // namespace figment::bench
