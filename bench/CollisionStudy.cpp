#include "CollisionStudy.h"

#include "Statistics.h"
#include "io/MeshImport.h"
#include "sim/BodyParts.h"
#include "sim/CapsuleFit.h"
#include "sim/MeshCollider.h"
#include "sim/SkeletonEstimate.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>

namespace figment::bench {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Row {
  double meanGap = 0.0, maxGap = 0.0, enclosed = 0.0, queryNs = 0.0, fitSeconds = 0.0;
};

// Gap (one-sided, from the body): each vertex's distance to the volume's surface, and
// the share of vertices inside or on it.
template <typename Volume>
void measureGaps(const Volume& volume, const std::vector<Vec3>& vertices, Row& row) {
  int inside = 0;
  for (const Vec3& v : vertices) {
    const SurfacePoint s = volume.nearest(v);
    const double gap = std::abs(s.distance);
    row.meanGap += gap, row.maxGap = std::max(row.maxGap, gap);
    inside += s.distance <= 1e-9;  // nearest() signs the distance by the inside test
  }
  row.meanGap /= static_cast<double>(vertices.size());
  row.enclosed = 100.0 * inside / static_cast<double>(vertices.size());
}

// Points around a part, where cloth nodes meet it: its vertices moved up to 1 cm on each
// axis (seeded).
std::vector<Vec3> queryPoints(const std::vector<Vec3>& vertices) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> offset(-0.01, 0.01);
  std::vector<Vec3> points;
  for (int i = 0; i < 2000; ++i)
    points.push_back(vertices[i % vertices.size()] + Vec3(offset(random), offset(random), offset(random)));
  return points;
}

template <typename Query>
double nanosecondsPerQuery(const std::vector<Vec3>& points, Query query) {
  double sink = 0.0;
  const auto start = Clock::now();
  for (const Vec3& p : points) sink += query(p);
  const double ns = 1e9 * secondsSince(start) / static_cast<double>(points.size());
  volatile double keep = sink;  // the queries' results are used: the compiler keeps them
  (void)keep;
  return ns;
}

int collisionStudy(const CollisionStudyOptions& options);

}  // namespace

int runCollisionStudy(const CollisionStudyOptions& options) {
  try {
    return collisionStudy(options);
  } catch (const std::exception& e) {  // a body that is no standing humanoid, say
    std::cerr << "figment-bench: " << options.body << ": " << e.what() << "\n";
    return 1;
  }
}

namespace {
int collisionStudy(const CollisionStudyOptions& options) {
  const std::string path = findModelFile(options.body);
  if (path.empty()) {
    std::cerr << "figment-bench: " << options.body << ": not found\n";
    return 1;
  }
  ImportOptions import;
  import.exclude = {"human-highpolyeyesMesh"};
  const TriangleMesh body = importMesh(path, import).mesh;
  const Skeleton skeleton = estimateSkeleton(body);
  const std::vector<PartMesh> parts = splitIntoParts(body, skeleton);

  std::filesystem::create_directories(options.outDir);
  const std::string csvPath = options.outDir + "/collision.csv";
  std::ofstream csv(csvPath + ".partial");
  csv << "part,method,mean_gap_mm,max_gap_mm,enclosed_pct,query_ns,fit_s,vertices\n";
  std::vector<double> capsuleGap, radialGap, capsuleNs, radialNs, exactNs;
  for (const PartMesh& part : parts) {
    const std::vector<Vec3>& vertices = part.mesh.vertices;
    const std::vector<Vec3> points = queryPoints(vertices);
    // Capsule: the genetic fit on at most 600 of the vertices (every k-th), enclosure on all.
    std::vector<Vec3> sample;
    const size_t every = std::max<size_t>(1, vertices.size() / 600);
    for (size_t i = 0; i < vertices.size(); i += every) sample.push_back(vertices[i]);
    Row capsuleRow;
    auto start = Clock::now();
    CapsuleFitOptions fitOptions;
    fitOptions.enclose = false;
    CapsuleParameters grown = fitCapsule(sample, fitOptions).parameters;
    growToEnclose(grown, vertices);
    const Capsule capsule(grown);
    capsuleRow.fitSeconds = secondsSince(start);
    measureGaps(capsule, vertices, capsuleRow);
    // A query as a cloth node makes it: the fast path (CapsuleCollider).
    capsuleRow.queryNs = nanosecondsPerQuery(points, [&](const Vec3& p) { return capsule.nearestFast(p).distance; });

    Row radialRow;
    start = Clock::now();
    const RadialDepthVolume radial = fitRadialPart(part, options.harmonics, options.sectionSpacing);
    radialRow.fitSeconds = secondsSince(start);
    measureGaps(radial, vertices, radialRow);
    radialRow.queryNs = nanosecondsPerQuery(points, [&](const Vec3& p) { return radial.nearestFast(p).distance; });

    Row exactRow;
    start = Clock::now();
    const MeshCollider exact(part.mesh);
    exactRow.fitSeconds = secondsSince(start);
    exactRow.enclosed = 100.0;
    const double inf = std::numeric_limits<double>::infinity();
    exactRow.queryNs = nanosecondsPerQuery(points, [&](const Vec3& p) {
      Contact c;
      exact.contact(p, 0.0, inf, c);
      return c.distance;
    });

    for (const auto& [method, row] : {std::pair<const char*, const Row&>{"capsule", capsuleRow},
                                      {"radial", radialRow}, {"exact", exactRow}}) {
      char line[256];
      std::snprintf(line, sizeof line, "%s,%s,%.3f,%.3f,%.2f,%.0f,%.3f,%zu\n", part.name.c_str(), method,
                    1000 * row.meanGap, 1000 * row.maxGap, row.enclosed, row.queryNs, row.fitSeconds, vertices.size());
      csv << line;
    }
    std::printf("%-11s %5zu vertices  capsule gap %5.1f mm (max %5.1f) %4.0f ns  radial gap %5.1f mm (max %5.1f) "
                "%5.0f ns  exact %6.0f ns\n",
                part.name.c_str(), vertices.size(), 1000 * capsuleRow.meanGap, 1000 * capsuleRow.maxGap,
                capsuleRow.queryNs, 1000 * radialRow.meanGap, 1000 * radialRow.maxGap, radialRow.queryNs,
                exactRow.queryNs);
    capsuleGap.push_back(1000 * capsuleRow.meanGap), radialGap.push_back(1000 * radialRow.meanGap);
    capsuleNs.push_back(capsuleRow.queryNs), radialNs.push_back(radialRow.queryNs), exactNs.push_back(exactRow.queryNs);
  }
  csv.close();
  std::filesystem::rename(csvPath + ".partial", csvPath);
  std::printf("medians over parts: mean gap capsule %.1f mm, radial %.1f mm (K = %d); query capsule %.0f ns, "
              "radial %.0f ns, exact %.0f ns\n",
              median(capsuleGap), median(radialGap), options.harmonics, median(capsuleNs), median(radialNs),
              median(exactNs));
  std::cout << csvPath << "\n";
  if (!options.plotScript.empty() && std::filesystem::exists(options.plotScript)) {
    const std::string png = options.outDir + "/collision.png";
    const std::string command = "/usr/bin/python3 '" + options.plotScript + "' '" + csvPath + "' '" + png + "'";
    if (std::system(command.c_str()) == 0) std::cout << png << "\n";
  }
  return 0;
}

}  // namespace

}  // namespace figment::bench
