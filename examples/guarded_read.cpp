// A plain Coin program that reads scenes through FIGMENT's guard: it links Coin and
// figment::guard only (no node kit, no FIGMENT node registered: Coin loads FIGMENT's nodes by
// name from the library path), reads the scene with the guard's first call, lets the engines
// evaluate, and checks the shapes with its second call before it would draw. Every refusal is
// one line and exit status 1.
//   guarded_read SCENE.iv

#include <Inventor/SoDB.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoSeparator.h>
#include <guard/Guard.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SCENE.iv\n", argv[0]);
    return 2;
  }
  SoDB::init();
  std::string error;
  SoSeparator* root = figment::guard::readScene(argv[1], error);
  if (!root) {
    std::fprintf(stderr, "guarded_read: %s: %s\n", argv[1], error.c_str());
    return 1;
  }
  // The shapes are checked against what they draw now: the check reads their coordinates, which
  // evaluates the engines feeding them (a ClothEngine drapes here).
  error = figment::guard::checkShapes(root);
  if (!error.empty()) {
    std::fprintf(stderr, "guarded_read: %s: %s\n", argv[1], error.c_str());
    root->unref();
    return 1;
  }
  SoGetBoundingBoxAction box(SbViewportRegion(100, 100));  // what a program may do only now
  box.apply(root);
  float x, y, z;
  box.getBoundingBox().getSize(x, y, z);
  std::printf("read %s: %d nodes at the top, %.2f x %.2f x %.2f m\n", argv[1], root->getNumChildren(), x, y, z);
  root->unref();
  return 0;
}
