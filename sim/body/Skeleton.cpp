#include "sim/body/Skeleton.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace figment {

int Skeleton::joint(const std::string& name) const {
  for (size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == name) return static_cast<int>(i);
  return -1;
}

const Joint& Skeleton::operator[](const std::string& name) const {
  const int i = joint(name);
  if (i < 0) throw std::invalid_argument("Skeleton: no joint named \"" + name + "\"");
  return joints[i];
}

const std::vector<std::string>& humanoidJointNames() {
  static const std::vector<std::string> names = {
      "pelvis",     "waist",         "chest",         "neckBase",   "neckTop",   "headTop", "hipL",
      "kneeL",      "ankleL",        "toeL",          "hipR",       "kneeR",     "ankleR",  "toeR",
      "shoulderL",  "elbowL",        "wristL",        "fingertipL", "shoulderR", "elbowR",  "wristR",
      "fingertipR", "shoulderBaseL", "shoulderBaseR", "pelvisFloor"};
  return names;
}

Skeleton humanoidSkeleton(const std::vector<Vec3>& positions) {
  const auto& names = humanoidJointNames();
  if (positions.size() != names.size())
    throw std::invalid_argument("a humanoid skeleton needs " + std::to_string(names.size()) + " joint positions, not " +
                                std::to_string(positions.size()));
  // Parents: the spine from the pelvis up; legs from the pelvis; arms from the chest.
  const std::vector<std::pair<std::string, std::string>> parent = {{"waist", "pelvis"},
                                                                   {"chest", "waist"},
                                                                   {"neckBase", "chest"},
                                                                   {"neckTop", "neckBase"},
                                                                   {"headTop", "neckTop"},
                                                                   {"hipL", "pelvis"},
                                                                   {"kneeL", "hipL"},
                                                                   {"ankleL", "kneeL"},
                                                                   {"toeL", "ankleL"},
                                                                   {"hipR", "pelvis"},
                                                                   {"kneeR", "hipR"},
                                                                   {"ankleR", "kneeR"},
                                                                   {"toeR", "ankleR"},
                                                                   {"shoulderBaseL", "chest"},
                                                                   {"shoulderL", "shoulderBaseL"},
                                                                   {"elbowL", "shoulderL"},
                                                                   {"wristL", "elbowL"},
                                                                   {"fingertipL", "wristL"},
                                                                   {"shoulderBaseR", "chest"},
                                                                   {"shoulderR", "shoulderBaseR"},
                                                                   {"elbowR", "shoulderR"},
                                                                   {"wristR", "elbowR"},
                                                                   {"fingertipR", "wristR"},
                                                                   {"pelvisFloor", "pelvis"}};
  Skeleton s;
  for (size_t i = 0; i < names.size(); ++i) s.joints.push_back({names[i], -1, positions[i]});
  for (const auto& [child, p] : parent) s.joints[s.joint(child)].parent = s.joint(p);
  const std::vector<std::array<std::string, 3>> parts = {
      {"head", "neckTop", "headTop"},   {"neck", "neckBase", "neckTop"},   {"upperTorso", "chest", "neckBase"},
      {"lowerTorso", "waist", "chest"}, {"hips", "pelvisFloor", "waist"},  {"upperArmL", "shoulderL", "elbowL"},
      {"forearmL", "elbowL", "wristL"}, {"handL", "wristL", "fingertipL"}, {"upperArmR", "shoulderR", "elbowR"},
      {"forearmR", "elbowR", "wristR"}, {"handR", "wristR", "fingertipR"}, {"thighL", "hipL", "kneeL"},
      {"shinL", "kneeL", "ankleL"},     {"footL", "ankleL", "toeL"},       {"thighR", "hipR", "kneeR"},
      {"shinR", "kneeR", "ankleR"},     {"footR", "ankleR", "toeR"}};
  for (const auto& [name, from, to] : parts) s.parts.push_back({name, s.joint(from), s.joint(to)});
  return s;
}

std::vector<int> assignParts(const Skeleton& skeleton, const std::vector<Vec3>& vertices) {
  std::vector<int> part(vertices.size(), -1);
  for (size_t v = 0; v < vertices.size(); ++v) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < skeleton.parts.size(); ++k) {
      const Vec3& a = skeleton.joints[skeleton.parts[k].from].position;
      const Vec3& b = skeleton.joints[skeleton.parts[k].to].position;
      const Vec3 ab = b - a;
      const double t = std::clamp((vertices[v] - a).dot(ab) / std::max(ab.squaredNorm(), 1e-18), 0.0, 1.0);
      const double d = (vertices[v] - (a + t * ab)).squaredNorm();
      if (d < best) best = d, part[v] = static_cast<int>(k);
    }
  }
  return part;
}

}  // namespace figment
