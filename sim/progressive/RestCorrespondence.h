#pragma once
// Drapes of one garment at two resolutions compared point by point: each vertex of one
// rest shape is found on the other rest shape (its closest point: a section and the
// barycentric weights there), and carried along when that one is draped. Resampling
// keeps a garment's surface (sim/progressive/Resampling.h), so the points lie on it to
// within the chords of the coarser one.

#include <array>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

class RestCorrespondence {
 public:
  // Every vertex of `from` on the surface of `onto` (both rest shapes).
  RestCorrespondence(const TriangleMesh& from, const TriangleMesh& onto);

  // `from`'s vertices where `onto`, draped to `ontoDraped`, carries them.
  std::vector<Vec3> carry(const std::vector<Vec3>& ontoDraped) const;

  // Largest distance of a `from` vertex from `onto`'s rest surface, m.
  double largestGap() const { return largestGap_; }

 private:
  std::vector<Triangle> corners_;               // per `from` vertex: the section of `onto`
  std::vector<std::array<double, 3>> weights_;  // and its barycentric weights
  double largestGap_ = 0.0;
};

}  // namespace figment
