// fuzz_scene: an input is the text of an .iv scene. It goes the way figment-view takes a scene
// (viewer/main.cpp): read with every FIGMENT node registered (after viewer/SceneTextCheck's look
// at its text), every ClothEngine draped, the face sets' indices checked, staged and rendered
// through OSMesa. Errors on the way are expected and fine; a crash, a sanitizer report, a leak,
// an escaping exception or an input that runs past libFuzzer's -timeout is a finding.
//
// Bounds the harness puts on an input, so one input cannot take minutes (figment-view has none:
// a scene may ask for a long drape on purpose): each engine's maxTime is cut to kMaxSteps steps
// of its timeStep and to kMaxSimulated seconds. Invalid values (zero, negative, NaN) are left as
// they are, so the engine's own checks of them are fuzzed too.

#include "FuzzTempDir.h"

#include "nodes/FaceIndexCheck.h"
#include "nodes/cloth/ClothEngine.h"
#include "viewer/OffscreenContext.h"
#include "viewer/SceneRenderer.h"
#include "viewer/SceneSession.h"

#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstddef>
#include <cstdint>
#include <memory>

namespace {

constexpr double kMaxSteps = 40;
constexpr double kMaxSimulated = 0.05;  // s
const figment::viewer::ImageSize kImage{48, 48};

// Small meshes the seeds name in place of the shipped body and garments (scenes/human.zae,
// dress.obj), so an input that keeps its MeshFile reads in microseconds, not seconds.
// tests/fuzz/make_corpus.sh renames them so in the seeds.
void writeMeshes() {
  figment::fuzz::writeFile("body.obj",
                           "v -0.1 0 -0.1\nv 0.1 0 -0.1\nv 0.1 0 0.1\nv -0.1 0 0.1\nv 0 0.4 0\n"
                           "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\nf 1 3 2\nf 1 4 3\n");
  figment::fuzz::writeFile("garment.obj",
                           "v -0.2 0.5 -0.2\nv 0 0.5 -0.2\nv 0.2 0.5 -0.2\nv -0.2 0.5 0\nv 0 0.5 0\n"
                           "v 0.2 0.5 0\nv -0.2 0.5 0.2\nv 0 0.5 0.2\nv 0.2 0.5 0.2\n"
                           "f 1 4 5 2\nf 2 5 6 3\nf 4 7 8 5\nf 5 8 9 6\n");
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
  figment::viewer::initHeadless();
  figment::fuzz::enterTempDir("figment-fuzz-scene");
  writeMeshes();
  copyVolumes();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // One renderer for the whole run: its OSMesa context is made on the first render only. Never
  // destroyed: at exit OSMesa's rasterizer threads are gone before static destructors run, and
  // destroying its context then waits for them forever.
  static auto& renderer = *new figment::viewer::SceneRenderer(kImage);
  figment::fuzz::writeFile("scene.iv", data, size);
  figment::viewer::SceneSession session;
  if (!session.load("scene.iv")) return 0;
  boundEngines(session.engines());
  if (!session.drape().empty() && !session.firstError().empty()) return 0;
  if (!figment::firstFaceIndexError(session.scene()).empty()) return 0;
  renderer.render(session.stage(kImage, std::nullopt));
  return 0;
}
