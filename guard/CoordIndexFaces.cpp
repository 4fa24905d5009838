#include "guard/CoordIndexFaces.h"

namespace figment::guard {

std::vector<CoordIndexFace> coordIndexFaces(const int32_t* coordIndex, int count) {
  std::vector<CoordIndexFace> faces;
  int first = 0;
  while (first < count) {
    int end = first;
    while (end < count && coordIndex[end] >= 0) ++end;
    faces.push_back({first, end});
    first = end + 1;
  }
  return faces;
}

bool cornersBelow(const CoordIndexFace& face, const int32_t* coordIndex, int pointCount) {
  for (int k = face.first; k < face.end; ++k)
    if (coordIndex[k] >= pointCount) return false;
  return true;
}

int firstBadIndex(const int32_t* coordIndex, int count, int pointCount) {
  for (int k = 0; k < count; ++k)
    if (coordIndex[k] < -1 || coordIndex[k] >= pointCount) return k;
  return -1;
}

}  // namespace figment::guard
