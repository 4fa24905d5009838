#include "MethodStudy.h"

#include <Inventor/SbName.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

#include "CsvFile.h"
#include "MethodSpec.h"
#include "SceneGarment.h"
#include "Statistics.h"
#include "nodes/body/CollisionBody.h"
#include "sim/collision/Collider.h"

namespace figment::bench {

namespace {

// What one method's drape came to: an error in its fields, or the drapes'.
RepeatedDrape drape(SceneGarment& garment, const Method& m, int repeat) {
  configure(*garment.engine, m);
  return garment.drapeRepeatedly(repeat);
}

struct Measures {
  double meanDeviation = NAN;  // m, against the reference
  double maxStrain = NAN;
  int inside = 0;          // nodes inside the body
  double topHeight = NAN;  // m, mean height of the rest shape's top ring
};

// The nodes of the rest shape's top centimetre: a skirt's waistband, a dress's top.
std::vector<int> topRing(const std::vector<SbVec3f>& rest) {
  float top = -std::numeric_limits<float>::max();
  for (const SbVec3f& p : rest) top = std::max(top, p[1]);
  std::vector<int> ring;
  for (size_t i = 0; i < rest.size(); ++i)
    if (rest[i][1] > top - 0.01f) ring.push_back(static_cast<int>(i));
  return ring;
}

Measures measure(const SceneGarment& garment, const std::vector<SbVec3f>& x, const std::vector<SbVec3f>& reference) {
  Measures m;
  m.maxStrain = garment.maxEdgeStrain(x);
  m.meanDeviation = 0.0;
  for (size_t i = 0; i < x.size(); ++i) m.meanDeviation += (x[i] - reference[i]).length();
  m.meanDeviation /= static_cast<double>(x.size());
  const std::vector<int> ring = topRing(garment.rest);
  m.topHeight = 0.0;
  for (int i : ring) m.topHeight += x[i][1];
  m.topHeight /= static_cast<double>(ring.size());
  if (const CollisionBody* body = asCollisionBody(garment.engine->body.getValue())) {
    const std::shared_ptr<const Collider> collider = body->bodyCollider();
    Contact contact;
    for (const SbVec3f& p : x)
      if (collider->contact(Vec3(p[0], p[1], p[2]), 0.0, 0.05, contact) && contact.distance < 0.0) ++m.inside;
  }
  return m;
}

void report(const std::string& scene, const Method& m, const RepeatedDrape& o, const Measures& s, double garmentHeight,
            std::ostream& csv) {
  // One step's breakdown (the implicit integrator's; zeros for the explicit ones), ms.
  const figment::DrapeReport& c = o.report;
  const double steps = std::max(1L, c.run.implicitCosts.steps);
  char line[640];
  std::snprintf(line, sizeof line, "%s,%s,%s,%g,%s,%g,%d,%.5g,%d,%.4f,%.6g,%.4f,%.4g,%d,%.4f,%.1f,%.4f,%.4f,%.4f\n",
                scene.c_str(), fieldName(m.drape.integrator), fieldName(m.drape.limiter),
                m.drape.limiter == AccelerationLimiter::None ? 0.0 : m.drape.limit.value_or(0.0), m.text.c_str(),
                m.drape.timeStep, o.report.run.iterations, o.report.run.simulatedTime, o.report.run.atRest ? 1 : 0,
                o.medianWall, s.meanDeviation, 100.0 * s.meanDeviation / garmentHeight, s.maxStrain, s.inside,
                s.topHeight, c.run.implicitCosts.solverIterations / steps,
                1000 * c.run.implicitCosts.assemblySeconds / steps, 1000 * c.run.implicitCosts.solveSeconds / steps,
                1000 * c.run.implicitCosts.contactSeconds / steps);
  csv << line;
  csv.flush();
  std::printf("%-24s %6d steps %6.3f s sim %7.3f s wall %-6s dev %6.3f %% strain %5.3f inside %3d top %.3f m",
              m.text.c_str(), o.report.run.iterations, o.report.run.simulatedTime, o.medianWall,
              o.report.run.atRest ? "rest" : "moving", 100.0 * s.meanDeviation / garmentHeight, s.maxStrain, s.inside,
              s.topHeight);
  if (c.run.implicitCosts.steps > 0)
    std::printf("  | step: %.0f PCG its, %.2f ms forces+matrix, %.2f ms solve, %.2f ms contacts",
                c.run.implicitCosts.solverIterations / steps, 1000 * c.run.implicitCosts.assemblySeconds / steps,
                1000 * c.run.implicitCosts.solveSeconds / steps, 1000 * c.run.implicitCosts.contactSeconds / steps);
  std::printf("\n");
}

// Every method on one scene; "" or the error.
std::string studyScene(const std::string& scene, const MethodStudyOptions& options, std::ostream& csv) {
  SceneGarment garment;
  std::string error;
  if (!garment.load(scene, error)) return error;
  const RepeatedDrape reference = drape(garment, parseMethod(options.reference), 1);
  if (!reference.error.empty()) return scene + ": the reference " + options.reference + ": " + reference.error;
  const double garmentHeight = garment.height();
  std::printf("%s: reference %s, %d steps, %.3f s simulated, %s\n", scene.c_str(), options.reference.c_str(),
              reference.report.run.iterations, reference.report.run.simulatedTime,
              reference.report.run.atRest ? "at rest" : "moving");
  for (const std::string& text : options.methods) {
    const Method m = parseMethod(text);
    const RepeatedDrape o = drape(garment, m, options.repeat);
    if (!o.error.empty()) {
      std::printf("%-26s failed: %s\n", text.c_str(), o.error.c_str());
      csv << scene << ',' << fieldName(m.drape.integrator) << ',' << fieldName(m.drape.limiter) << ",,\"" << text
          << "\"," << m.drape.timeStep << ",,,,,,,,,,,,,\n";
      continue;
    }
    report(scene, m, o, measure(garment, o.positions, reference.positions), garmentHeight, csv);
  }
  return "";
}

}  // namespace

int runMethodStudy(const MethodStudyOptions& options) {
  if (!parsesOrReports([&] {
        parseMethod(options.reference);
        for (const std::string& text : options.methods) parseMethod(text);
      }))
    return 2;
  std::filesystem::create_directories(options.outDir);
  const bool written = writeCsv(options.outDir + "/methods.csv", [&](std::ostream& csv) -> std::string {
    csv << "scene,integrator,limiter,limit_g,method,dt,steps,simulated_s,at_rest,median_wall_s,mean_dev_m,"
           "mean_dev_pct_height,max_edge_strain,nodes_inside,top_height_m,solver_iterations_per_step,"
           "assembly_ms_per_step,solve_ms_per_step,contact_ms_per_step\n";
    for (const std::string& scene : options.scenes)
      if (std::string error = studyScene(scene, options, csv); !error.empty()) return error;
    return "";
  });
  return written ? 0 : 1;
}

}  // namespace figment::bench
