// figment-fit: fits a body's collision volumes once and writes them as an .iv file that
// scenes include in a Mannequin (paper §3).
//
//   figment-fit [--body human.zae] -o scenes/human-volumes.iv [--method radial|capsule]
//               [--capsule PART ...] [--exact PART ...] [--harmonics K]
//               [--section-spacing M] [--seed N] [--metres-per-unit M] [--up-axis AXIS]
//
// The body is read as a MeshFile with the same fields reads it (metres, y up, without
// the excluded meshes): the volumes are in that frame, so a scene's MeshFile for the body
// takes the same metresPerUnit and upAxis. A body that then does not stand along +y at a
// human stature is refused at once, with the options that would fix it (tools/ToolMain.h:
// the fit's thresholds are in metres). Its skeleton is estimated from cross sections
// (sim/body/SkeletonEstimate.h); each part gets radial depth volumes (or capsules where a
// radial volume does not suit it, sim/volumes/VolumeShaping.h) or capsules, or, for the parts
// named by --capsule and --exact, capsules and ExactVolume. The file holds one
// SkeletonJoints and the volume nodes. One summary line on stdout; any error is one
// line, "figment-fit: <file>: <reason>", exit status 1, and no file.

#include <Inventor/SoOutput.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/nodes/SoGroup.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "ToolMain.h"
#include "io/AtomicFile.h"
#include "io/MeshImport.h"
#include "nodes/Init.h"
#include "nodes/body/CapsuleVolume.h"
#include "nodes/body/ExactVolume.h"
#include "nodes/body/RadialDepthVolume.h"
#include "nodes/body/SkeletonJoints.h"
#include "sim/body/SkeletonEstimate.h"
#include "sim/volumes/VolumeShaping.h"

