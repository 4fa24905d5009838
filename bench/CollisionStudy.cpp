#include "CollisionStudy.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <variant>

#include "CsvFile.h"
#include "Statistics.h"
#include "io/AtomicFile.h"
#include "io/MeshImport.h"
#include "sim/body/BodyParts.h"
#include "sim/body/SkeletonEstimate.h"
#include "sim/collision/MeshCollider.h"
#include "sim/volumes/VolumeShaping.h"

namespace figment::bench {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Row {
  double meanGap = 0.0, maxGap = 0.0, enclosed = 0.0, queryNs = 0.0, fitSeconds = 0.0;
  int volumes = 0;
};

// One fitted volume ready for queries, with its bounding sphere.
struct Volume {
  std::variant<Capsule, RadialDepth> shape;
  Vec3 centre;
  double radius;
  explicit Volume(const CollisionVolumeParameters& v) : shape(makeShape(v)) {
    if (const Capsule* c = std::get_if<Capsule>(&shape)) {
      centre = c->fromUnit(Vec3::Zero());
      radius = 0.0;
      for (int corner = 0; corner < 8; ++corner) {
        const Vec3 u(corner & 1 ? 0.5 : -0.5, corner & 2 ? 0.5 : -0.5, corner & 4 ? 0.5 : -0.5);
        radius = std::max(radius, (c->fromUnit(u) - centre).norm());
      }
    } else {
      const RadialDepthParameters& p = std::get<RadialDepth>(shape).parameters();
      double widest = 0.0;
      for (const auto& section : p.coefficients) {
        double r = 0.0;
        for (double coefficient : section) r += std::abs(coefficient);
        widest = std::max(widest, r);
      }
      centre = p.base + 0.5 * p.length * p.direction;
      radius = std::hypot(0.5 * p.length, widest);
    }
  }
  static std::variant<Capsule, RadialDepth> makeShape(const CollisionVolumeParameters& v) {
    if (v.kind == CollisionVolumeParameters::Kind::Capsule) return Capsule(v.capsule);
    return RadialDepth(v.radial);
  }
  SurfacePoint nearest(const Vec3& p) const {
    return std::visit([&](const auto& s) { return s.nearest(p); }, shape);
  }
  bool contains(const Vec3& p) const {
    return std::visit([&](const auto& s) { return s.contains(p); }, shape);
  }
  SurfacePoint nearestFast(const Vec3& p) const {
    return std::visit([&](const auto& s) { return s.nearestFast(p); }, shape);
  }
};

// Gap (one-sided, from the body): for each vertex of the part, its depth in the deepest
// of the part's volumes that holds it (exact when one volume holds it; where volumes
// overlap, a lower bound of its distance to the union's surface), or, when none holds
// it, its distance to the nearest volume; and the share of vertices inside or on one.
void measureGaps(const std::vector<Volume>& volumes, const std::vector<Vec3>& vertices, Row& row) {
  int inside = 0;
  for (const Vec3& v : vertices) {
    double deepest = -1.0, nearestOutside = std::numeric_limits<double>::infinity();
    for (const Volume& volume : volumes) {
      const double d = volume.nearest(v).distance;  // signed by the inside test
      if (d <= 1e-9)
        deepest = std::max(deepest, -d);
      else
        nearestOutside = std::min(nearestOutside, d);
    }
    const double gap = deepest >= 0.0 ? deepest : nearestOutside;
    inside += deepest >= 0.0;
    row.meanGap += gap, row.maxGap = std::max(row.maxGap, gap);
  }
  row.meanGap /= static_cast<double>(vertices.size());
  row.enclosed = 100.0 * inside / static_cast<double>(vertices.size());
}

// One query as a cloth node makes it against a part (the deepest contact, as
// CompositeCollider reports it): when volumes hold the point, the fast nearest point
// (nearestFast: point, normal, signed distance) of those only (a volume that does not
// hold it cannot be deeper); else of each volume whose bounding sphere the point is not
// outside (CapsuleCollider's test); the smallest signed distance is the answer.
double queryVolumes(const std::vector<Volume>& volumes, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  bool held = false;
  for (const Volume& v : volumes)
    if (v.contains(p)) best = std::min(best, v.nearestFast(p).distance), held = true;
  if (held) return best;
  for (const Volume& v : volumes) {
    const double outside = (p - v.centre).norm() - v.radius;
    best = std::min(best, outside > 0.0 ? outside : v.nearestFast(p).distance);
  }
  return best;
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

// One part's rows: its capsules, its radial volume (or the capsules it fell back to),
// its own triangles.
struct PartRows {
  Row capsule, radial, exact;
  bool fellBack = false;  // the radial fit returned capsules
};

// The row of `fitted` (fitted in `fitSeconds`) for the part's `vertices`, queried at `points`.
Row fittedRow(const std::vector<CollisionVolumeParameters>& fitted, double fitSeconds,
              const std::vector<Vec3>& vertices, const std::vector<Vec3>& points) {
  Row row;
  row.fitSeconds = fitSeconds;
  const std::vector<Volume> volumes(fitted.begin(), fitted.end());
  row.volumes = static_cast<int>(fitted.size());
  measureGaps(volumes, vertices, row);
  row.queryNs = nanosecondsPerQuery(points, [&](const Vec3& p) { return queryVolumes(volumes, p); });
  return row;
}

Row exactRow(const PartMesh& part, const std::vector<Vec3>& points) {
  Row row;
  const auto start = Clock::now();
  const MeshCollider exact(part.mesh);
  row.fitSeconds = secondsSince(start);
  row.enclosed = 100.0;
  row.volumes = 1;
  const double inf = std::numeric_limits<double>::infinity();
  row.queryNs = nanosecondsPerQuery(points, [&](const Vec3& p) {
    Contact c;
    exact.contact(p, 0.0, inf, c);
    return c.distance;
  });
  return row;
}

PartRows studyPart(const PartMesh& part, const CollisionStudyOptions& options) {
  const std::vector<Vec3>& vertices = part.mesh.vertices;
  const std::vector<Vec3> points = queryPoints(vertices);
  // What shapeCapsules and shapeRadialVolumes return for this part (they loop over the
  // parts of splitIntoParts with these same calls).
  VolumeShapingOptions fitOptions;
  fitOptions.harmonics = options.harmonics;
  fitOptions.sectionSpacing = options.sectionSpacing;
  PartRows rows;
  auto start = Clock::now();
  const std::vector<CollisionVolumeParameters> capsules = shapePartCapsules(part, fitOptions);
  rows.capsule = fittedRow(capsules, secondsSince(start), vertices, points);
  start = Clock::now();
  const std::vector<CollisionVolumeParameters> radial = shapePartRadial(part, fitOptions);
  rows.radial = fittedRow(radial, secondsSince(start), vertices, points);
  rows.fellBack = radial.front().kind == CollisionVolumeParameters::Kind::Capsule;
  rows.exact = exactRow(part, points);
  return rows;
}

// The part's three CSV lines.
std::string csvLines(const PartMesh& part, const PartRows& rows) {
  std::string lines;
  for (const auto& [method, row] :
       {std::pair<const char*, const Row&>{"capsule", rows.capsule}, {"radial", rows.radial}, {"exact", rows.exact}}) {
    char line[256];
    const char* kind = method == std::string("radial") && rows.fellBack ? "capsule" : method;
    std::snprintf(line, sizeof line, "%s,%s,%.3f,%.3f,%.2f,%.0f,%.3f,%zu,%d,%s\n", part.name.c_str(), method,
                  1000 * row.meanGap, 1000 * row.maxGap, row.enclosed, row.queryNs, row.fitSeconds,
                  part.mesh.vertices.size(), row.volumes, kind);
    lines += line;
  }
  return lines;
}

void printPart(const PartMesh& part, const PartRows& rows) {
  const Row &capsule = rows.capsule, &radial = rows.radial;
  std::printf(
      "%-11s %5zu vertices  capsule x%d gap %5.1f mm (max %5.1f) %4.0f ns  radial%s gap %5.1f mm (max "
      "%5.1f) %5.0f ns  exact %6.0f ns  enclosed %.0f %% %.0f %%\n",
      part.name.c_str(), part.mesh.vertices.size(), capsule.volumes, 1000 * capsule.meanGap, 1000 * capsule.maxGap,
      capsule.queryNs, rows.fellBack ? "(capsules)" : "", 1000 * radial.meanGap, 1000 * radial.maxGap, radial.queryNs,
      rows.exact.queryNs, capsule.enclosed, radial.enclosed);
}

std::string writeText(const std::string& path, const std::string& text) {
  return writeAtomically(path, [&text](const std::string& temporary) -> std::string {
    std::ofstream out(temporary);
    out << text;
    out.close();
    return out ? "" : "cannot write " + temporary;
  });
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
  std::string csv = "part,method,mean_gap_mm,max_gap_mm,enclosed_pct,query_ns,fit_s,vertices,volumes,kind\n";
  std::vector<double> capsuleGap, radialGap, capsuleNs, radialNs, exactNs;
  for (const PartMesh& part : parts) {
    const PartRows rows = studyPart(part, options);
    csv += csvLines(part, rows);
    printPart(part, rows);
    capsuleGap.push_back(1000 * rows.capsule.meanGap), radialGap.push_back(1000 * rows.radial.meanGap);
    capsuleNs.push_back(rows.capsule.queryNs), radialNs.push_back(rows.radial.queryNs);
    exactNs.push_back(rows.exact.queryNs);
  }
  if (const std::string error = writeText(csvPath, csv); !error.empty()) {
    std::cerr << "figment-bench: " << csvPath << ": " << error << "\n";
    return 1;
  }
  std::printf(
      "medians over parts: mean gap capsule %.1f mm, radial %.1f mm (K = %d); query capsule %.0f ns, "
      "radial %.0f ns, exact %.0f ns; exact/capsule %.1fx, radial/capsule %.2fx\n",
      median(capsuleGap), median(radialGap), options.harmonics, median(capsuleNs), median(radialNs), median(exactNs),
      median(exactNs) / median(capsuleNs), median(radialNs) / median(capsuleNs));
  std::cout << csvPath << "\n";
  std::cout.flush();
  chartCsv(options.plotScript, csvPath, options.outDir + "/collision.png");
  return 0;
}

}  // namespace

}  // namespace figment::bench
