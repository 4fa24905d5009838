#include "nodes/body/SkeletonJoints.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "nodes/NodeSource.h"
#include "sim/body/Skeleton.h"

FIGMENT_NODE_SOURCE(SkeletonJoints, SoNode, "Node")

SkeletonJoints::SkeletonJoints() {
  SO_NODE_CONSTRUCTOR(SkeletonJoints);
  SO_NODE_ADD_EMPTY_MFIELD(names);
  SO_NODE_ADD_EMPTY_MFIELD(positions);
}

SkeletonJoints::~SkeletonJoints() = default;

figment::Skeleton SkeletonJoints::skeleton() const {
  const auto& known = figment::humanoidJointNames();
  if (names.getNum() != positions.getNum())
    throw std::invalid_argument("SkeletonJoints: " + std::to_string(names.getNum()) + " names but " +
                                std::to_string(positions.getNum()) + " positions");
  std::vector<figment::Vec3> ordered(known.size());
  std::vector<bool> seen(known.size(), false);
  for (int i = 0; i < names.getNum(); ++i) {
    const std::string name = names[i].getString();
    const auto it = std::find(known.begin(), known.end(), name);
    if (it == known.end())
      throw std::invalid_argument("SkeletonJoints: names[" + std::to_string(i) + "] = \"" + name +
                                  "\" is not a joint of the humanoid skeleton");
    const size_t k = it - known.begin();
    if (seen[k])
      throw std::invalid_argument("SkeletonJoints: names[" + std::to_string(i) + "] = \"" + name + "\" repeats");
    seen[k] = true;
    const SbVec3f& p = positions[i];
    ordered[k] = figment::Vec3(p[0], p[1], p[2]);
  }
  for (size_t k = 0; k < known.size(); ++k)
    if (!seen[k]) throw std::invalid_argument("SkeletonJoints: names has no \"" + known[k] + "\"");
  return figment::humanoidSkeleton(ordered);
}

void SkeletonJoints::setSkeleton(const figment::Skeleton& skeleton) {
  const bool notifying = enableNotify(FALSE);
  names.setNum(0);
  positions.setNum(0);
  for (size_t i = 0; i < skeleton.joints.size(); ++i) {
    const figment::Vec3& p = skeleton.joints[i].position;
    names.set1Value(int(i), skeleton.joints[i].name.c_str());
    positions.set1Value(int(i), SbVec3f(float(p.x()), float(p.y()), float(p.z())));
  }
  enableNotify(notifying);
  touch();
}
