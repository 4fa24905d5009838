// A Coin program that knows nothing of FIGMENT: no FIGMENT header, not linked to the
// node library (only Coin and, to render with no display, OSMesa through
// figment_headless, which holds no node code). It reads the scene named on the command
// line; Coin meets FIGMENT's node names it does not know and loads them itself
// (SoType::fromName opens lib<Name>.so from the library path and calls
// <Name>::initClass()). Then it renders the scene off-screen and counts what was drawn.
//
//   figment_plain_coin_reader SCENE.iv [MIN_BLUE_PIXELS [OUT.png]]
// prints "read <n> figment types; <p> pixels drawn, <b> blue-dominant" and exits 0
// when the scene read, something was drawn and at least MIN_BLUE_PIXELS (default 0)
// are of the default dress's blue; 1 when it did not read (no library on the path),
// 2 when it read but drew too little, 3 when FIGMENT was there before reading (the
// program would prove nothing).
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoOffscreenRenderer.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

#include "headless/OsmesaForCoin.h"

namespace {

// FIGMENT classes whose initClass() the scenes' loading must have brought in. Mangled
// by hand: the program must not see FIGMENT's headers.
constexpr const char* kInitClassSymbols[] = {
    "_ZN8MeshFile9initClassEv",  "_ZN11ClothEngine9initClassEv",      "_ZN13ClothingLayer9initClassEv",
    "_ZN9Mannequin9initClassEv", "_ZN16StencilSeparator9initClassEv",
};
constexpr const char* kTypeNames[] = {"MeshFile", "ClothEngine", "ClothingLayer", "Mannequin", "StencilSeparator"};

// Whether any FIGMENT class is in the program's global symbols (linked in, or loaded
// by someone before Coin).
bool figmentLinkedIn() {
  for (const char* symbol : kInitClassSymbols)
    if (dlsym(RTLD_DEFAULT, symbol)) return true;
  return false;
}

// FIGMENT types Coin knows, after reading (asking may load one more, which is harmless
// here: the scene has read already).
int knownFigmentTypes() {
  int known = 0;
  for (const char* name : kTypeNames) known += SoType::fromName(name) != SoType::badType();
  return known;
}

constexpr short kWidth = 240, kHeight = 280;
constexpr float kGrey = 0.8f;  // the background

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SCENE.iv [MIN_BLUE_PIXELS [OUT.png]]\n", argv[0]);
    return 64;
  }
  figment::useOsmesaForCoin();
  SoDB::init();
  if (figmentLinkedIn()) {
    std::fprintf(stderr, "FIGMENT is linked in before reading: nothing to prove\n");
    return 3;
  }

  SoInput in;
  if (!in.openFile(argv[1])) return 1;
  SoSeparator* scene = SoDB::readAll(&in);
  if (!scene) {
    std::fprintf(stderr, "%s did not read (is the FIGMENT library on LD_LIBRARY_PATH?)\n", argv[1]);
    return 1;
  }
  const int loaded = knownFigmentTypes();

  // What any viewer adds: a camera that frames the scene, and a headlight.
  auto* root = new SoSeparator;
  root->ref();
  auto* camera = new SoPerspectiveCamera;
  auto* light = new SoDirectionalLight;
  light->direction = SbVec3f(-0.3f, -0.4f, -1.0f);
  root->addChild(camera);
  root->addChild(light);
  root->addChild(scene);
  const SbViewportRegion viewport(kWidth, kHeight);
  camera->viewAll(root, viewport);  // reads the ClothEngine's output: it drapes here

  SoOffscreenRenderer renderer(viewport);
  renderer.setComponents(SoOffscreenRenderer::RGB);
  renderer.setBackgroundColor(SbColor(kGrey, kGrey, kGrey));
  if (!renderer.render(root)) {
    std::fprintf(stderr, "rendering failed\n");
    root->unref();
    return 2;
  }
  const int minBlue = argc > 2 ? std::atoi(argv[2]) : 0;
  if (argc > 3) renderer.writeToFile(argv[3], "png");
  const unsigned char* rgb = renderer.getBuffer();
  const int background = static_cast<int>(kGrey * 255.0f + 0.5f);
  int drawn = 0, blue = 0;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    const int r = rgb[3 * i], g = rgb[3 * i + 1], b = rgb[3 * i + 2];
    drawn += std::abs(r - background) > 3 || std::abs(g - background) > 3 || std::abs(b - background) > 3;
    blue += b > r + 30 && b > g + 15;  // the default dress's colour, lit or in shade
  }
  root->unref();
  std::printf("read %d figment types; %d pixels drawn, %d blue-dominant\n", loaded, drawn, blue);
  return drawn > 0 && blue >= minBlue ? 0 : 2;
}
