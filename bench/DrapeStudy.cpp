#include "DrapeStudy.h"

#include <Inventor/fields/SoMFVec3f.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "BodyChoice.h"
#include "CsvFile.h"
#include "Statistics.h"
#include "io/DrapeReportJson.h"
#include "nodes/Init.h"
#include "nodes/cloth/ClothEngine.h"
#include "session/SceneSession.h"

namespace figment::bench {

namespace {

// One CSV row and one line on stdout for a drape.
void report(const std::string& method, bool broadPhase, int run, const ClothEngine& engine, std::ostream& csv) {
  const figment::DrapeReport& stats = engine.lastRun();
  // The figures figment-view --stats writes, by the same names (io/DrapeReportJson.h).
  const nlohmann::json figures = nlohmann::json::parse(figment::drapeReportJson(stats));
  const double perSecond = stats.run.iterations / stats.wallSeconds;
  const std::string name = engine.getName().getString();
  const std::string garment = name.empty() ? "unnamed" : name;
  csv << method << ',' << (broadPhase ? 1 : 0) << ',' << run << ',' << garment << ',' << stats.triangles << ','
      << stats.run.iterations << ',' << stats.run.simulatedTime << ',' << stats.wallSeconds << ','
      << (stats.run.atRest ? 1 : 0) << ',' << perSecond << ',' << (stats.verdict.empty() ? 1 : 0) << ','
      << figures["verdict"]["max_edge_stretch"].get<double>() << ',' << stats.run.implicitCosts.halvedSteps << ','
      << stats.run.implicitCosts.failedSteps << '\n';
  std::cout << method << (broadPhase ? "" : " (no broad phase)") << " run " << run << ": " << engine.label() << " "
            << stats.triangles << " triangles, " << stats.run.iterations << " iterations, " << stats.run.simulatedTime
            << " s simulated in " << stats.wallSeconds << " s" << (stats.run.atRest ? ", at rest" : ", not at rest")
            << (stats.run.implicitCosts.halvedSteps > 0
                    ? ", " + std::to_string(stats.run.implicitCosts.halvedSteps) + " steps halved"
                    : "")
            << (stats.verdict.empty() ? ", clean" : "; not clean: " + stats.verdict) << "\n";
}

// Runs every engine options.repeat times against the body they have now; one CSV row
// per run and engine. On an engine's error sets `error`.
void timeDrapes(const std::string& method, bool broadPhase, const DrapeStudyOptions& options,
                session::SceneSession& session, std::ostream& csv, std::string& error) {
  std::vector<double> wall, rate;
  session.context().broadPhase = broadPhase;
  for (int run = 0; run < options.repeat; ++run) {
    for (ClothEngine* engine : session.engines()) engine->restPoints.touch();  // inputs changed: simulate again
    for (const ClothEngine* engine : session.drape()) {
      if (!engine->lastError().empty()) {
        error = engine->lastError();
        return;
      }
      report(method, broadPhase, run, *engine, csv);
      wall.push_back(engine->lastRun().wallSeconds);
      rate.push_back(engine->lastRun().run.iterations / engine->lastRun().wallSeconds);
    }
  }
  session.context().broadPhase = true;
  std::cout << method << (broadPhase ? "" : " (no broad phase)") << ": median wall " << median(wall) << " s, median "
            << median(rate) << " iterations/s\n";
}

// Times the engines against each body of options.bodies in turn; "" or the error.
std::string timeEveryBody(const DrapeStudyOptions& options, session::SceneSession& session, std::ostream& csv) {
  csv << "body,broad_phase,run,garment,triangles,iterations,simulated_s,wall_s,at_rest,iterations_per_s,clean,"
         "max_edge_stretch,halved_steps,failed_steps\n";
  const std::vector<ClothEngine*>& engines = session.engines();
  std::vector<SoNode*> sceneBodies;
  for (ClothEngine* engine : engines) sceneBodies.push_back(engine->body.getValue());
  for (const std::string& method : options.bodies) {
    std::string error;
    SoNode* body = bodyFor(method, session.scene(), error);
    if (error.empty()) {
      for (size_t e = 0; e < engines.size(); ++e) engines[e]->body = body ? body : sceneBodies[e];
      for (const std::string& broadPhase : options.broadPhase)
        if (error.empty()) timeDrapes(method, broadPhase == "on", options, session, csv, error);
    }
    if (!error.empty()) return error;
  }
  return "";
}

// The scene's method replaced where the options say so.
void overrideMethod(const DrapeStudyOptions& options, session::SceneSession& session) {
  for (ClothEngine* engine : session.engines()) {
    if (!options.integrator.empty()) engine->integrator.setValue(SbName(options.integrator.c_str()));
    if (options.timeStep > 0.0) engine->timeStep = options.timeStep;
  }
}

bool writePositions(const std::string& path, session::SceneSession& session) {
  return writeCsv(path, [&](std::ostream& csv) -> std::string {
    csv << std::setprecision(9) << "garment,node,x,y,z\n";
    for (ClothEngine* engine : session.engines()) {
      SoMFVec3f positions;
      positions.connectFrom(&engine->positions);
      const std::string name = engine->getName().getLength() ? engine->getName().getString() : "unnamed";
      for (int i = 0; i < positions.getNum(); ++i)
        csv << name << ',' << i << ',' << positions[i][0] << ',' << positions[i][1] << ',' << positions[i][2] << '\n';
    }
    return "";
  });
}

}  // namespace

int runDrapeStudy(const DrapeStudyOptions& options) {
  figment::init();
  session::SceneSession session;
  if (!session.load(options.scene)) {
    std::cerr << "figment-bench: " << options.scene << ": " << session.loadError() << "\n";
    return 1;
  }
  if (session.engines().empty()) {
    std::cerr << "figment-bench: " << options.scene << ": no ClothEngine to time\n";
    return 1;
  }
  overrideMethod(options, session);
  std::filesystem::create_directories(options.outDir);
  const bool written = writeCsv(options.outDir + "/drape.csv", [&](std::ostream& csv) -> std::string {
    const std::string error = timeEveryBody(options, session, csv);
    return error.empty() ? "" : options.scene + ": " + error;
  });
  if (!written) return 1;
  if (!options.positionsFile.empty() && !writePositions(options.positionsFile, session)) return 1;
  return 0;
}

}  // namespace figment::bench
