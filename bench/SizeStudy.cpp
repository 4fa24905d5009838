#include "SizeStudy.h"

#include "CsvFile.h"
#include "MethodSpec.h"
#include "SceneGarment.h"

#include "io/ProgressiveScript.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "sim/progressive/Decimation.h"
#include "sim/progressive/Resampling.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include <unistd.h>  // getpid: one temporary script per process

namespace figment::bench {

namespace {

// The garment as the engine holds it (floats), so its script's hash matches.
TriangleMesh asFloats(TriangleMesh mesh) {
  for (Vec3& x : mesh.vertices) x = x.cast<float>().cast<double>();
  return mesh;
}

struct SizedGarment {
  TriangleMesh mesh;
  std::string script;  // its progressive script, a temporary file
  int coarseSections = 0, levels = 0;
  double preparation = 0.0;  // s to resample and decimate
};

SizedGarment prepare(const TriangleMesh& base, int sections, const SizeStudyOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SizedGarment out;
  out.mesh = asFloats(resampled(base, sections));
  const int coarse = std::max(1, static_cast<int>(std::lround(options.coarseShare * out.mesh.triangles.size())));
  const ProgressiveMesh progressive = decimate(out.mesh, DecimationOptions{.targetFaces = coarse});
  out.levels = progressive.levels();
  out.coarseSections = MeshLevel(progressive).activeFaces();
  out.script = (std::filesystem::temp_directory_path() /
                ("figment-sizes-" + std::to_string(sections) + "-" + std::to_string(::getpid()) + ".pm"))
                   .string();
  writeProgressiveScript(progressive, out.script);
  out.preparation = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

// Mean and largest distance between two drapes, % of `height`.
std::pair<double, double> deviation(const std::vector<SbVec3f>& a, const std::vector<SbVec3f>& b, double height) {
  double mean = 0.0, largest = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    const double d = (a[i] - b[i]).length();
    mean += d, largest = std::max(largest, d);
  }
  mean /= static_cast<double>(a.size());
  return {100.0 * mean / height, 100.0 * largest / height};
}

// One size: the full garment, then the progressive drape; "" or the error.
std::string studySize(SceneGarment& garment, const TriangleMesh& base, int sections, const SizeStudyOptions& options,
                      std::ostream& csv) {
  const SizedGarment sized = prepare(base, sections, options);
  garment.replaceGarment(sized.mesh);
  ClothEngine& engine = *garment.engine;
  engine.progressiveScript = "";
  const RepeatedDrape full = garment.drapeRepeatedly(options.repeat);
  const double rate = sized.levels / options.splitTime;
  engine.progressiveScript = sized.script.c_str();
  engine.beginLevel = 0;
  engine.endLevel = -1;
  engine.splitRate = rate;
  const RepeatedDrape progressive = garment.drapeRepeatedly(options.repeat);
  std::filesystem::remove(sized.script);
  const int triangles = static_cast<int>(sized.mesh.triangles.size());
  const std::string failure = !full.error.empty() ? "full: " + full.error
                              : !progressive.error.empty() ? "progressive: " + progressive.error : "";
  if (!failure.empty()) {
    std::printf("%6d sections: failed: %s\n", triangles, failure.c_str());
    csv << triangles << ',' << sized.mesh.vertices.size() << ',' << options.method << ",,,,,,,,,,,,,\"" << failure
        << "\"\n";
    return "";
  }
  const auto [mean, largest] = deviation(progressive.positions, full.positions, garment.height());
  const double speedUp = full.medianWall / progressive.medianWall;
  std::printf("%6d sections (%5d nodes): full %4d steps %8.3f s %-6s | from %5d: %4d steps %8.3f s %-6s %5.2fx "
              "dev mean %6.3f %% max %6.3f %% (prepared in %.2f s)\n",
              triangles, static_cast<int>(sized.mesh.vertices.size()), full.run.iterations, full.medianWall,
              full.run.atRest ? "rest" : "moving", sized.coarseSections, progressive.run.iterations,
              progressive.medianWall, progressive.run.atRest ? "rest" : "moving", speedUp, mean, largest,
              sized.preparation);
  std::fflush(stdout);
  csv << triangles << ',' << sized.mesh.vertices.size() << ',' << options.method << ',' << sized.coarseSections << ','
      << sized.levels << ',' << rate << ',' << full.run.iterations << ',' << full.medianWall << ','
      << (full.run.atRest ? 1 : 0) << ',' << progressive.run.iterations << ',' << progressive.medianWall << ','
      << (progressive.run.atRest ? 1 : 0) << ',' << speedUp << ',' << mean << ',' << largest << ",\n";
  return "";
}

}  // namespace

int runSizeStudy(const SizeStudyOptions& options) {
  Method method;
  try {
    method = parseMethod(options.method);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "figment-bench: %s\n", e.what());
    return 2;
  }
  SceneGarment garment;
  std::string error;
  if (!garment.load(options.scene, error)) {
    std::fprintf(stderr, "figment-bench: %s\n", error.c_str());
    return 1;
  }
  if (error = configure(*garment.engine, method); !error.empty()) {
    std::fprintf(stderr, "figment-bench: %s\n", error.c_str());
    return 1;
  }
  const TriangleMesh base = garmentFromFields(garment.engine->restPoints, garment.engine->coordIndex);
  std::filesystem::create_directories(options.outDir);
  const bool written = writeCsv(options.outDir + "/sizes.csv", [&](std::ostream& csv) -> std::string {
    csv << "sections,nodes,method,coarse_sections,levels,split_rate_per_s,full_steps,full_median_wall_s,full_at_rest,"
           "steps,median_wall_s,at_rest,speed_up,mean_dev_pct_height,max_dev_pct_height,failure\n";
    for (int sections : options.sizes)
      if (std::string e = studySize(garment, base, sections, options, csv); !e.empty()) return e;
    return "";
  });
  if (!written) return 1;
  if (!options.plotScript.empty() && std::filesystem::exists(options.plotScript)) {
    const std::string png = options.outDir + "/sizes.png";
    const std::string command =
        "/usr/bin/python3 '" + options.plotScript + "' '" + options.outDir + "/sizes.csv' '" + png + "'";
    if (std::system(command.c_str()) == 0) std::printf("%s\n", png.c_str());
    else std::fprintf(stderr, "figment-bench: no chart (needs /usr/bin/python3 with matplotlib)\n");
  }
  return 0;
}

}  // namespace figment::bench
