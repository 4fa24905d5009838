#include "TradeoffStudy.h"

#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "BodyChoice.h"
#include "CsvFile.h"
#include "MethodSpec.h"
#include "SceneGarment.h"
#include "TemporaryScript.h"
#include "nodes/body/CollisionBody.h"
#include "nodes/body/CollisionGroup.h"
#include "nodes/body/Mannequin.h"
#include "sim/body/Skeleton.h"
#include "sim/collision/Collider.h"
#include "sim/drape/MethodChoice.h"
#include "sim/progressive/Resampling.h"
#include "sim/progressive/RestCorrespondence.h"

namespace figment::bench {

namespace {

constexpr double kTornStrain = 0.2;  // an edge this far off its rest length: torn (as the stability study)

struct Row {
  std::string scene, method, body, schedule;
  double resolution = 1.0;
  int sections = 0;
  double steps = 0.0, wall = 0.0, simulated = 0.0;
  int rested = 0, runs = 0;
  double meanDev = NAN, maxDev = NAN;  // % of the garment's height
  int inside = 0;
  double maxStrain = NAN;
  std::string failure;  // "" when it came to rest whole and finite
  bool pareto = false;
};

std::vector<Vec3> toVec3(const std::vector<SbVec3f>& points) {
  std::vector<Vec3> out;
  out.reserve(points.size());
  for (const SbVec3f& p : points) out.emplace_back(p[0], p[1], p[2]);
  return out;
}

// Mean and largest distance, % of `height`.
std::pair<double, double> deviation(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double height) {
  double mean = 0.0, largest = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    const double d = (a[i] - b[i]).norm();
    mean += d, largest = std::max(largest, d);
  }
  return {100.0 * mean / static_cast<double>(a.size()) / height, 100.0 * largest / height};
}

// The bodies a scene's garment is draped against, by the options' names (kept referenced).
// An outer layer's (a CollisionGroup of the Mannequin and inner garments) keeps its
// inner garments: each choice takes the Mannequin's place in a copy of the group.
class Bodies {
 public:
  // `garmentStart`: where the garment starts (the per-part mix's exact parts are those it
  // starts near); `sceneBody`: the garment's body as the scene has it.
  Bodies(SoNode* root, const TradeoffStudyOptions& options, const std::vector<Vec3>& garmentStart, SoNode* sceneBody,
         std::string& error)
      : layers_(sceneBody && sceneBody->isOfType(CollisionGroup::getClassTypeId())
                    ? static_cast<CollisionGroup*>(sceneBody)
                    : nullptr) {
    if (layers_) layers_->ref();
    SoNode* triangles = bodyFor("exact", root, error);
    if (triangles) exact_ = asCollisionBody(triangles)->bodyCollider();  // the body alone: "inside" counts
    add("triangles", triangles);
    for (const std::string& name : options.bodies) {
      if (!error.empty() || nodes_.count(name)) continue;
      if (name == "volumes")
        add(name, bodyFor(options.volumesFile, root, error));
      else if (name == "capsules")
        add(name, bodyFor(options.capsulesFile, root, error));
      else if (name == "mix")
        add(name, mixFor(root, options, garmentStart, error));
      else
        error = "--body " + name + ": expected volumes, capsules, triangles or mix";
    }
  }
  ~Bodies() {
    for (auto& [name, node] : nodes_) node->unref();
    if (layers_) layers_->unref();
  }
  Bodies(const Bodies&) = delete;
  Bodies& operator=(const Bodies&) = delete;

  SoNode* operator[](const std::string& name) const { return nodes_.at(name); }
  // Nodes of `x` inside the body's own triangles.
  int inside(const std::vector<Vec3>& x) const {
    int count = 0;
    Contact contact;
    for (const Vec3& p : x) count += exact_->contact(p, 0.0, 0.05, contact) && contact.distance < 0.0;
    return count;
  }

