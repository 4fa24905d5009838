// fuzz_mesh: an input is a mesh file read through a MeshFile node, as a scene's body or garment
// is: assimp's import, then ours (up axis, welding by position, the crop box, the output fields,
// the collision surface and its BVH, a contact query, the bounding box).
//
// Input layout: byte 0 picks the format by file extension (assimp chooses its reader by it),
// byte 1 the up axis (low 3 bits) and whether a crop box is set (bit 3); the rest is the file.
// Errors are expected and fine (the node reports them and stays empty); a crash, a sanitizer
// report, a leak or an escaping exception is a finding.

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/errors/SoDebugError.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "FuzzTempDir.h"
#include "nodes/Init.h"
#include "nodes/body/MeshFile.h"
#include "sim/collision/MeshCollider.h"

namespace {

constexpr std::array<const char*, 4> kExtensions = {"obj", "ply", "off", "stl"};

// The node's load errors are expected: dropped, not printed thousands of times a second.
void quiet(const SoError*, void*) {}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  figment::init();
  SoDebugError::setHandlerCallback(quiet, nullptr);
  figment::fuzz::enterTempDir("figment-fuzz-mesh");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const std::string name = std::string("mesh.") + kExtensions[data[0] % kExtensions.size()];
  figment::fuzz::writeFile(name, data + 2, size - 2);

  auto* node = new MeshFile;
  node->ref();
  node->upAxis = (data[1] & 7) % 6;
  if (data[1] & 8) {
    node->cropMin.setValue(-0.5f, -0.5f, -0.5f);
    node->cropMax.setValue(0.5f, 0.5f, 0.5f);
  }
  node->fileName = name.c_str();  // reads the file
  if (const auto collider = node->collider()) {
    figment::Contact contact;
    collider->contact(figment::Vec3(0.0, 0.0, 0.0), 0.003, 0.1, contact);
  }
  SoGetBoundingBoxAction box(SbViewportRegion(64, 64));
  box.apply(node);
  node->unref();
  return 0;
}
