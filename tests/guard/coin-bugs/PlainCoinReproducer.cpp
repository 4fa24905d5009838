// The reproducer for docs/coin-bugs.md: what any Coin program does with a scene file, and
// nothing of FIGMENT's (Coin only, no guard). Reads FILE with SoDB::readAll, then, if it read,
// bounds it (SoGetBoundingBoxAction), renders it nowhere but through a callback action over its
// primitives (SoCallbackAction, as drawing does), writes it (SoWriteAction) and lets it go.
// Prints each step before it runs, so a crash or hang shows where:
//   figment_coin_reproducer tests/guard/coin-bugs/field-declaration.iv
// Exit status 0 when every step ran, 1 when the file did not read; a Coin bug crashes it (a
// signal) or never returns.

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoOutput.h>
#include <Inventor/SoPrimitiveVertex.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShape.h>

#include <cstdio>

namespace {

void step(const char* what) {
  std::printf("%s\n", what);
  std::fflush(stdout);
}

void onTriangle(void*, SoCallbackAction*, const SoPrimitiveVertex*, const SoPrimitiveVertex*,
                const SoPrimitiveVertex*) {}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s FILE.iv\n", argv[0]);
    return 2;
  }
  SoDB::init();
  step("read");
  SoInput in;
  if (!in.openFile(argv[1])) return 1;
  SoSeparator* root = SoDB::readAll(&in);
  if (!root) {
    step("did not read");
    return 1;
  }
  root->ref();
  step("bound");
  SoGetBoundingBoxAction box(SbViewportRegion(100, 100));
  box.apply(root);
  step("generate primitives");
  SoCallbackAction primitives;
  primitives.addTriangleCallback(SoShape::getClassTypeId(), onTriangle, nullptr);
  primitives.apply(root);
  step("write");
  SoOutput out;
  out.openFile("/dev/null");
  SoWriteAction write(&out);
  write.apply(root);
  step("unref");
  root->unref();
  step("done");
  return 0;
}
