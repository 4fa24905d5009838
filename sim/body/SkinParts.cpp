#include "sim/body/SkinParts.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace figment {

namespace {

bool startsWithAny(const std::string& name, std::initializer_list<const char*> prefixes) {
  return std::any_of(prefixes.begin(), prefixes.end(), [&](const char* p) { return name.starts_with(p); });
}

}  // namespace

const std::vector<std::string>& skinPartNames() {
  static const std::vector<std::string> names = {"trunk",        "head",          "left upper arm", "right upper arm",
                                                 "left forearm", "right forearm", "left hand",      "right hand",
                                                 "left thigh",   "right thigh",   "left lower leg", "right lower leg",
                                                 "left foot",    "right foot"};
  return names;
}

int skinPartOfBone(const std::string& bone) {
  const int side = bone.ends_with(".R") ? 1 : 0;
  if (startsWithAny(bone, {"shoulder", "upperarm"})) return 2 + side;
  if (startsWithAny(bone, {"lowerarm"})) return 4 + side;
  if (startsWithAny(bone, {"wrist", "metacarpal", "finger"})) return 6 + side;
  if (startsWithAny(bone, {"upperleg"})) return 8 + side;
  if (startsWithAny(bone, {"lowerleg"})) return 10 + side;
  if (startsWithAny(bone, {"foot", "toe"})) return 12 + side;
  if (startsWithAny(bone, {"root", "spine", "pelvis", "breast", "clavicle"})) return 0;
  return 1;  // neck, head, jaw, eyes, tongue and the face's muscles
}

std::vector<int> skinTriangleParts(const HumanRig& rig, const HumanBase& base) {
  if (rig.fileVertexCount() != base.fileVertexCount)
    throw std::invalid_argument("skin parts: a rig over " + std::to_string(rig.fileVertexCount()) +
                                " vertices for a base of " + std::to_string(base.fileVertexCount));
  std::vector<double> heaviest(size_t(base.fileVertexCount), -1.0);
  std::vector<int> part(size_t(base.fileVertexCount), 0);
  for (const RigBone& bone : rig.bones()) {
    const int p = skinPartOfBone(bone.name);
    for (const auto& [vertex, weight] : bone.weights)
      if (weight > heaviest[size_t(vertex)]) heaviest[size_t(vertex)] = weight, part[size_t(vertex)] = p;
  }
  std::vector<int> out;
  out.reserve(base.skin.triangles.size());
  for (const Triangle& t : base.skin.triangles) {
    std::array<int, 3> p{};
    for (int k = 0; k < 3; ++k) p[size_t(k)] = part[size_t(base.fileIndex[size_t(t[k])])];
    std::sort(p.begin(), p.end());
    out.push_back(p[1] == p[0] || p[1] == p[2] ? p[1] : p[0]);  // the majority, else the lowest
  }
  return out;
}

}  // namespace figment
