#pragma once
// Bodies built from boxes for the tests of body slicing and garment generation: shapes whose
// sections, landmarks and distances are known exactly.

#include <algorithm>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment::mannequin {

struct Box {
  Vec3 min, max;
  // Distance from p to the box: 0 inside.
  double distance(const Vec3& p) const { return (min - p).cwiseMax(p - max).cwiseMax(0.0).norm(); }
  bool contains(const Vec3& p) const { return (p.array() >= min.array()).all() && (p.array() <= max.array()).all(); }
};

// Appends a closed box, counter-clockwise seen from outside, four vertices per face (like a
// mesh split along texture seams): face quad o, o + u, o + u + v, o + v with u x v outward.
inline void appendBox(TriangleMesh& mesh, const Box& box) {
  const Vec3 d = box.max - box.min;
  const Vec3 x(d.x(), 0, 0), y(0, d.y(), 0), z(0, 0, d.z());
  const Vec3& o = box.min;
  const Vec3 faces[6][3] = {{o, z, y}, {o + x, y, z}, {o, x, z}, {o + y, z, x}, {o, y, x}, {o + z, x, y}};
  for (const auto& [origin, u, v] : faces) {
    const int first = static_cast<int>(mesh.vertices.size());
    for (const Vec3& corner : {origin, Vec3(origin + u), Vec3(origin + u + v), Vec3(origin + v)})
      mesh.vertices.push_back(corner);
    mesh.triangles.push_back({first, first + 1, first + 2});
    mesh.triangles.push_back({first, first + 2, first + 3});
  }
}

inline TriangleMesh boxMesh(const Box& box) {
  TriangleMesh mesh;
  appendBox(mesh, box);
  return mesh;
}

// A standing figure 1.75 m tall, y up, facing +z, symmetric in x, arms hanging apart from the
// torso and joined to it by a shoulder bar: legs up to 0.85 m, torso 0.8-1.45 m (|x| <= 0.16),
// shoulders 1.3-1.45 m (|x| <= 0.3), arms 0.85-1.45 m at |x| 0.24-0.3 (8 cm from the torso),
// neck 1.45-1.55 m (|x| <= 0.05), head 1.55-1.75 m (|x| <= 0.09). The boxes overlap; the
// surface is their union's outline plus inner faces, which sections and hulls do not mind.
inline std::vector<Box> figureBoxes() {
  std::vector<Box> boxes = {
      {{0.02, 0.0, -0.07}, {0.14, 0.85, 0.07}},    // right leg
      {{-0.14, 0.0, -0.07}, {-0.02, 0.85, 0.07}},  // left leg
      {{-0.16, 0.8, -0.1}, {0.16, 1.45, 0.1}},     // torso
      {{-0.3, 1.3, -0.08}, {0.3, 1.45, 0.08}},     // shoulders
      {{0.24, 0.85, -0.05}, {0.3, 1.45, 0.05}},    // right arm
      {{-0.3, 0.85, -0.05}, {-0.24, 1.45, 0.05}},  // left arm
      {{-0.05, 1.45, -0.05}, {0.05, 1.55, 0.05}},  // neck
      {{-0.09, 1.55, -0.1}, {0.09, 1.75, 0.1}},    // head
  };
  return boxes;
}

inline TriangleMesh figure() {
  TriangleMesh mesh;
  for (const Box& box : figureBoxes()) appendBox(mesh, box);
  return mesh;
}

// The fewest boxes that stand as sim/body/BodyStance reads a standing body, 1.75 m tall along
// +y: two narrow legs 20 cm apart (each foot's corners within 4 % of the stature of each other, the
// feet farther apart) under a torso, and a head narrower than that gap at the top.
inline TriangleMesh stanceFigure() {
  TriangleMesh mesh;
  for (const Box& box : {Box{{-0.15, 0.0, -0.03}, {-0.1, 0.8, 0.03}}, Box{{0.1, 0.0, -0.03}, {0.15, 0.8, 0.03}},
                         Box{{-0.2, 0.8, -0.1}, {0.2, 1.5, 0.1}}, Box{{-0.03, 1.5, -0.03}, {0.03, 1.75, 0.03}}})
    appendBox(mesh, box);
  return mesh;
}

// Distance from p to the figure, 0 inside it.
inline double distanceToFigure(const Vec3& p) {
  double nearest = 1e9;
  for (const Box& box : figureBoxes()) nearest = std::min(nearest, box.distance(p));
  return nearest;
}

}  // namespace figment::mannequin
