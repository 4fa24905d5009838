// figment-size: a size recommendation by simulation (docs/sizes.md).
//   figment-size --style STYLE --sex female|male (--body FILE | --stature M --bust-girth M
//                --waist-girth M --hip-girth M) [--chart FILE] [--json] [--warm]
// Drapes the chart's nearest size of the style and its neighbours on the body, measures
// each one's fit per region and recommends the smallest with no region tight. Prints each
// size's regions and verdicts (or one JSON object with --json) on stdout. Bad input is one
// line on stderr and exit status 1.

#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ToolMain.h"
#include "io/FitMapScene.h"
#include "io/GarmentCatalogue.h"
#include "io/MakeHumanFiles.h"
#include "io/MakeHumanLibrary.h"
#include "io/MeshExport.h"
#include "io/RecommendationJson.h"
#include "io/SizeChartFile.h"
#include "sim/fit/FitMap.h"
#include "sim/fit/SizeFitter.h"

namespace {

const figment::tools::ToolMain kTool{"figment-size"};

struct Request {
  std::string style, sex, body, chart;
  std::map<std::string, double> typed;  // makeMeasuredBody's keys -> m
  bool json = false, warm = false;
  std::string fitMap, fitMapDir;  // kind; folder for body.obj and <size>.iv
  std::string size;               // set: try this size on only, no recommendation
};

void printText(const figment::Recommendation& r, const std::string& style) {
  if (!r.recommended.empty())
    std::printf("%s: recommended size %s%s\n", style.c_str(), r.recommended.c_str(),
                r.allTight ? " (every candidate is tight somewhere: the largest)" : "");
  for (const figment::SizeFit& fit : r.sizes) {
    std::printf("\n%s: %s (%d steps%s, %.2f s)\n", fit.size.c_str(), fit.text.c_str(), fit.drape.report.run.iterations,
                fit.drape.report.warm ? ", warm start" : "", fit.drape.report.run.wallSeconds);
    std::printf("  %-11s %9s %8s %8s %10s %9s  %s\n", "region", "stretch%", "max%", "ease mm", "girth ease", "kPa",
                "verdict");
    for (size_t i = 0; i < fit.regions.size(); ++i) {
      const figment::RegionFit& g = fit.regions[i];
      if (!g.covered()) continue;
      char girth[32] = "-";
      if (std::isfinite(g.girthEase)) std::snprintf(girth, sizeof girth, "%.1f cm", 100 * g.girthEase);
      std::printf("  %-11s %9.1f %8.1f %8.1f %10s %9.3f  %s\n", g.name.c_str(), 100 * g.meanStrain, 100 * g.maxStrain,
                  1000 * g.ease, girth, g.pressure / 1000, figment::verdictName(fit.verdicts[i]));
    }
  }
}

// Each candidate's fit map: DIR/body.obj and DIR/<size>.iv, for figment-view.
void writeFitMaps(const Request& request, figment::SizeFitter& fitter, const figment::SizeChart& chart,
                  figment::Sex sex, const figment::TriangleMesh& body, const figment::Recommendation& r) {
  const std::string dir = request.fitMapDir.empty() ? "." : request.fitMapDir;
  figment::exportObj(figment::numberedByFirstUse(body), dir + "/body.obj");
  const figment::MeshCollider collider(body);
  const figment::FitMapKind kind = figment::fitMapKind(request.fitMap);
  for (const figment::SizeFit& fit : r.sizes) {
    const figment::SizeFitter::Graded& graded = fitter.graded(sex, chart.find(sex, fit.size));
    const figment::TriangleMesh& garment = graded.garment;
    figment::FitInput input = fitter.fitInput(graded);
    input.positions = &fit.drape.positions;
    input.body = &collider;
    const std::vector<int> bands = figment::fitMapBands(input, kind, fitter.rule().limits);
    figment::writeFitMapScene(dir + "/" + fit.size + ".iv", {fit.drape.positions, garment.triangles}, bands,
                              "body.obj");
  }
}

// The recommendation for `body`; the exit status.
int recommend(const Request& request, const figment::HumanModel& model, const figment::TriangleMesh& body) {
  const figment::SizeChart chart = figment::readSizeChart(request.chart);
  std::optional<figment::SewnStyle> sewn;
  if (!figment::findStyle(request.style)) {
    const figment::GarmentCatalogue catalogue(figment::defaultCataloguePath());
    sewn = figment::sewnStyle(*catalogue.style(request.style), chart);
  }
  figment::SizeFitter fitter = sewn ? figment::SizeFitter(model, chart, *sewn)
                                    : figment::SizeFitter(model, chart, *figment::findStyle(request.style));
  const figment::Sex sex = request.sex == "male" ? figment::Sex::Male : figment::Sex::Female;
  figment::Recommendation r;
  if (request.size.empty()) {
    r = fitter.recommend(body, sex, request.warm);
  } else {
    const int size = chart.find(sex, request.size);
    if (size < 0) return kTool.fail("--size " + request.size + ": no " + figment::sexName(sex) + " size of that name");
    r.sizes.push_back(fitter.tryOn(body, sex, size));
  }
  if (!request.fitMap.empty()) writeFitMaps(request, fitter, chart, sex, body, r);
  for (const std::string& line : figment::unrestedSizeLines(r, request.style, fitter.parameters().maxTime))
    std::fprintf(stderr, "%s: %s\n", kTool.program().c_str(), line.c_str());
  if (request.json)
    std::printf("%s\n", figment::recommendationJson(r).c_str());
  else
    printText(r, request.style);
  return 0;
}

int run(const Request& request) {
  figment::MakeHumanLibrary human;
  if (human.dir().empty()) return kTool.fail(figment::kMakeHumanDataMissing);
  try {
    const figment::HumanModel& model = human.model();
    if (!request.body.empty()) {
      figment::tools::BodyInput input;
      input.name = request.body;
      return kTool.withBody(input, [&](const figment::TriangleMesh& body, const std::string&) {
        return recommend(request, model, body);
      });
    }
    std::vector<figment::MeasurementGoal> goals;
    for (const auto& [key, value] : request.typed) goals.push_back({key, value});
    return recommend(request, model,
                     human.measuredBody(request.sex == "male" ? figment::Sex::Male : figment::Sex::Female, goals).body);
  } catch (const std::exception& error) {
    return kTool.fail(error.what());
  }
}

}  // namespace

