// fuzz_scene: an input is the text of an .iv scene. It goes the way figment-view takes a scene,
// through SceneSession: read through the guard with every FIGMENT node registered
// (guard::readScene), every ClothEngine draped, the shapes checked by the guard
// (guard::checkShapes), staged and rendered through OSMesa. Errors on the way are expected and
// fine; a crash, a sanitizer report, a leak, an escaping exception or an input that runs past
// libFuzzer's -timeout is a finding.
//
// Bounds the harness puts on an input, so one input cannot take minutes (figment-view has none:
// a scene may ask for a long drape on purpose): each engine's maxTime is cut to kMaxSteps steps
// of its timeStep and to kMaxSimulated seconds. Invalid values (zero, negative, NaN) are left as
// they are, so the engine's own checks of them are fuzzed too.

#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>

#include "FuzzTempDir.h"
#include "headless/InitHeadless.h"
#include "nodes/cloth/ClothEngine.h"
#include "session/SceneRenderer.h"
#include "session/SceneSession.h"

namespace {

constexpr double kMaxSteps = 40;
constexpr double kMaxSimulated = 0.05;  // s
const figment::session::ImageSize kImage{48, 48};

// Small meshes the seeds name in place of the shipped body and garments (scenes/human.zae,
// dress.obj), so an input that keeps its MeshFile reads in microseconds, not seconds.
// tests/fuzz/make_corpus.sh renames them so in the seeds. OFF, not OBJ: assimp 5.2's OBJ reader
// allocates and fills a 16 MB line buffer for any file, which under AddressSanitizer (fresh
// pages every time) took half of each input's time; fuzz_mesh fuzzes the OBJ reader itself.
void writeMeshes() {
  figment::fuzz::writeFile("body.off",
                           "OFF\n5 6 0\n-0.1 0 -0.1\n0.1 0 -0.1\n0.1 0 0.1\n-0.1 0 0.1\n0 0.4 0\n"
                           "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n3 0 2 1\n3 0 3 2\n");
  figment::fuzz::writeFile("garment.off",
                           "OFF\n9 4 0\n-0.2 0.5 -0.2\n0 0.5 -0.2\n0.2 0.5 -0.2\n-0.2 0.5 0\n0 0.5 0\n"
                           "0.2 0.5 0\n-0.2 0.5 0.2\n0 0.5 0.2\n0.2 0.5 0.2\n"
                           "4 0 3 4 1\n4 1 4 5 2\n4 3 6 7 4\n4 4 7 8 5\n");
}

// The Mannequin seeds include the default body's fitted volumes by name.
void copyVolumes() {
  for (const char* name : {"human-volumes.iv", "human-capsules.iv"})
    std::filesystem::copy_file(std::filesystem::path(FIGMENT_SOURCE_DIR) / "scenes" / name, name,
                               std::filesystem::copy_options::overwrite_existing);
}

void boundEngines(const std::vector<ClothEngine*>& engines) {
  for (ClothEngine* engine : engines) {
    const double step = engine->timeStep.getValue();
    const double maxTime = engine->maxTime.getValue();
    if (step > 0 && std::isfinite(step) && maxTime > 0 && std::isfinite(maxTime))
      engine->maxTime = std::max(std::min({maxTime, kMaxSteps * step, kMaxSimulated}), std::min(step, maxTime));
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  figment::initHeadless();
  figment::fuzz::enterTempDir("figment-fuzz-scene");
  writeMeshes();
  copyVolumes();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // One renderer for the whole run: its OSMesa context is made on the first render only. Never
  // destroyed: at exit OSMesa's rasterizer threads are gone before static destructors run, and
  // destroying its context then waits for them forever.
  static auto& renderer = *new figment::session::SceneRenderer(kImage);
  figment::fuzz::writeFile("scene.iv", data, size);
  figment::session::SceneSession session;
  if (!session.load("scene.iv")) return 0;
  boundEngines(session.engines());
  session.drape();  // then the guard's check of the shapes
  if (!session.firstError().empty()) return 0;
  if (SoSeparator* root = session.stage(kImage, std::nullopt)) renderer.render(root);
  return 0;
}