 private:
  // The radial volumes with the parts the garment starts near on their own triangles, as
  // ClothEngine.tolerance builds it (sim/drape/MethodChoice.h), as Mannequin.exactParts.
  static SoNode* mixFor(SoNode* root, const TradeoffStudyOptions& options, const std::vector<Vec3>& garmentStart,
                        std::string& error) {
    SoNode* node = bodyFor(options.volumesFile, root, error);
    if (!node) return nullptr;
    auto* mannequin = static_cast<Mannequin*>(node);
    const std::vector<int> parts = partsWhereGarmentMeets(*mannequin->collider(), garmentStart);
    mannequin->exactParts.setNum(0);
    for (int part : parts) {
      const std::string& name = mannequin->skeleton().parts[part].name;
      mannequin->exactParts.set1Value(mannequin->exactParts.getNum(), name.c_str());
    }
    std::printf("mix: triangles on %zu parts the garment starts within %.0f mm of\n", parts.size(),
                1000.0 * kExactPartReach);
    return node;
  }
  void add(const std::string& name, SoNode* node) {
    if (!node) return;
    if (layers_) {
      auto* group = new CollisionGroup;
      group->body = node;
      group->layers = layers_->layers;
      node = group;
    }
    node->ref();
    nodes_[name] = node;
  }
  CollisionGroup* layers_;  // the scene's group, or null
  std::map<std::string, SoNode*> nodes_;
  std::shared_ptr<const Collider> exact_;
};

// The converged drape the others are measured against, on the body's triangles.
struct Reference {
  std::vector<Vec3> positions;
  double height = 0.0;
};

std::optional<Reference> drapeReference(SceneGarment& garment, const Bodies& bodies,
                                        const TradeoffStudyOptions& options, std::ostream& csv, std::string& error) {
  ClothEngine& engine = *garment.engine;
  const Method method = parseMethod(options.reference);
  configure(engine, method);
  engine.body = bodies["triangles"];
  engine.progressiveScript = "";
  const RepeatedDrape run = garment.drapeRepeatedly(1);
  if (!(error = run.error).empty()) return std::nullopt;
  Reference reference{toVec3(run.positions), garment.height()};
  std::printf("reference %s on the body's triangles: %d steps, %.3f s simulated, %s, %.1f s wall\n",
              options.reference.c_str(), run.report.run.iterations, run.report.run.simulatedTime,
              run.report.run.atRest ? "at rest" : "moving", run.medianWall);
  double halfMean = NAN, halfMax = NAN;
  if (options.checkReference) {
    engine.timeStep = 0.5 * method.drape.timeStep;
    const RepeatedDrape half = garment.drapeRepeatedly(1);
    if (!(error = half.error).empty()) return std::nullopt;
    std::tie(halfMean, halfMax) = deviation(toVec3(half.positions), reference.positions, reference.height);
    std::printf("  at half its step it moves %.3f %% mean, %.3f %% max of the garment's height\n", halfMean, halfMax);
  }
  csv << options.reference << ',' << run.report.run.iterations << ',' << run.report.run.simulatedTime << ','
      << run.report.run.atRest << ',' << reference.height << ',' << halfMean << ',' << halfMax << '\n';
  return reference;
}

// Whether and how a drape failed.
std::string failureOf(const RepeatedDrape& run, double maxStrain) {
  if (!run.error.empty()) return run.error.find("blew up") != std::string::npos ? "blew up" : "error: " + run.error;
  std::string failure;
  if (maxStrain > kTornStrain) failure = "tore";
  if (!run.report.run.atRest) failure += failure.empty() ? "never rested" : "; never rested";
  return failure;
}

// The garment at one resolution: its rest mesh, where the reference's vertices lie on
// it, and its progressive script when a schedule needs one.
struct Resolution {
  double factor = 1.0;
  TriangleMesh mesh;
  std::optional<RestCorrespondence> correspondence;  // none at the garment's own resolution
  std::unique_ptr<TemporaryScript> script;
};

Resolution makeResolution(const TriangleMesh& base, double factor, const TradeoffStudyOptions& options) {
  Resolution r;
  r.factor = factor;
  const int sections = static_cast<int>(std::lround(factor * static_cast<double>(base.triangles.size())));
  r.mesh = factor == 1.0 ? base : asSceneHoldsIt(resampled(base, sections));
  if (factor != 1.0) r.correspondence.emplace(base, r.mesh);
  if (std::any_of(options.schedules.begin(), options.schedules.end(), [](const std::string& s) { return s != "off"; }))
    r.script = std::make_unique<TemporaryScript>(r.mesh, options.coarseShare);
  return r;
}

// One configuration's drapes and measures.
Row drapeOne(SceneGarment& garment, const Bodies& bodies, const Reference& reference, const Resolution& resolution,
             const Method& method, const std::string& body, const std::string& schedule,
             const TradeoffStudyOptions& options) {
  ClothEngine& engine = *garment.engine;
  Row row;
  row.method = method.text, row.body = body, row.schedule = schedule;
  row.resolution = resolution.factor, row.sections = static_cast<int>(resolution.mesh.triangles.size());
  configure(engine, method);
  engine.body = bodies[body];
  engine.progressiveScript = "";
  if (schedule != "off") {
    const Schedule s = parseSchedule(schedule);
    engine.progressiveScript = resolution.script->path().c_str();
    engine.splitRate = s.rate;
    engine.endLevel = -1;
    engine.beginLevel = static_cast<int>(std::lround(s.beginShare * resolution.script->levels()));
  }
  const RepeatedDrape run = garment.drapeRepeatedly(options.repeat);
  row.runs = options.repeat;
  if (!run.error.empty()) {
    row.failure = failureOf(run, 0.0);
    return row;
  }
  row.steps = run.report.run.iterations, row.wall = run.medianWall, row.simulated = run.report.run.simulatedTime;
  row.rested = run.report.run.atRest ? options.repeat : 0;  // the same fields drape the same way every time
  const std::vector<Vec3> x = toVec3(run.positions);
  const std::vector<Vec3> carried = resolution.correspondence ? resolution.correspondence->carry(x) : x;
  std::tie(row.meanDev, row.maxDev) = deviation(carried, reference.positions, reference.height);
  row.inside = bodies.inside(x);
  row.maxStrain = garment.maxEdgeStrain(run.positions);
  row.failure = failureOf(run, row.maxStrain);
  return row;
}

// Marks the rows that did not fail and that no other row beats on both wall and deviation.
void markPareto(std::vector<Row>& rows) {
  for (Row& a : rows) {
    if (!a.failure.empty()) continue;
    a.pareto = std::none_of(rows.begin(), rows.end(), [&](const Row& b) {
      return &a != &b && b.failure.empty() && b.wall <= a.wall && b.meanDev <= a.meanDev &&
             (b.wall < a.wall || b.meanDev < a.meanDev);
    });
  }
}

void print(const Row& r) {
  std::printf("  %-24s %-9s %-7s x%-4g %5d sections: ", r.method.c_str(), r.body.c_str(), r.schedule.c_str(),
              r.resolution, r.sections);
  if (r.steps == 0.0) {
    std::printf("%s\n", r.failure.c_str());
  } else {
    std::printf("%6.0f steps %7.3f s wall  dev %6.3f %% (max %6.3f %%) inside %3d strain %5.3f%s%s\n", r.steps, r.wall,
                r.meanDev, r.maxDev, r.inside, r.maxStrain, r.failure.empty() ? "" : "  ", r.failure.c_str());
  }
  std::fflush(stdout);
}

// Every configuration on one scene; "" or the error.
std::string studyScene(const std::string& scene, const TradeoffStudyOptions& options, std::ostream& referenceCsv,
                       std::vector<Row>& out) {
  SceneGarment garment;
  std::string error;
  if (!garment.load(scene, error)) return error;
  const TriangleMesh base = garment.engine->restGarment();
  const Bodies bodies(garment.session.scene(), options, base.vertices, garment.engine->body.getValue(), error);
  if (!error.empty()) return scene + ": " + error;
  std::printf("%s\n", scene.c_str());
  referenceCsv << scene << ',';
  const std::optional<Reference> reference = drapeReference(garment, bodies, options, referenceCsv, error);
  if (!reference) return scene + ": the reference " + options.reference + ": " + error;
  std::vector<Row> rows;
  for (double factor : options.resolutions) {
    const Resolution resolution = makeResolution(base, factor, options);
    garment.replaceGarment(resolution.mesh);
    for (const std::string& text : options.methods)
      for (const std::string& body : options.bodies)
        for (const std::string& schedule : options.schedules) {
          rows.push_back(drapeOne(garment, bodies, *reference, resolution, parseMethod(text), body, schedule, options));
          rows.back().scene = scene;
          print(rows.back());
        }
  }
  garment.engine->progressiveScript = "";  // the scripts went with their resolutions
  markPareto(rows);
  out.insert(out.end(), rows.begin(), rows.end());
  return "";
}

// The configurations that rested whole on every garment, by their worst deviation and
// total wall, only those no other beats on both (io/TradeoffTable.h's format).
void writeFront(const std::vector<Row>& rows, size_t garments, std::ostream& csv) {
  struct Total {
    const Row* first = nullptr;
    size_t done = 0;
    double worst = 0.0, wall = 0.0;
  };
  std::map<std::string, Total> totals;
  for (const Row& r : rows) {
    Total& t = totals[r.method + "|" + r.body + "|" + r.schedule + "|" + std::to_string(r.resolution)];
    if (!t.first) t.first = &r;
    if (!r.failure.empty()) continue;
    ++t.done, t.worst = std::max(t.worst, r.meanDev), t.wall += r.wall;
  }
  std::vector<Total> eligible;
  for (const auto& [key, t] : totals)
    if (t.done == garments) eligible.push_back(t);
  std::sort(eligible.begin(), eligible.end(), [](const Total& a, const Total& b) { return a.wall < b.wall; });
  csv << "method,body,progressive,resolution,garments,worst_mean_dev_pct_height,total_median_wall_s\n";
  double best = INFINITY;  // the smallest worst deviation of the faster ones
  for (const Total& t : eligible) {
    if (t.worst >= best) continue;
    best = t.worst;
    csv << t.first->method << ',' << t.first->body << ',' << t.first->schedule << ',' << t.first->resolution << ','
        << garments << ',' << t.worst << ',' << t.wall << '\n';
  }
}

void writeRow(const Row& r, std::ostream& csv) {
  csv << r.scene << ',' << r.method << ',' << r.body << ',' << r.schedule << ',' << r.resolution << ',' << r.sections
      << ',' << r.steps << ',' << r.wall << ',' << r.simulated << ',' << r.rested << ',' << r.runs << ',' << r.meanDev
      << ',' << r.maxDev << ',' << r.inside << ',' << r.maxStrain << ",\"" << r.failure << "\"," << r.pareto << '\n';
}

}  // namespace