namespace {

const figment::tools::ToolMain kTool{"figment-fit"};

struct Options {
  figment::tools::BodyInput body;
  std::string output;
  std::string method = "radial";
  std::vector<std::string> capsuleParts, exactParts;
  figment::VolumeShapingOptions fit;
  std::string commandLine;
};

// The nodes for `volumes`, with the parts in `exact` as ExactVolume.
SoGroup* volumeNodes(const figment::Skeleton& skeleton, const std::vector<figment::CollisionVolumeParameters>& volumes,
                     const std::set<std::string>& exact) {
  auto* group = new SoGroup;
  auto* joints = new SkeletonJoints;
  joints->setSkeleton(skeleton);
  group->addChild(joints);
  for (const figment::CollisionVolumeParameters& v : volumes) {
    if (exact.count(v.part)) continue;
    if (v.kind == figment::CollisionVolumeParameters::Kind::Capsule) {
      auto* node = new CapsuleVolume;
      node->part = v.part.c_str();
      node->setParameters(v.capsule);
      group->addChild(node);
    } else {
      auto* node = new RadialDepthVolume;
      node->part = v.part.c_str();
      node->setParameters(v.radial);
      group->addChild(node);
    }
  }
  for (const std::string& part : exact) {
    auto* node = new ExactVolume;
    node->part = part.c_str();
    group->addChild(node);
  }
  return group;
}

std::string writeIv(SoNode* root, const std::string& path, const std::string& header) {
  SoOutput out;
  if (!out.openFile(path.c_str())) return "cannot write " + path;
  out.setHeaderString(SbString(("#Inventor V2.1 ascii\n\n" + header).c_str()));
  SoWriteAction write(&out);
  write.apply(root);
  out.closeFile();
  return "";
}

// Reads the command line into `options`: -1 to go on, else the exit status.
int parseCommandLine(int argc, char** argv, Options& options) {
  CLI::App app{"Fits a body's collision volumes and writes them as an .iv file for a Mannequin.", kTool.program()};
  figment::tools::addBodyOptions(app, options.body);
  app.add_option("-o,--output", options.output, ".iv file to write")->required();
  app.add_option("--method", options.method, "radial (radial depth, capsules where it does not suit) or capsule")
      ->check(CLI::IsMember({"radial", "capsule"}))
      ->capture_default_str();
  app.add_option("--capsule", options.capsuleParts, "parts that get capsules whatever the method");
  app.add_option("--exact", options.exactParts, "parts that collide with their own triangles (ExactVolume)");
  app.add_option("--harmonics", options.fit.harmonics, "K, Fourier harmonics of the radial depth")
      ->check(CLI::Range(0, 31))
      ->capture_default_str();
  app.add_option("--section-spacing", options.fit.sectionSpacing, "distance between radial sections, m")
      ->check(CLI::Range(0.002, 0.5))
      ->capture_default_str();
  app.add_option("--seed", options.fit.seed, "seed of the genetic algorithm")->capture_default_str();
  if (const int status = kTool.parse(app, argc, argv); status >= 0) return status;
  options.commandLine = kTool.program();
  for (int i = 1; i < argc; ++i) options.commandLine += std::string(" ") + argv[i];
  return -1;
}

// The first of `names` that is no part of `skeleton`, or "".
std::string unknownPart(const figment::Skeleton& skeleton, const std::set<std::string>& names) {
  for (const std::string& name : names)
    if (std::none_of(skeleton.parts.begin(), skeleton.parts.end(), [&](const auto& p) { return p.name == name; }))
      return name;
  return "";
}

// The volumes of the method, with capsules for the parts in `forcedCapsules`.
std::vector<figment::CollisionVolumeParameters> fitVolumes(const figment::TriangleMesh& body,
                                                           const figment::Skeleton& skeleton, const Options& options,
                                                           const std::set<std::string>& forcedCapsules) {
  std::vector<figment::CollisionVolumeParameters> volumes;
  const bool radial = options.method == "radial";
  if (radial) {
    for (figment::CollisionVolumeParameters& v : figment::shapeRadialVolumes(body, skeleton, options.fit))
      if (!forcedCapsules.count(v.part)) volumes.push_back(std::move(v));
  }
  if (!radial || !forcedCapsules.empty()) {
    for (figment::CollisionVolumeParameters& v : figment::shapeCapsules(body, skeleton, options.fit))
      if (!radial || forcedCapsules.count(v.part)) volumes.push_back(std::move(v));
  }
  return volumes;
}

// Fits `body` and writes the file: the exit status.
int fitAndWrite(const Options& options, const figment::TriangleMesh& body) {
  const auto start = std::chrono::steady_clock::now();
  const figment::Skeleton skeleton = figment::estimateSkeleton(body);
  const std::set<std::string> exact(options.exactParts.begin(), options.exactParts.end());
  const std::set<std::string> forcedCapsules(options.capsuleParts.begin(), options.capsuleParts.end());
  if (const std::string name = unknownPart(skeleton, exact); !name.empty())
    return kTool.fail("--exact: " + name + " is not a part");
  if (const std::string name = unknownPart(skeleton, forcedCapsules); !name.empty())
    return kTool.fail("--capsule: " + name + " is not a part");

  // A fit takes seconds to minutes: say which part is being fitted, a line each.
  Options withProgress = options;
  withProgress.fit.progress = [&](const std::string& part, int index, int count) {
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    std::fprintf(stderr, "figment-fit: %s: part %d of %d (%s), %.1f s\n", options.body.name.c_str(), index + 1, count,
                 part.c_str(), elapsed.count());
  };
  const std::vector<figment::CollisionVolumeParameters> volumes =
      fitVolumes(body, skeleton, withProgress, forcedCapsules);
  size_t capsules = 0, radials = 0;
  for (const auto& v : volumes)
    if (!exact.count(v.part)) (v.kind == figment::CollisionVolumeParameters::Kind::Capsule ? capsules : radials)++;
  SoGroup* root = volumeNodes(skeleton, volumes, exact);
  root->ref();
  const std::string header = "# The collision volumes of " + options.body.name + ", fitted by\n#   " +
                             options.commandLine +
                             "\n# Include it in a Mannequin (nodes/body/Mannequin.h); regenerate, do not edit.";
  const std::string error = figment::writeAtomically(
      options.output, [&](const std::string& temporary) { return writeIv(root, temporary, header); });
  root->unref();
  if (!error.empty()) return kTool.fail(options.output + ": " + error);
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  std::printf("%s: %s: %zu radial depth volumes, %zu capsules, %zu exact parts, %.1f s\n", kTool.program().c_str(),
              options.output.c_str(), radials, capsules, exact.size(), wall.count());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const int status = parseCommandLine(argc, argv, options); status >= 0) return status;
  figment::init();
  return kTool.withBody(
      options.body, [&](const figment::TriangleMesh& body, const std::string&) { return fitAndWrite(options, body); });
}
