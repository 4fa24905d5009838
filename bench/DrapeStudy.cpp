#include "DrapeStudy.h"

#include "Statistics.h"
#include "nodes/ClothEngine.h"
#include "nodes/Init.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace figment::bench {

int runDrapeStudy(const DrapeStudyOptions& options) {
  figment::init();
  SoInput input;
  if (!input.openFile(options.scene.c_str())) {
    std::cerr << "figment-bench: " << options.scene << ": cannot open the scene\n";
    return 1;
  }
  SoSeparator* root = SoDB::readAll(&input);
  if (!root) {
    std::cerr << "figment-bench: " << options.scene << ": cannot read the scene\n";
    return 1;
  }
  root->ref();
  const std::vector<ClothEngine*> engines = findClothEngines(root);
  if (engines.empty()) {
    std::cerr << "figment-bench: " << options.scene << ": no ClothEngine to time\n";
    root->unref();
    return 1;
  }
  std::filesystem::create_directories(options.outDir);
  const std::string csvPath = options.outDir + "/drape.csv";
  const std::string partialPath = csvPath + ".partial";
  std::ofstream csv(partialPath);
  csv << "run,garment,triangles,iterations,simulated_s,wall_s,at_rest,iterations_per_s\n";
  std::vector<double> wall, rate;
  for (int run = 0; run < options.repeat; ++run) {
    for (ClothEngine* engine : engines) engine->restPoints.touch();  // inputs changed: simulate again
    SoGetBoundingBoxAction bbox(SbViewportRegion(640, 480));
    bbox.apply(root);  // reading the garment's coordinates evaluates its engine
    for (ClothEngine* engine : engines) {
      if (!engine->lastError().empty()) {
        std::cerr << "figment-bench: " << options.scene << ": " << engine->lastError() << "\n";
        root->unref();
        return 1;
      }
      const ClothEngine::RunStats& stats = engine->lastRun();
      const double perSecond = stats.iterations / stats.wallSeconds;
      const std::string garment = engine->getName().getLength() ? engine->getName().getString() : "unnamed";
      csv << run << ',' << garment << ',' << stats.triangles << ',' << stats.iterations << ','
          << stats.simulatedSeconds << ',' << stats.wallSeconds << ',' << (stats.atRest ? 1 : 0) << ',' << perSecond
          << '\n';
      wall.push_back(stats.wallSeconds);
      rate.push_back(perSecond);
      std::cout << "run " << run << ": " << engine->label() << " " << stats.triangles << " triangles, "
                << stats.iterations << " iterations, " << stats.simulatedSeconds << " s simulated in "
                << stats.wallSeconds << " s" << (stats.atRest ? ", at rest" : ", not at rest") << "\n";
    }
  }
  csv.close();
  std::filesystem::rename(partialPath, csvPath);
  std::cout << "median wall " << median(wall) << " s, median " << median(rate) << " iterations/s; " << csvPath
            << "\n";
  root->unref();
  return 0;
}

}  // namespace figment::bench