TradeoffStudyOptions quickTradeoff(TradeoffStudyOptions options) {
  options.scenes = {"scenes/dress.iv"};
  options.methods = {"heun:1.5e-4:clamp:30", "implicit:0.02", "implicit:0.05", "implicit+penalty:0.05"};
  options.schedules = {"off", "0:3000"};
  options.resolutions = {0.5, 1.0};
  options.reference = "heun:1e-4";
  options.checkReference = false;
  options.repeat = 1;
  return options;
}

int runTradeoffStudy(const TradeoffStudyOptions& options) {
  if (!parsesOrReports([&] {
        parseMethod(options.reference);
        for (const std::string& text : options.methods) parseMethod(text);
        for (const std::string& text : options.schedules)
          if (text != "off") parseSchedule(text);
      }))
    return 2;
  std::filesystem::create_directories(options.outDir);
  std::vector<Row> rows;
  std::ostringstream references;
  for (const std::string& scene : options.scenes)
    if (std::string error = studyScene(scene, options, references, rows); !error.empty()) {
      std::fprintf(stderr, "figment-bench: %s\n", error.c_str());
      return 1;
    }
  const std::string csvPath = options.outDir + "/tradeoff.csv";
  const bool written =
      writeCsv(options.outDir + "/tradeoff-reference.csv",
               [&](std::ostream& csv) -> std::string {
                 // How far the reference moves when its step is halved (NaN: not checked).
                 csv << "scene,method,steps,simulated_s,at_rest,garment_height_m,half_step_mean_dev_pct_height,"
                        "half_step_max_dev_pct_height\n"
                     << references.str();
                 return "";
               }) &&
      writeCsv(csvPath, [&](std::ostream& csv) -> std::string {
        // Steps, simulated time and deviations are of the last drape; wall the median of
        // `runs`; deviations are % of the garment's height from the reference; nodes
        // inside the body's own triangles.
        csv << "scene,method,body,progressive,resolution,sections,steps,median_wall_s,simulated_s,rested,runs,"
               "mean_dev_pct_height,max_dev_pct_height,nodes_inside,max_edge_strain,failure,pareto\n";
        for (const Row& r : rows) writeRow(r, csv);
        return "";
      });
  const bool front = written && writeCsv(options.outDir + "/tradeoff-table.csv", [&](std::ostream& csv) -> std::string {
                       writeFront(rows, options.scenes.size(), csv);
                       return "";
                     });
  if (!front) return 1;
  chartCsv(options.plotScript, csvPath, options.outDir + "/tradeoff.png");
  return 0;
}

}  // namespace figment::bench
