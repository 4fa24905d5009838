#pragma once
// A garment's rest (unstressed) shape: its triangles and, for each, its three corners at
// rest. What the cloth model's sections, bending joints, masses and edge stretch are
// measured against.
//
// Two kinds:
//  - a mesh: the garment was made in one piece and its vertices are its rest shape (every
//    garment of the generators and of a file); joints rest at the mesh's dihedral angles;
//  - flat pieces: a sewn garment, whose rest shape is its flat panels. No one placement of
//    its nodes holds it (a dart's apex, two panels' curves sewn together), so each
//    triangle keeps its own corners, in its panel's plane, and every joint rests flat.

#include <array>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

class RestShape {
 public:
  // The mesh's own shape (not checked here: ClothModel checks the garment first).
  explicit RestShape(const TriangleMesh& mesh);
  RestShape() = default;  // no triangles, no nodes
  // Flat pieces: corners[t] are triangle t's corners at rest (m), each triangle's in its
  // piece's plane (z = 0 when given 2-D coordinates); nodeCount nodes in all. Throws
  // std::invalid_argument when the counts disagree or an index is out of range.
  static RestShape flatPieces(std::vector<Triangle> triangles, std::vector<std::array<Vec3, 3>> corners,
                              size_t nodeCount);

  const std::vector<Triangle>& triangles() const { return triangles_; }
  const std::array<Vec3, 3>& corners(size_t triangle) const { return corners_[triangle]; }
  size_t nodeCount() const { return nodeCount_; }
  // The mesh, when the shape is one (else null): joints and edges then rest as it has them.
  const TriangleMesh* mesh() const { return fromMesh_ ? &mesh_ : nullptr; }

  // A joint's four corners at rest: shared edge (e0, e1) and the opposite corners of the
  // sections on either side. From the mesh for a mesh; for flat pieces the two sections
  // unfolded into one plane about their shared edge (each with its own edge length), so
  // the joint rests flat whatever panels the two sections came from.
  // Corners (e0, e1, o2, o3): sectionA = (e0, e1, o2), sectionB has e0, e1 and o3.
  std::array<Vec3, 4> hinge(int sectionA, int sectionB, const std::array<int, 4>& corners) const;
  // The corner of `section` that is node `node` (the node must be one of its corners).
  const Vec3& cornerAt(int section, int node) const;

 private:
  std::vector<Triangle> triangles_;
  std::vector<std::array<Vec3, 3>> corners_;
  size_t nodeCount_ = 0;
  bool fromMesh_ = false;
  TriangleMesh mesh_;  // for a mesh only
};

}  // namespace figment
