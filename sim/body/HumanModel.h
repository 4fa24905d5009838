#pragma once
// MakeHuman's body (MPFB2's hm08 base mesh, CC0) made from its macro parameters and its
// measure targets: the skin only, triangulated, in metres, y up, feet on the floor. The
// data is read by io/MakeHumanFiles.h; this is the blend, Eigen only.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "sim/body/MacroBlend.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

// A morph target: offsets (in the base mesh's unit) of some of its vertices.
struct MorphTarget {
  std::vector<int> vertices;  // indices into the base mesh file's vertex list
  std::vector<Vec3> offsets;
};

// The base mesh's skin: its vertices (the file's unit), its triangles, and the index in
// the file's vertex list of each vertex (the numbering targets use).
struct HumanBase {
  TriangleMesh skin;
  std::vector<int> fileIndex;
  int fileVertexCount = 0;
  // Every vertex of the file (the skin, the helper geometry and the joint cubes), the
  // file's unit: where the rig's joints are placed from (sim/body/HumanRig.h). May be
  // empty (a base made in code); fileVertices() then throws.
  std::vector<Vec3> fileVertices;
  double metresPerUnit = 0.1;  // MakeHuman models in decimetres
};

// MakeHuman's measure targets as scalar parameters in [-1, 1]: +1 applies the "-incr"
// target fully, -1 the "-decr" one, 0 neither. By key, in this order.
struct MeasureTargetName {
  const char* key;   // e.g. "bust"
  const char* stem;  // under targets/, e.g. "torso/measure-bust-circ"
};
const std::vector<MeasureTargetName>& measureTargetNames();

struct HumanParameters {
  MacroParameters macro;
  std::map<std::string, double> measures;  // key (measureTargetNames) -> [-1, 1]; absent = 0
};

// Finds a target by name (a path under targets/ without ".target.gz"); null when the data
// has none. Kept by the model, so whatever it refers to must outlive it.
using TargetLookup = std::function<const MorphTarget*(const std::string& name)>;

class HumanModel {
 public:
  HumanModel(HumanBase base, TargetLookup lookup);

  // Every target `p` blends and its weight: the macro ones, then the measure ones.
  // Throws std::invalid_argument naming a parameter out of range or an unknown measure key.
  std::vector<WeightedTarget> targets(const HumanParameters& p) const;
  // The body: metres, y up, its lowest point on y = 0, as symmetric about x = 0 as the base.
  // Throws as targets().
  TriangleMesh make(const HumanParameters& p) const;
  // Every file vertex blended as make() blends the skin, in the same frame (metres, y up,
  // moved by make()'s floor): what the rig's joints follow. Throws as targets(), and
  // std::logic_error when the base has no fileVertices.
  std::vector<Vec3> fileVertices(const HumanParameters& p) const;
  const HumanBase& base() const { return base_; }

 private:
  HumanBase base_;
  TargetLookup lookup_;
  std::vector<int> skinIndex_;  // file vertex -> skin vertex, -1 when not in the skin
};

}  // namespace figment
