#include "SceneGarment.h"

#include <Inventor/SoPath.h>
#include <Inventor/engines/SoEngineOutput.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <stdexcept>

#include "Statistics.h"
#include "nodes/Init.h"
#include "nodes/SceneSearch.h"
#include "sim/core/TriangleMesh.h"

namespace figment::bench {

namespace {

// The Coordinate3 whose points `engine` feeds, or null.
SoCoordinate3* coordinatesFedBy(SoNode* root, const ClothEngine* engine) {
  const SoPathList found = findAll(root, SoCoordinate3::getClassTypeId());
  for (int i = 0; i < found.getLength(); ++i) {
    auto* candidate = static_cast<SoCoordinate3*>(fullTail(found[i]));
    SoEngineOutput* output = nullptr;
    if (candidate->point.getConnectedEngine(output) && output == &engine->positions) return candidate;
  }
  return nullptr;
}

// Each edge of the garment's triangles once, as (smaller, larger) vertex index.
std::vector<std::array<int, 2>> uniqueEdges(const TriangleMesh& garment) {
  std::set<std::array<int, 2>> unique;
  for (const auto& triangle : garment.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = triangle[k], b = triangle[(k + 1) % 3];
      unique.insert({std::min(a, b), std::max(a, b)});
    }
  return {unique.begin(), unique.end()};
}

}  // namespace

bool SceneGarment::load(const std::string& scene, std::string& error) {
  figment::init();
  if (!session.load(scene)) {
    error = scene + ": " + session.loadError();
    return false;
  }
  if (session.engines().empty()) {
    error = scene + ": no ClothEngine";
    return false;
  }
  // The last garment: a single garment, or an outfit's outer layer (scenes list layers
  // inside out; the inner ones drape once, as the scene has them).
  engine = session.engines().back();
  coordinates = coordinatesFedBy(session.scene(), engine);
  if (!coordinates) {
    error = scene + ": no Coordinate3 fed by " + engine->label();
    return false;
  }
  rest.assign(engine->restPoints.getValues(0), engine->restPoints.getValues(0) + engine->restPoints.getNum());
  try {
    edges = uniqueEdges(engine->restGarment());
  } catch (const std::invalid_argument& e) {
    error = scene + ": " + engine->label() + ": " + e.what();
    return false;
  }
  return true;
}

void SceneGarment::release() {
  session.clear();
  engine = nullptr;
  coordinates = nullptr;
}

void SceneGarment::replaceGarment(const TriangleMesh& mesh) {
  engine->restPoints.disconnect();
  engine->coordIndex.disconnect();
  rest.clear();
  for (const Vec3& x : mesh.vertices) rest.emplace_back(float(x.x()), float(x.y()), float(x.z()));
  std::vector<int32_t> index;
  for (const Triangle& t : mesh.triangles) index.insert(index.end(), {t[0], t[1], t[2], -1});
  engine->restPoints.setValues(0, static_cast<int>(rest.size()), rest.data());
  engine->restPoints.setNum(static_cast<int>(rest.size()));
  engine->coordIndex.setValues(0, static_cast<int>(index.size()), index.data());
  engine->coordIndex.setNum(static_cast<int>(index.size()));
  edges = uniqueEdges(mesh);
}

std::vector<SbVec3f> SceneGarment::drape() {
  const SbVec3f* draped = coordinates->point.getValues(0);  // evaluates the engine when an input changed
  return {draped, draped + coordinates->point.getNum()};
}

RepeatedDrape SceneGarment::drapeRepeatedly(int repeat) {
  RepeatedDrape out;
  std::vector<double> wall;
  for (int i = 0; i < repeat && out.error.empty(); ++i) {
    engine->restPoints.touch();  // simulate again
    out.positions = drape();
    out.error = engine->lastError();
    out.report = engine->lastRun();
    wall.push_back(out.report.wallSeconds);
  }
  if (out.error.empty()) out.medianWall = median(wall);
  return out;
}

bool SceneGarment::loadOrReport(const std::string& scene) {
  std::string error;
  if (load(scene, error)) return true;
  std::fprintf(stderr, "figment-bench: %s\n", error.c_str());
  return false;
}

double SceneGarment::height() const {
  float low = std::numeric_limits<float>::max(), high = -low;
  for (const SbVec3f& p : rest) low = std::min(low, p[1]), high = std::max(high, p[1]);
  return high - low;
}

std::pair<double, double> SceneGarment::deviationPercent(const std::vector<SbVec3f>& a,
                                                         const std::vector<SbVec3f>& b) const {
  double mean = 0.0, largest = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    const double d = (a[i] - b[i]).length();
    mean += d, largest = std::max(largest, d);
  }
  mean /= static_cast<double>(a.size());
  return {100.0 * mean / height(), 100.0 * largest / height()};
}

double SceneGarment::maxEdgeStrain(const std::vector<SbVec3f>& positions) const {
  double worst = 0.0;
  for (const auto& [a, b] : edges) {
    const double restLength = (rest[a] - rest[b]).length();
    const double length = (positions[a] - positions[b]).length();
    if (restLength > 0.0) worst = std::max(worst, std::abs(length / restLength - 1.0));
  }
  return worst;
}

}  // namespace figment::bench