// --style as a catalogue garment ("pencil:M": its style, and its size tried on) or a pattern
// style of the catalogue (a shop's own garments, sewn): -1 to go on, else the exit status.
int resolveStyle(Request& request) {
  if (request.style.find(':') != std::string::npos) {
    // A catalogue garment, "pencil:M": its style, and its size tried on.
    try {
      const figment::GarmentCatalogue catalogue(figment::defaultCataloguePath());
      const figment::CatalogueItem item =
          catalogue.resolve(request.style, request.sex == "male" ? figment::Sex::Male : figment::Sex::Female);
      if (!request.size.empty())
        return kTool.fail("--size " + request.size + ": --style " + request.style + " names the size");
      request.style = item.styleName;
      request.size = item.sizeName;
    } catch (const std::exception& error) {
      return kTool.fail("--style " + std::string(error.what()));
    }
  }
  if (!figment::findStyle(request.style)) {
    // A pattern style of the catalogue (a shop's own garments, sewn).
    try {
      const figment::GarmentCatalogue catalogue(figment::defaultCataloguePath());
      const figment::CatalogueStyle* sold = catalogue.style(request.style);
      if (!sold || !sold->sewn()) {
        std::string patterns;
        for (const figment::CatalogueStyle& style : catalogue.styles())
          if (style.sewn()) patterns += ", " + style.name;
        return kTool.fail("--style " + request.style + ": not one of " + figment::styleNames() + patterns +
                          " (or a catalogue garment, style:size)");
      }
    } catch (const std::exception& error) {
      return kTool.fail(error.what());
    }
  }
  return -1;
}

int main(int argc, char** argv) {
  CLI::App app{"Recommends a garment size by draping the size chart's candidates on a body.", kTool.program()};
  Request request;
  request.chart = figment::defaultSizeChartPath();
  app.add_option("--style", request.style,
                 figment::styleNames() +
                     ", or a pattern style of the catalogue (scenes/catalogue/: tee, pencilskirt...); or a "
                     "catalogue garment, style:size[:rrggbb]: that size tried on, as --size")
      ->required();
  app.add_option("--sex", request.sex, "female or male")->required()->check(CLI::IsMember({"female", "male"}));
  auto* body = app.add_option("--body", request.body, "a body mesh file (metres, y up) instead of measurements");
  for (const char* key : {"stature", "bust_girth", "waist_girth", "hip_girth"}) {
    std::string name = std::string("--") + key;
    for (char& c : name)
      if (c == '_') c = '-';
    app.add_option_function<double>(
           name, [&request, key](double v) { request.typed[key] = v; }, std::string(key) + ", m")
        ->excludes(body);
  }
  app.add_option("--chart", request.chart, "size chart file")->capture_default_str();
  app.add_option("--size", request.size, "try this size on only (letter code or number): no recommendation");
  app.add_flag("--json", request.json, "one JSON object on stdout");
  app.add_flag("--warm", request.warm,
               "start each size from its neighbour's drape (fewer steps; may change a verdict near its edge: the "
               "service drapes each size from its cut shape, as without it)");
  app.add_option("--fit-map", request.fitMap,
                 "write each size's fit map, a scene for figment-view: stretch, ease or pressure")
      ->check(CLI::IsMember({"stretch", "ease", "pressure"}));
  app.add_option("--fit-map-dir", request.fitMapDir, "folder for the fit maps (<size>.iv and body.obj)")
      ->capture_default_str();
  if (const int status = kTool.parse(app, argc, argv); status >= 0) return status;
  if (const int status = resolveStyle(request); status >= 0) return status;
  if (request.body.empty() && request.typed.size() < 4)
    return kTool.fail("give --body FILE, or all of --stature, --bust-girth, --waist-girth and --hip-girth");
  return run(request);
}
