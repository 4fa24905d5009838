// An application of the extended kit: registers FIGMENT's nodes and SphereVolume, reads
// a scene, drapes its garment (by reading the draped coordinates) and says how the
// cloth lies on the ball. Exits 0 when it drapes over the ball: no node inside it, some
// resting on it (within 1 cm: a cloth that fell through is far away), and the cloth
// hanging below its centre.
//   drape_over_sphere sphere-drape.iv

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoSeparator.h>
#include <nodes/Init.h>
#include <nodes/SceneSearch.h>
#include <nodes/cloth/ClothEngine.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "SphereVolume.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SCENE.iv\n", argv[0]);
    return 2;
  }
  SoDB::init();
  figment::init();
  SphereVolume::initClass();

  SoInput in;
  if (!in.openFile(argv[1])) return 1;
  SoSeparator* root = SoDB::readAll(&in);
  if (!root) return 1;
  root->ref();
  auto* ball = dynamic_cast<SphereVolume*>(SoNode::getByName("Ball"));
  auto* draped = dynamic_cast<SoCoordinate3*>(SoNode::getByName("Draped"));
  const std::vector<ClothEngine*> engines = figment::findClothEngines(root);
  if (!ball || !draped || engines.size() != 1) {
    std::fprintf(stderr, "%s: expected a SphereVolume 'Ball', a Coordinate3 'Draped' and one ClothEngine\n", argv[1]);
    root->unref();
    return 1;
  }

  const int count = draped->point.getNum();  // reading the output drapes, once
  const SbVec3f* points = draped->point.getValues(0);
  const SbVec3f centre = ball->center.getValue();
  const float radius = ball->radius.getValue();
  float nearest = std::numeric_limits<float>::infinity(), lowest = std::numeric_limits<float>::infinity();
  for (int i = 0; i < count; ++i) {
    nearest = std::min(nearest, (points[i] - centre).length() - radius);
    lowest = std::min(lowest, points[i][1]);
  }
  const std::string& error = engines.front()->lastError();
  std::printf("%d cloth nodes; nearest %.4f m from the ball's surface; lowest %.3f m (ball centre %.3f m)%s%s\n", count,
              nearest, lowest, centre[1], error.empty() ? "" : "; ", error.c_str());
  const bool drapedOver = error.empty() && count > 0 && nearest > -0.001f && nearest < 0.01f && lowest < centre[1];
  root->unref();
  return drapedOver ? 0 : 1;
}
