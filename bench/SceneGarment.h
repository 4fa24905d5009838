#pragma once
// The last garment of a scene (an outfit's outer layer), for studies that re-run its
// ClothEngine with other settings: the engine, the Coordinate3 it feeds, and its rest shape.

#include <Inventor/nodes/SoCoordinate3.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "nodes/cloth/ClothEngine.h"
#include "session/SceneSession.h"
#include "sim/core/TriangleMesh.h"
#include "sim/drape/DrapeReport.h"

namespace figment::bench {

// What `repeat` drapes with the same fields came to: the last one's statistics and
// positions, the median wall time, or the first error.
struct RepeatedDrape {
  figment::DrapeReport report;
  double medianWall = 0.0;
  std::vector<SbVec3f> positions;
  std::string error;
};

struct SceneGarment {
  session::SceneSession session;  // holds the scene; release() empties it
  ClothEngine* engine = nullptr;
  SoCoordinate3* coordinates = nullptr;
  std::vector<SbVec3f> rest;
  std::vector<std::array<int, 2>> edges;  // each edge of the garment's triangles once

  // Reads `scene`; on failure returns false and sets `error` to one line.
  bool load(const std::string& scene, std::string& error);
  // The same, saying "figment-bench: <error>" on stderr when it fails.
  bool loadOrReport(const std::string& scene);
  void release();
  // Drapes `mesh` instead of the scene's garment from now on: the engine's restPoints and
  // coordIndex are disconnected from the scene and set to it (vertices as floats).
  void replaceGarment(const TriangleMesh& mesh);
  // Simulates with the engine's current fields; the draped positions.
  std::vector<SbVec3f> drape();
  // Simulates `repeat` times (stopping at an error).
  RepeatedDrape drapeRepeatedly(int repeat);
  // m: the rest shape's extent along y.
  double height() const;
  // Mean and largest distance between two drapes of the garment, % of height().
  std::pair<double, double> deviationPercent(const std::vector<SbVec3f>& a, const std::vector<SbVec3f>& b) const;
  // Largest |edge length / rest length - 1| of `positions`.
  double maxEdgeStrain(const std::vector<SbVec3f>& positions) const;
};

}  // namespace figment::bench
