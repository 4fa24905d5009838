#include "FitStudy.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "CsvFile.h"
#include "Statistics.h"
#include "io/GarmentCatalogue.h"
#include "io/MakeHumanFiles.h"
#include "io/MakeHumanLibrary.h"
#include "io/SizeChartFile.h"
#include "sim/fit/SizeFitter.h"

namespace figment::bench {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int steps(const Recommendation& r) {
  int sum = 0;
  for (const SizeFit& fit : r.sizes) sum += fit.drape.report.run.iterations;
  return sum;
}

struct ChartRow {
  std::string style, sex, body, recommended, coldRecommended, text;
  double warm, cold;
  int warmSteps, coldSteps, sizes;
};

// Every chart body of `sex` with `style`: the recommendation warm (median of `repeat`) and cold.
void chartRows(SizeFitter& fitter, const SizeChart& chart, const std::string& style, Sex sex, int repeat,
               std::vector<ChartRow>& rows) {
  for (size_t i = 0; i < chart.sizes(sex).size(); ++i) fitter.graded(sex, static_cast<int>(i));
  for (size_t i = 0; i < chart.sizes(sex).size(); ++i) {
    const TriangleMesh& body = fitter.graded(sex, static_cast<int>(i)).body;
    std::vector<double> warm;
    Recommendation r;
    for (int k = 0; k < repeat; ++k) {
      const auto start = std::chrono::steady_clock::now();
      r = fitter.recommend(body, sex, true);
      warm.push_back(secondsSince(start));
    }
    const auto start = std::chrono::steady_clock::now();
    const Recommendation cold = fitter.recommend(body, sex, false);
    const double coldSeconds = secondsSince(start);
    std::string text;
    for (const SizeFit& fit : r.sizes) text += (text.empty() ? "" : " | ") + fit.size + ": " + fit.text;
    rows.push_back({style, sexName(sex), chart.sizes(sex)[i].name, r.recommended, cold.recommended, text, median(warm),
                    coldSeconds, steps(r), steps(cold), static_cast<int>(r.sizes.size())});
    std::printf("%s %s %s -> %s (%.2f s warm, %d steps; cold: %s, %.2f s, %d steps)\n", style.c_str(), sexName(sex),
                rows.back().body.c_str(), r.recommended.c_str(), rows.back().warm, rows.back().warmSteps,
                cold.recommended.c_str(), coldSeconds, rows.back().coldSteps);
    std::fflush(stdout);
  }
}

struct GridRow {
  std::string style, sex;
  double position, bust, waist, hip;
  std::string recommended;  // "" when the body is out of the model's reach
};

// The chart's dimensions at `position` (size index, fractional; beyond the ends by the end steps).
ChartSize along(const std::vector<ChartSize>& sizes, double position) {
  const int last = static_cast<int>(sizes.size()) - 1;
  const int i = std::clamp(static_cast<int>(std::floor(position)), 0, last - 1);
  const double t = position - i;
  const ChartSize &a = sizes[i], &b = sizes[i + 1];
  ChartSize c = a;
  c.stature = a.stature + t * (b.stature - a.stature);
  c.bust = a.bust + t * (b.bust - a.bust);
  c.waist = a.waist + t * (b.waist - a.waist);
  c.hip = a.hip + t * (b.hip - a.hip);
  return c;
}

void gridRows(SizeFitter& fitter, MakeHumanLibrary& human, const SizeChart& chart, const FitStudyOptions& options,
              const std::string& style, Sex sex, std::vector<GridRow>& rows) {
  const std::vector<ChartSize>& sizes = chart.sizes(sex);
  const double low = -options.gridBeyond, high = static_cast<double>(sizes.size()) - 1 + options.gridBeyond;
  for (int k = 0; k < options.grid; ++k) {
    const double position = low + (high - low) * k / std::max(1, options.grid - 1);
    const ChartSize c = along(sizes, position);
    GridRow row{style, sexName(sex), position, c.bust, c.waist, c.hip, ""};
    try {
      row.recommended = fitter.recommend(human.measuredBody(c).body, sex, true).recommended;
    } catch (const UnreachableMeasurement&) {
    }
    std::printf("grid %s %s %.2f (bust %.3f waist %.3f hip %.3f) -> %s\n", style.c_str(), sexName(sex), position,
                c.bust, c.waist, c.hip, row.recommended.empty() ? "out of reach" : row.recommended.c_str());
    std::fflush(stdout);
    rows.push_back(row);
  }
}

bool soldIn(const GarmentCatalogue& catalogue, const std::string& style, Sex sex) {
  const CatalogueStyle* sold = catalogue.style(style);
  return sold && !sold->sizes(sex).empty();
}

// Whether each style's and sex's grid recommendations never get smaller: the violations,
// told apart where the catalogue does not sell the style in that sex (the flared skirt on
// men's bodies), since no shopper is told those sizes.
struct MonotonyBreaks {
  int sold = 0, unsold = 0;
};

MonotonyBreaks monotonyBreaks(const GarmentCatalogue& catalogue, const std::vector<GridRow>& grid) {
  MonotonyBreaks breaks;
  for (size_t k = 1; k < grid.size(); ++k) {
    const GridRow &a = grid[k - 1], &b = grid[k];
    if (a.style != b.style || a.sex != b.sex || a.recommended.empty() || b.recommended.empty()) continue;
    const Sex sex = a.sex == "male" ? Sex::Male : Sex::Female;
    if (catalogue.chart().find(sex, b.recommended) < catalogue.chart().find(sex, a.recommended)) {
      const bool sold = soldIn(catalogue, a.style, sex);
      std::printf("not monotone%s: %s %s at %.2f -> %s, at %.2f -> %s\n", sold ? "" : " (not sold in this sex)",
                  a.style.c_str(), a.sex.c_str(), a.position, a.recommended.c_str(), b.position, b.recommended.c_str());
      ++(sold ? breaks.sold : breaks.unsold);
    }
  }
  return breaks;
}

void summarise(const std::vector<ChartRow>& rows) {
  std::vector<double> warm, cold, saved;
  int own = 0, coldOwn = 0, warmSteps = 0, coldSteps = 0;
  for (const ChartRow& r : rows) {
    warm.push_back(r.warm);
    cold.push_back(r.cold);
    saved.push_back(r.coldSteps - r.warmSteps);
    own += r.recommended == r.body;
    coldOwn += r.coldRecommended == r.body;
    warmSteps += r.warmSteps;
    coldSteps += r.coldSteps;
  }
  std::printf(
      "chart bodies: %zu, own size recommended for %d; median recommendation %.2f s warm, %.2f s cold; "
      "steps %d warm against %d cold (median saved per recommendation %.0f)\n",
      rows.size(), own, median(warm), median(cold), warmSteps, coldSteps, median(saved));
}

int writeFitCsv(const FitStudyOptions& options, const GarmentCatalogue& catalogue, const std::vector<ChartRow>& rows,
                const std::vector<GridRow>& grid) {
  std::filesystem::create_directories(options.outDir);
  const bool written = writeCsv(options.outDir + "/fit.csv", [&](std::ostream& csv) -> std::string {
    csv << "style,sex,body,recommended,cold_recommended,sizes,warm_s,cold_s,warm_steps,cold_steps,verdicts\n";
    for (const ChartRow& r : rows)
      csv << r.style << ',' << r.sex << ',' << r.body << ',' << r.recommended << ',' << r.coldRecommended << ','
          << r.sizes << ',' << r.warm << ',' << r.cold << ',' << r.warmSteps << ',' << r.coldSteps << ",\"" << r.text
          << "\"\n";
    return "";
  });
  if (!written) return 1;
  if (!rows.empty()) summarise(rows);
  if (grid.empty()) return 0;
  const bool gridWritten = writeCsv(options.outDir + "/fit-grid.csv", [&](std::ostream& csv) -> std::string {
    csv << "style,sex,position,bust,waist,hip,recommended\n";
    for (const GridRow& r : grid)
      csv << r.style << ',' << r.sex << ',' << r.position << ',' << r.bust << ',' << r.waist << ',' << r.hip << ','
          << r.recommended << '\n';
    return "";
  });
  const MonotonyBreaks breaks = monotonyBreaks(catalogue, grid);
  std::printf(
      "grid: %zu bodies, %d places where the recommendation got smaller (and %d in styles not sold in that "
      "sex)\n",
      grid.size(), breaks.sold, breaks.unsold);
  return gridWritten ? 0 : 1;
}

}  // namespace

int runFitStudy(const FitStudyOptions& options) {
  MakeHumanLibrary human;
  if (human.dir().empty()) {
    std::fprintf(stderr, "figment-bench: %s\n", kMakeHumanDataMissing);
    return 1;
  }
  const HumanModel& model = human.model();
  const SizeChart chart = readSizeChart(defaultSizeChartPath());
  std::vector<ChartRow> rows;
  std::vector<GridRow> grid;
  for (const std::string& styleName : options.styles) {
    const GarmentStyle* style = findStyle(styleName);
    if (!style) {
      std::fprintf(stderr, "figment-bench: --style %s: not one of %s\n", styleName.c_str(), styleNames().c_str());
      return 1;
    }
    SizeFitter fitter(model, chart, *style);
    for (const std::string& sexText : options.sexes) {
      const Sex sex = sexText == "male" ? Sex::Male : Sex::Female;
      chartRows(fitter, chart, styleName, sex, options.repeat, rows);
      gridRows(fitter, human, chart, options, styleName, sex, grid);
    }
  }
  return writeFitCsv(options, GarmentCatalogue(defaultCataloguePath()), rows, grid);
}

}  // namespace figment::bench
