#include "TemporaryScript.h"

#include <unistd.h>  // getpid: temporary names of their own per process

#include <atomic>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "io/ProgressiveScript.h"
#include "sim/progressive/Decimation.h"

namespace figment::bench {

TriangleMesh asSceneHoldsIt(TriangleMesh mesh) {
  for (Vec3& x : mesh.vertices) x = x.cast<float>().cast<double>();
  return mesh;
}

TemporaryScript::TemporaryScript(const TriangleMesh& garment, double coarseShare) {
  static std::atomic<int> made{0};
  const int coarse = std::max(1, static_cast<int>(std::lround(coarseShare * garment.triangles.size())));
  const ProgressiveMesh progressive = decimate(garment, DecimationOptions{.targetFaces = coarse});
  levels_ = progressive.levels();
  coarseSections_ = MeshLevel(progressive).activeFaces();
  path_ = (std::filesystem::temp_directory_path() /
           ("figment-bench-" + std::to_string(::getpid()) + "-" + std::to_string(made++) + ".pm"))
              .string();
  writeProgressiveScript(progressive, path_);
}

TemporaryScript::~TemporaryScript() {
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

}  // namespace figment::bench
