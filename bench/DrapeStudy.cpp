#include "DrapeStudy.h"

#include "Statistics.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/Init.h"
#include "nodes/body/Mannequin.h"
#include "nodes/SceneSearch.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoFile.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace figment::bench {

namespace {

// The body the engines use for `method`, or null (with `error`) when the scene has no
// Mannequin to take it from.
SoNode* bodyFor(const std::string& method, SoNode* root, std::string& error) {
  if (method == "scene") return nullptr;
  const SoPathList found = findAll(root, Mannequin::getClassTypeId());
  if (found.getLength() != 1) {
    error = "--body " + method + " needs a scene with one Mannequin";
    return nullptr;
  }
  auto* mannequin = static_cast<Mannequin*>(found[0]->getTail());
  if (method == "exact") return mannequin->body.getValue();
  // The same mannequin (body, pose, size) with other volumes.
  auto* other = new Mannequin;
  other->copyFieldValues(mannequin);
  auto* file = new SoFile;
  file->ref();
  file->name = std::filesystem::absolute(method).string().c_str();
  if (file->getChildren()->getLength() == 0) {
    error = "--body " + method + ": no volumes read from it";
    file->unref();
    return nullptr;
  }
  other->addChild(file);
  file->unref();
  return other;
}

// Runs every engine options.repeat times against the body they have now; one CSV row
// per run and engine. On an engine's error sets `error`.
void timeDrapes(const std::string& method, const DrapeStudyOptions& options, SoNode* root,
                const std::vector<ClothEngine*>& engines, std::ofstream& csv, std::string& error) {
  std::vector<double> wall, rate;
  for (int run = 0; run < options.repeat; ++run) {
    for (ClothEngine* engine : engines) engine->restPoints.touch();  // inputs changed: simulate again
    SoGetBoundingBoxAction bbox(SbViewportRegion(640, 480));
    bbox.apply(root);  // reading the garment's coordinates evaluates its engine
    for (ClothEngine* engine : engines) {
      if (!engine->lastError().empty()) {
        error = engine->lastError();
        return;
      }
      const ClothEngine::RunStats& stats = engine->lastRun();
      const double perSecond = stats.iterations / stats.wallSeconds;
      const std::string garment = engine->getName().getLength() ? engine->getName().getString() : "unnamed";
      csv << method << ',' << run << ',' << garment << ',' << stats.triangles << ',' << stats.iterations << ','
          << stats.simulatedSeconds << ',' << stats.wallSeconds << ',' << (stats.atRest ? 1 : 0) << ',' << perSecond
          << '\n';
      wall.push_back(stats.wallSeconds);
      rate.push_back(perSecond);
      std::cout << method << " run " << run << ": " << engine->label() << " " << stats.triangles << " triangles, "
                << stats.iterations << " iterations, " << stats.simulatedSeconds << " s simulated in "
                << stats.wallSeconds << " s" << (stats.atRest ? ", at rest" : ", not at rest") << "\n";
    }
  }
  std::cout << method << ": median wall " << median(wall) << " s, median " << median(rate) << " iterations/s\n";
}

}  // namespace

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
  csv << "body,run,garment,triangles,iterations,simulated_s,wall_s,at_rest,iterations_per_s\n";
  std::vector<SoNode*> sceneBodies;
  for (ClothEngine* engine : engines) sceneBodies.push_back(engine->body.getValue());
  for (const std::string& method : options.bodies) {
    std::string error;
    SoNode* body = bodyFor(method, root, error);
    if (error.empty()) {
      for (size_t e = 0; e < engines.size(); ++e) engines[e]->body = body ? body : sceneBodies[e];
      timeDrapes(method, options, root, engines, csv, error);
    }
    if (!error.empty()) {
      std::cerr << "figment-bench: " << options.scene << ": " << error << "\n";
      root->unref();
      return 1;
    }
  }
  csv.close();
  std::filesystem::rename(partialPath, csvPath);
  std::cout << csvPath << "\n";
  root->unref();
  return 0;
}

}  // namespace figment::bench
