// The rig's joints placed as MakeHuman places them: from the vertices of the body as
// morphed, so a taller body's knees are higher and a heavier one's shoulders wider.

#include "sim/body/HumanRig.h"

#include <cmath>
#include <stdexcept>

namespace figment {

namespace {

void checkPlace(const RigJointPlace& place, const std::string& bone, int count) {
  if (place.vertices.empty()) throw std::invalid_argument("rig: bone " + bone + " has a joint with no vertex");
  for (int v : place.vertices)
    if (v < 0 || v >= count)
      throw std::invalid_argument("rig: bone " + bone + " names vertex " + std::to_string(v) + ", outside the mesh's " +
                                  std::to_string(count));
}

Vec3 meanOf(const RigJointPlace& place, const std::vector<Vec3>& vertices) {
  Vec3 sum = Vec3::Zero();
  for (int v : place.vertices) sum += vertices[v];
  return sum / double(place.vertices.size());
}

}  // namespace

HumanRig::HumanRig(std::vector<RigBone> bones, int fileVertexCount)
    : bones_(std::move(bones)), fileVertexCount_(fileVertexCount) {
  for (size_t b = 0; b < bones_.size(); ++b) {
    const RigBone& bone = bones_[b];
    if (bone.parent >= int(b)) throw std::invalid_argument("rig: bone " + bone.name + " comes before its parent");
    checkPlace(bone.head, bone.name, fileVertexCount);
    checkPlace(bone.tail, bone.name, fileVertexCount);
    for (const auto& [vertex, weight] : bone.weights)
      if (vertex < 0 || vertex >= fileVertexCount || !std::isfinite(weight))
        throw std::invalid_argument("rig: bone " + bone.name + " has a bad weight on vertex " + std::to_string(vertex));
  }
}

int HumanRig::find(const std::string& name) const {
  for (size_t b = 0; b < bones_.size(); ++b)
    if (bones_[b].name == name) return int(b);
  return -1;
}

int HumanRig::require(const std::string& name) const {
  const int b = find(name);
  if (b < 0) throw std::invalid_argument("no bone '" + name + "'");
  return b;
}

std::vector<PlacedBone> HumanRig::place(const std::vector<Vec3>& fileVertices) const {
  if (int(fileVertices.size()) != fileVertexCount_)
    throw std::invalid_argument("rig: " + std::to_string(fileVertices.size()) + " vertices for a rig over " +
                                std::to_string(fileVertexCount_));
  std::vector<PlacedBone> placed;
  placed.reserve(bones_.size());
  for (const RigBone& bone : bones_)
    placed.push_back({meanOf(bone.head, fileVertices), meanOf(bone.tail, fileVertices)});
  return placed;
}

}  // namespace figment
