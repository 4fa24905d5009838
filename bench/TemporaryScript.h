#pragma once
// A garment's progressive mesh (its reconstruction script) made on the fly for a study,
// in a temporary file that goes when the object does: for garments with no committed
// script (the T-shirt) and for the garment-size study's resampled garments.

#include <string>

#include "sim/core/TriangleMesh.h"

namespace figment::bench {

class TemporaryScript {
 public:
  // Decimates `garment` (as a scene holds it: float coordinates) to `coarseShare` of its
  // sections and writes the splits. Throws std::runtime_error when the file cannot be written.
  TemporaryScript(const TriangleMesh& garment, double coarseShare);
  ~TemporaryScript();
  TemporaryScript(const TemporaryScript&) = delete;
  TemporaryScript& operator=(const TemporaryScript&) = delete;

  const std::string& path() const { return path_; }
  int levels() const { return levels_; }
  int coarseSections() const { return coarseSections_; }

 private:
  std::string path_;
  int levels_ = 0, coarseSections_ = 0;
};

// The mesh with its coordinates rounded to floats, as a scene's fields hold them (a
// script's hash is of those).
TriangleMesh asSceneHoldsIt(TriangleMesh mesh);

}  // namespace figment::bench
