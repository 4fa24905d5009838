// MakeHuman's body blended from its targets: x = base + sum_t w_t * offsets_t (the targets
// are sparse, so the cost is their entries, not the mesh), then scaled to metres and set on
// the floor.

#include "sim/body/HumanModel.h"

#include <cmath>
#include <stdexcept>

namespace figment {

const std::vector<MeasureTargetName>& measureTargetNames() {
  static const std::vector<MeasureTargetName> names = {
      {"bust", "torso/measure-bust-circ"},
      {"underbust", "torso/measure-underbust-circ"},
      {"waist", "torso/measure-waist-circ"},
      {"hips", "torso/measure-hips-circ"},
      {"neck", "neck/measure-neck-circ"},
      {"shoulder", "torso/measure-shoulder-dist"},
      {"upperarm", "arms/measure-upperarm-circ"},
      {"thigh", "legs/measure-thigh-circ"},
      {"upperarm_length", "arms/measure-upperarm-length"},
      {"lowerarm_length", "arms/measure-lowerarm-length"},
      {"upperleg_height", "legs/measure-upperleg-height"},
      {"lowerleg_height", "legs/measure-lowerleg-height"},
      {"frontchest", "torso/measure-frontchest-dist"},
      {"napetowaist", "torso/measure-napetowaist-dist"},
      {"waisttohip", "torso/measure-waisttohip-dist"},
      {"neck_height", "neck/measure-neck-height"},
      // not measure targets but shaped the same (an -incr and a -decr): what a measured body
      // goes on with past a girth's target (sim/body/MeasuredBody.cpp, issue 43)
      {"stomach", "stomach/stomach-pregnant"},
      {"buttocks", "buttocks/buttocks-volume"},
  };
  return names;
}

HumanModel::HumanModel(HumanBase base, TargetLookup lookup) : base_(std::move(base)), lookup_(std::move(lookup)) {
  skinIndex_.assign(base_.fileVertexCount, -1);
  for (size_t i = 0; i < base_.fileIndex.size(); ++i) skinIndex_.at(base_.fileIndex[i]) = int(i);
}

std::vector<WeightedTarget> HumanModel::targets(const HumanParameters& p) const {
  std::vector<WeightedTarget> all = macroTargets(p.macro);
  for (const auto& [key, value] : p.measures) {
    const MeasureTargetName* known = nullptr;
    for (const MeasureTargetName& name : measureTargetNames())
      if (key == name.key) known = &name;
    if (!known) throw std::invalid_argument("no measure target '" + key + "'");
    if (!(value >= -1.0 && value <= 1.0))
      throw std::invalid_argument("measure " + key + " = " + std::to_string(value) + " is outside [-1, 1]");
    if (value != 0) all.push_back({std::string(known->stem) + (value > 0 ? "-incr" : "-decr"), std::abs(value)});
  }
  return all;
}

TriangleMesh HumanModel::make(const HumanParameters& p) const {
  TriangleMesh body = base_.skin;
  for (const WeightedTarget& t : targets(p)) {
    const MorphTarget* target = lookup_(t.name);
    if (!target) continue;
    for (size_t k = 0; k < target->vertices.size(); ++k) {
      const int file = target->vertices[k];
      const int skin = file >= 0 && file < int(skinIndex_.size()) ? skinIndex_[file] : -1;
      if (skin >= 0) body.vertices[skin] += t.weight * target->offsets[k];
    }
  }
  double floor = std::numeric_limits<double>::infinity();
  for (Vec3& v : body.vertices) {
    v *= base_.metresPerUnit;
    floor = std::min(floor, v.y());
  }
  for (Vec3& v : body.vertices) v.y() -= floor;
  return body;
}

std::vector<Vec3> HumanModel::fileVertices(const HumanParameters& p) const {
  if (int(base_.fileVertices.size()) != base_.fileVertexCount)
    throw std::logic_error("HumanModel: the base has no file vertices to place a rig from");
  std::vector<Vec3> all = base_.fileVertices;
  for (const WeightedTarget& t : targets(p)) {
    const MorphTarget* target = lookup_(t.name);
    if (!target) continue;
    for (size_t k = 0; k < target->vertices.size(); ++k) {
      const int file = target->vertices[k];
      if (file >= 0 && file < int(all.size())) all[file] += t.weight * target->offsets[k];
    }
  }
  // The same arithmetic as make() on the skin's vertices, so the same floor to the bit.
  double floor = std::numeric_limits<double>::infinity();
  for (Vec3& v : all) v *= base_.metresPerUnit;
  for (int file : base_.fileIndex) floor = std::min(floor, all[file].y());
  for (Vec3& v : all) v.y() -= floor;
  return all;
}

}  // namespace figment
