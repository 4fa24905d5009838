// MPFB2's rig JSON: { bone: { "parent": name|"", "head": place, "tail": place, ... } } with a
// place { "strategy": "CUBE", "cube_name": group } | { "strategy": "VERTEX",
// "vertex_index": i } | { "strategy": "MEAN", "vertex_indices": [i, ...] }; a vertex group
// is a list of inclusive [first, last] ranges. Weights: { "weights": { bone: [[i, w], ...] } }.

#include "io/MakeHumanRig.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace fs = std::filesystem;
using nlohmann::json;

namespace figment {

namespace {

json readJson(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot be opened");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

RigJointPlace placeOf(const json& place, const json& groups) {
  RigJointPlace out;
  const std::string strategy = place.at("strategy").get<std::string>();
  if (strategy == "VERTEX") {
    out.vertices.push_back(place.at("vertex_index").get<int>());
  } else if (strategy == "MEAN") {
    out.vertices = place.at("vertex_indices").get<std::vector<int>>();
  } else if (strategy == "CUBE") {
    for (const json& range : groups.at(place.at("cube_name").get<std::string>()))
      for (int v = range.at(0).get<int>(); v <= range.at(1).get<int>(); ++v) out.vertices.push_back(v);
  } else {
    throw std::runtime_error("unknown joint strategy '" + strategy + "'");
  }
  return out;
}

// The bones in an order with every parent before its children (depth first from the
// roots, each level by name as the file's object lists them).
std::vector<std::string> parentsFirst(const json& rig) {
  std::map<std::string, std::vector<std::string>> children;
  std::vector<std::string> order;
  for (const auto& [name, bone] : rig.items()) {
    const std::string parent = bone.value("parent", std::string());
    if (parent.empty())
      order.push_back(name);
    else
      children[parent].push_back(name);
  }
  for (size_t k = 0; k < order.size(); ++k)
    for (const std::string& child : children[order[k]]) order.push_back(child);
  if (order.size() != rig.size()) throw std::runtime_error("a bone's parent is missing or the bones form a cycle");
  return order;
}

std::vector<RigBone> bonesOf(const json& rig, const json& groups, const json& weights) {
  const std::vector<std::string> order = parentsFirst(rig);
  std::map<std::string, int> index;
  std::vector<RigBone> bones;
  for (const std::string& name : order) {
    const json& bone = rig.at(name);
    RigBone out;
    out.name = name;
    const std::string parent = bone.value("parent", std::string());
    out.parent = parent.empty() ? -1 : index.at(parent);
    out.head = placeOf(bone.at("head"), groups);
    out.tail = placeOf(bone.at("tail"), groups);
    if (weights.contains(name))
      for (const json& pair : weights.at(name))
        out.weights.push_back({pair.at(0).get<int>(), pair.at(1).get<double>()});
    index[name] = int(bones.size());
    bones.push_back(std::move(out));
  }
  return bones;
}

}  // namespace

HumanRig readHumanRig(const std::string& dir, int fileVertexCount) {
  const fs::path rigPath = fs::path(dir) / "rigs" / "standard" / "rig.default.json";
  const fs::path weightsPath = fs::path(dir) / "rigs" / "standard" / "weights.default.json";
  const fs::path groupsPath = fs::path(dir) / "mesh_metadata" / "basemesh_vertex_groups.json";
  const json rig = readJson(rigPath), weights = readJson(weightsPath), groups = readJson(groupsPath);
  try {
    return HumanRig(bonesOf(rig, groups, weights.at("weights")), fileVertexCount);
  } catch (const std::exception& e) {  // json's out_of_range and type errors, the rig's checks
    throw std::runtime_error(rigPath.string() + ": " + e.what());
  }
}

}  // namespace figment
