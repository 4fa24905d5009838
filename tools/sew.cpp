// figment-sew: a sewing pattern sewn on a body and draped (docs/patterns.md).
//   figment-sew PATTERN.json --body BODY -o garment.obj|.glb|.gltf [--stats stats.json]
//               [--spacing M] [--material NAME] [--made-for-stature M] [--max-time S]
//               [--max-step S] [--with-body]
// PATTERN is GarmentCode's specification JSON (io/PatternFile.h); BODY any standing body a
// MeshFile reads (human.zae, one figment-body made), found through the model search path.
// The panels are placed around the body (sim/pattern/PatternPlacement.h), cut into cloth
// (sim/pattern/PatternCutting.h), sewn and draped to rest (sim/pattern/Sewing.h) by backward
// Euler from 1/20 s, the drape's step growing to --max-step while the cloth is quiet. The
// garment goes to the output with its panel coordinates; --stats writes what the drape did
// as JSON. Bad input is one line on stderr, exit status 1, and no file.
// A drape that is not clean (not at rest, torn, a seam left open, nodes inside the body) is
// written, with one line per problem on stderr.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "ToolMain.h"
#include "io/AtomicFile.h"
#include "io/DrapeReportJson.h"
#include "io/MeshSetExport.h"
#include "io/PatternFile.h"
#include "sim/cloth/DrapeVerdict.h"
#include "sim/cloth/MaterialPresets.h"
#include "sim/collision/MeshCollider.h"
#include "sim/drape/GarmentDrape.h"
#include "sim/pattern/PatternCutting.h"
#include "sim/pattern/PatternPlacement.h"

