#pragma once
// The faces of an Inventor coordIndex: runs of vertex indices, each ended by a negative
// index (-1 by convention) or by the end of the list. The one walk over a coordIndex
// that the cloth engine's input, the facet order and the clothing layer's normals share.

#include <cstdint>
#include <vector>

namespace figment::guard {

// One face: coordIndex[first, end) are its corners; when end < the list's length,
// coordIndex[end] is the negative index that ended it.
struct CoordIndexFace {
  int first;
  int end;
  int corners() const { return end - first; }
};

// Every face of `coordIndex` (`count` entries) in order, empty ones (two negatives in
// a row) included, so a caller can report a terminator it does not accept.
std::vector<CoordIndexFace> coordIndexFaces(const int32_t* coordIndex, int count);

// Whether every corner of `face` is a vertex of a list of `pointCount` points.
bool cornersBelow(const CoordIndexFace& face, const int32_t* coordIndex, int pointCount);

// Where in `coordIndex` (`count` entries) the first entry lies that is neither a vertex
// of a list of `pointCount` points nor the -1 that ends a face; -1 when there is none.
int firstBadIndex(const int32_t* coordIndex, int count, int pointCount);

}  // namespace figment::guard
