// The blend of MakeHuman's targets (sim/body/HumanModel.h) on a tiny literal base: offsets
// weighted, decimetres to metres, the lowest point on the floor.
#include <gtest/gtest.h>

#include <map>
#include <stdexcept>

#include "sim/body/HumanModel.h"

using namespace figment;

namespace {

// A triangle standing 10 dm tall on the file's vertices 1, 2, 3 (vertex 0 is helper geometry).
HumanBase tinyBase() {
  HumanBase base;
  base.skin.vertices = {Vec3(0, -5, 0), Vec3(1, -5, 0), Vec3(0, 5, 0)};
  base.skin.triangles = {{0, 1, 2}};
  base.fileIndex = {1, 2, 3};
  base.fileVertexCount = 4;
  return base;
}

}  // namespace

TEST(HumanModel, MeasureTargetsAddTheirOffsetsTimesTheirWeight) {
  std::map<std::string, MorphTarget> data;
  data["torso/measure-bust-circ-incr"] = {{3, 0}, {Vec3(2, 0, 0), Vec3(9, 9, 9)}};  // file 0: not skin
  data["torso/measure-bust-circ-decr"] = {{3}, {Vec3(-4, 0, 0)}};
  const HumanModel model(tinyBase(), [&](const std::string& name) -> const MorphTarget* {
    const auto it = data.find(name);
    return it == data.end() ? nullptr : &it->second;
  });
  HumanParameters p;
  p.measures["bust"] = 0.5;
  TriangleMesh body = model.make(p);
  // 0.1 m per unit; vertex 2 (file 3) moved 0.5 * 2 dm in x; the floor at y = 0
  EXPECT_NEAR(body.vertices[2].x(), 0.1, 1e-15);
  EXPECT_NEAR(body.vertices[2].y(), 1.0, 1e-15);
  EXPECT_NEAR(body.vertices[0].y(), 0.0, 1e-15);
  p.measures["bust"] = -0.25;  // the decr target, weight 0.25
  body = model.make(p);
  EXPECT_NEAR(body.vertices[2].x(), -0.1, 1e-15);
}

TEST(HumanModel, UnknownOrOutOfRangeMeasuresAreNamed) {
  const HumanModel model(tinyBase(), [](const std::string&) -> const MorphTarget* { return nullptr; });
  HumanParameters p;
  p.measures["wasit"] = 0.1;
  EXPECT_THROW(model.make(p), std::invalid_argument);
  p.measures.clear();
  p.measures["waist"] = 1.5;
  EXPECT_THROW(model.make(p), std::invalid_argument);
  p.measures["waist"] = 1.0;
  EXPECT_EQ(model.make(p).vertices.size(), 3u);  // a target the data lacks adds nothing
}

TEST(HumanModel, FileVerticesAreBlendedAndFlooredAsTheSkin) {
  std::map<std::string, MorphTarget> data;
  data["torso/measure-bust-circ-incr"] = {{3, 0}, {Vec3(2, 0, 0), Vec3(0, 4, 0)}};  // file 0: helper geometry
  HumanBase base = tinyBase();
  const TargetLookup lookup = [&](const std::string& name) -> const MorphTarget* {
    const auto it = data.find(name);
    return it == data.end() ? nullptr : &it->second;
  };
  EXPECT_THROW(HumanModel(base, lookup).fileVertices({}), std::logic_error);  // a base made without them
  base.fileVertices = {Vec3(0, 0, 0), Vec3(0, -5, 0), Vec3(1, -5, 0), Vec3(0, 5, 0)};
  const HumanModel model(base, lookup);
  HumanParameters p;
  p.measures["bust"] = 0.5;
  const std::vector<Vec3> all = model.fileVertices(p);
  const TriangleMesh skin = model.make(p);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(all[base.fileIndex[k]], skin.vertices[k]);  // the same to the bit
  EXPECT_NEAR(all[0].y(), 0.5 * 0.4 + 0.5, 1e-15);  // the helper moved too, on the skin's floor
}