namespace {

const figment::tools::ToolMain kTool{"figment-sew"};

struct Request {
  std::string pattern, output, stats, material = "cotton";
  double spacing = 0.02, madeForStature = 0.0, maxTime = 20.0,
         maxStep = figment::ImplicitSolverParameters::kShippedMaxTimeStep;
  bool withBody = false;
};

figment::ClothParameters drapeParameters(const Request& request) {
  figment::ClothParameters p;
  const auto material = figment::materialPreset(request.material);
  if (!material)
    throw std::invalid_argument("--material " + request.material + ": not a fabric (" + [] {
      std::string names;
      for (const std::string& n : figment::materialPresetNames()) names += (names.empty() ? "" : ", ") + n;
      return names;
    }() + ")");
  p.material = *material;
  p.integrator = figment::Integrator::Implicit;
  p.timeStep = 0.05;
  p.maxTime = request.maxTime;
  p.implicitSolver.maxTimeStep = request.maxStep;
  p.rest = {0.01, 0.25};
  p.friction = 0.5;
  p.clearance = 0.003;
  return p;
}

// Garment nodes inside the body (negative distance to its surface), and the deepest: how
// deep, on which panel, how high, so a shop can see where its garment meets the body.
struct InsideNodes {
  int count = 0;
  double depth = 0.0;  // m, the deepest node's
  int node = -1;       // the deepest node (panel numbering)
};

InsideNodes nodesInside(const figment::Collider& body, const std::vector<figment::Vec3>& positions) {
  InsideNodes inside;
  for (size_t i = 0; i < positions.size(); ++i) {
    figment::Contact contact;
    if (!body.contact(positions[i], 0.0, 0.3, contact) || contact.distance >= 0.0) continue;
    ++inside.count;
    if (-contact.distance > inside.depth) inside.depth = -contact.distance, inside.node = static_cast<int>(i);
  }
  return inside;
}

// The sewing's figures, the whole run's, and the drape's report as figment-view --stats
// writes it (io/DrapeReportJson.h) under "drape".
std::string statsJson(const figment::GarmentDrape& drape, const figment::DrapeVerdict& verdict, int inside,
                      const figment::UnsewnGarment& cut) {
  const figment::SewingOutcome& sewing = *drape.sewing;
  const nlohmann::json stats = {{"at_rest", verdict.run.atRest},
                                {"seam_gap_max_m", sewing.seamGap},
                                {"inside_nodes", inside},
                                {"steps", sewing.run.iterations + verdict.run.iterations},
                                {"wall_s", sewing.run.wallSeconds + verdict.run.wallSeconds},
                                {"sewing_steps", sewing.run.iterations},
                                {"sewing_wall_s", sewing.run.wallSeconds},
                                {"drape_steps", verdict.run.iterations},
                                {"closed_gap_m", sewing.closedGap},
                                {"open_seam_pairs", sewing.openPairs},
                                {"panels", cut.panelNames.size()},
                                {"nodes", cut.placed.vertices.size()},
                                {"sewn_nodes", sewing.sewnNodes},
                                {"triangles", cut.placed.triangles.size()},
                                {"clean", verdict.clean() && inside == 0 && sewing.openPairs == 0},
                                {"drape", nlohmann::json::parse(figment::drapeReportJson(drape.report))}};
  return stats.dump(2) + "\n";
}

// What the drape's end says of it (sim/cloth/DrapeVerdict.h).
figment::DrapeVerdict verdictOf(const figment::GarmentDrape& drape) {
  return {drape.report.run, drape.report.maxTime};
}

// The stitches whose pairs stayed open, by their panels and edges: "stitch 3 (skirt_front
// edge 11, skirt_back edge 0), ...".
std::string openStitches(const figment::SewingPattern& pattern, const figment::UnsewnGarment& cut,
                         const figment::SewingOutcome& sewing) {
  std::set<int> stitches;
  for (int pair : sewing.openSeamPairs) stitches.insert(cut.seamStitch[pair]);
  std::string text;
  for (int s : stitches) {
    const figment::Stitch& stitch = pattern.stitches[s];
    const auto edge = [&](const figment::EdgeRef& e) {
      return pattern.panels[e.panel].name + " edge " + std::to_string(e.edge);
    };
    text += (text.empty() ? "" : ", ") +
            ("stitch " + std::to_string(s) + " (" + edge(stitch.first) + ", " + edge(stitch.second) + ")");
  }
  return text;
}

// One line on stderr per problem of a drape that is not clean.
void reportProblems(const std::string& name, const figment::SewingPattern& pattern, const figment::UnsewnGarment& cut,
                    const figment::GarmentDrape& drape, const figment::DrapeVerdict& verdict,
                    const InsideNodes& inside) {
  if (!verdict.clean())
    std::fprintf(stderr, "%s: %s: %s\n", kTool.program().c_str(), name.c_str(), verdict.describe().c_str());
  if (drape.sewing->openPairs > 0)
    std::fprintf(stderr, "%s: %s: a seam left open: %d node pairs apart, the widest %.1f mm (%s)\n",
                 kTool.program().c_str(), name.c_str(), drape.sewing->openPairs, 1000 * drape.sewing->seamGap,
                 openStitches(pattern, cut, *drape.sewing).c_str());
  if (inside.count > 0) {
    const figment::Vec3& deepest = drape.positions[inside.node];
    std::fprintf(stderr, "%s: %s: %d garment nodes inside the body, the deepest %.1f mm in (panel %s, %.2f m up)\n",
                 kTool.program().c_str(), name.c_str(), inside.count, 1000 * inside.depth,
                 cut.panelNames[cut.panelOf[inside.node]].c_str(), deepest.y());
  }
}

int sew(const Request& request, const figment::TriangleMesh& body) {
  const figment::ClothParameters parameters = drapeParameters(request);
  const figment::SewingPattern pattern = figment::readPatternFile(request.pattern);
  const auto started = std::chrono::steady_clock::now();
  const figment::PatternPlacement placement = figment::placementOn(body, request.madeForStature);
  const figment::UnsewnGarment cut = figment::cutPattern(figment::placed(pattern, placement), request.spacing);
  auto collider = std::make_shared<figment::MeshCollider>(body);

  figment::DrapeRequest drapeRequest;
  drapeRequest.garment = cut.placed;
  drapeRequest.parameters = parameters;
  drapeRequest.body = collider;
  drapeRequest.sewing = figment::DrapeSewing{cut.flat, cut.seams, {}};
  figment::GarmentDrape drape = figment::drapeGarment(drapeRequest);
  // The report's wall time is the drape's whole: placing, cutting and the body's tree too.
  drape.report.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  drape.report.verdict = figment::verdictOf(drape.report);

  const figment::DrapeVerdict verdict = verdictOf(drape);
  const InsideNodes inside = nodesInside(*collider, drape.positions);

  std::vector<figment::ColouredMesh> meshes;
  figment::ColouredMesh garment;
  garment.name = pattern.name.empty() ? "garment" : pattern.name;
  garment.mesh = {drape.positions, cut.placed.triangles};
  garment.normals = figment::vertexNormals(garment.mesh);
  garment.colour = {0.2f, 0.35f, 0.7f};
  garment.twoSided = true;
  meshes.push_back(garment);
  if (request.withBody) {
    figment::ColouredMesh skin{"body", body, figment::vertexNormals(body), {0.8f, 0.58f, 0.45f}, 1.0f, false};
    meshes.push_back(skin);
  }
  std::vector<std::string> written;
  figment::exportMeshSet(meshes, request.output, &written);
  if (!request.stats.empty()) {
    const std::string text = statsJson(drape, verdict, inside.count, cut);
    const std::string error = figment::writeAtomically(request.stats, [&](const std::string& temporary) {
      std::ofstream out(temporary);
      out << text;
      out.close();
      return out ? std::string() : temporary + ": cannot write";
    });
    if (!error.empty()) {
      for (const std::string& path : written) std::remove(path.c_str());  // no partial output
      throw std::runtime_error(request.stats + ": " + error);
    }
  }

  reportProblems(request.pattern, pattern, cut, drape, verdict, inside);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Sews a sewing pattern (GarmentCode JSON) on a body and drapes it to rest.", kTool.program()};
  Request request;
  figment::tools::BodyInput body;
  figment::tools::addBodyOptions(app, body);
  app.add_option("pattern", request.pattern, "the pattern: GarmentCode's specification JSON")->required();
  app.add_option("-o,--output", request.output, "the sewn, draped garment: .obj, .glb or .gltf")->required();
  app.add_option("--stats", request.stats, "what the drape did, as JSON (at_rest, seam_gap_max_m, ...)");
  app.add_option("--spacing", request.spacing, "the cloth's node spacing, m (default 0.02)")
      ->check(CLI::Range(0.005, 0.1));
  app.add_option("--material", request.material, "the fabric: a material preset (default cotton)");
  app.add_option("--made-for-stature", request.madeForStature,
                 "the stature of the body the pattern was made for, m (default: the body's own)");
  app.add_option("--max-time", request.maxTime, "simulated seconds the drape may take to rest, at most (default 20)")
      ->check(CLI::Range(0.05, 120.0));
  app.add_option("--max-step", request.maxStep,
                 "the drape's step grows from 1/20 s to this while the cloth is quiet, s (default 0.4, "
                 "the service's; 0: a fixed 1/20 s)")
      ->check(CLI::Number);
  app.add_flag("--with-body", request.withBody, "write the body beside the garment");
  if (const int status = kTool.parse(app, argc, argv); status >= 0) return status;
  if (!figment::meshSetFormatOf(request.output))
    return kTool.fail("-o " + request.output + ": not .obj, .glb or .gltf");
  return kTool.withBody(body,
                        [&](const figment::TriangleMesh& mesh, const std::string&) { return sew(request, mesh); });
}
