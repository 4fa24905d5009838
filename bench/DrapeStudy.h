#pragma once
// The drape study: how long the default scene's garments take to come to rest.

#include <string>
#include <vector>

namespace figment::bench {

struct DrapeStudyOptions {
  std::string scene = "scenes/dress.iv";
  int repeat = 3;
  std::string outDir = "bench-out";
  // What the garments collide with, each timed in turn: "scene" (as written), "exact"
  // (the triangles of the scene's Mannequin body), or a volumes file (.iv, as
  // figment-fit writes) that replaces the Mannequin's children.
  std::vector<std::string> bodies = {"scene"};
  // Each body timed with the broad phase "on" (the default), "off", or both in turn: a
  // drape is the same either way, only its time differs.
  std::vector<std::string> broadPhase = {"on"};
  // Overrides of every engine's method: "" and 0 keep the scene's.
  std::string integrator;  // EULER, SYMPLECTIC, HEUN or IMPLICIT
  double timeStep = 0.0;   // s
  // When set: the last drape's node positions, CSV garment,node,x,y,z (m).
  std::string positionsFile;
};

// Reads the scene, re-runs every ClothEngine `repeat` times against each body, writes
// DIR/drape.csv and prints the medians per body. Returns the process exit code.
int runDrapeStudy(const DrapeStudyOptions& options);

}  // namespace figment::bench
