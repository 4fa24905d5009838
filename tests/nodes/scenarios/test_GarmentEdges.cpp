// Every shipped garment's openings (hems, sleeve ends, necklines, armholes) read as smooth
// curves: the median turning angle between consecutive edges of its free boundary
// (sim/core/BoundaryLoops.h) is at most twice what the same openings would turn as circles
// of their own length sampled at their own vertices (roundTurning: 360 / n degrees a vertex
// of an n-gon, about 9 on these 40-column garments, so bounds of 14 to 19), in the rest
// shape and draped, and so on both display meshes, whose bounds halve with each level as
// their vertices double. The rule is derived from each mesh, not copied from a run: the
// bounds were golden numbers once (the measured medians plus half a degree or a degree, up
// to 17.9), which a measure reading 57 times small (radians) passed (issue 45). A hem cut
// along the body's triangles zig-zags: the T-shirt's turned a median 49 degrees at rest and
// 52 draped before its openings were cut along planes and a sphere; the control
// (expectZigZagFails) makes every garment's openings zig-zag on purpose, at rest and
// draped, and the rule must fail them (they turn 53 to 58 degrees). The progressive dress
// (dress.pm) is dress.obj at its full level, so dress.iv covers it. The posed scenes'
// garments (human-posed-*.iv: the T-shirt on the raised arm, the dress in a walking step,
// the skirt sitting) are draped as the scenes drape them, the body moving from rest into
// its pose: every garment file under scenes/ is measured at rest and in a drape. The posed
// T-shirt (human-body-tshirt.obj) was the last made before the T-shirt's openings were cut
// along surfaces: 46.8 at rest, 48.6 in the pose, 34.9 within the cloth with a zig-zag
// share of 0.59; made again by the same command, 8.8 / 9.8, 3.0 within the cloth, no
// zig-zag.
//
// What turns most: the default dress at rest (12.8 of 18.1), its straps bending over the
// shoulder in 14 quads (up to 35 degrees a vertex); and the drapes that fold their
// openings: the flared skirt's hem falls into folds about four of its 40 columns wide (its
// hem turns a median 33 degrees draped, the waistband 9; 13.6 in all), the second body's
// dress stops at maxTime still moving (second-body.iv says why) with its armholes creased
// (16.9 of 18.1), the catalogue's dress and T-shirt in XL on the chart's XL body crease
// theirs (13.1 and 13.9). A fold is the drape's shape, and the display mesh follows it:
// with one level of display mesh (ClothingLayer.displaySubdivision) the medians are 3.9 to
// 5.5 at rest and 4.1 to 7.2 draped (bounds 7.2 to 9.4), with two 2.0 to 2.9 and 2.0 to
// 3.5 (bounds 3.6 to 4.7). "No worse draped than at rest" in 3D does not hold on the
// display mesh either (the skirt's 4.3 rest, 6.1 draped at one level): it smooths the
// corners between the folds' edges, not the folds. Within the cloth it holds (below).
//
// "No worse draped than at rest" is checked where it means something, within the cloth:
// the 3D turning is the boundary's turning within the cloth (its geodesic part: a jagged
// cut) and its bending with the cloth (its normal part: a fold, a hem round a body) together
// (sim/core/BoundaryTurning.h). The geodesic part depends on edge lengths alone, so a drape
// can change it only as far as it stretches the cloth (expectNoWorseWithinTheCloth): on the
// simulation's mesh and on both display meshes of every garment here, with a zig-zag share
// that does not grow. The garments' rest shapes turn a median 0.2 to 3.3 degrees within the
// cloth and 0.3 to 3.4 draped (the T-shirt before its openings were cut along surfaces: 42);
// most of their 3D turning is the cloth wrapping the body.
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/fields/SoMFVec3f.h>
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "io/MakeHumanFiles.h"
#include "io/MeshImport.h"
#include "nodes/cloth/CatalogueGarment.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "sim/core/BoundaryLoops.h"
#include "sim/core/BoundaryTurning.h"
#include "sim/core/DisplaySubdivision.h"
#include "support/ShippedGarmentScene.h"

using namespace figment::test;

namespace {

// How much more than a circle an opening may turn and still read as a smooth curve (see
// roundTurning): twice.
constexpr double kRoundness = 2.0;
// How much the zig-zag share (BoundaryTurning.h) may grow draped: round a body a hem runs
// nearly straight within the cloth (a median geodesic turning under 3.5 degrees on every
// garment here), so the strain's noise in it, a few tenths of a degree either way, alternates
// in sign from vertex to vertex; against 3D turnings of 5 to 17 degrees a vertex it grew the
// share by up to 0.038 (the catalogue's XL dress, simulation mesh). A cut along the skin's
// triangles counts 0.57 (the T-shirt's before its openings were cut along surfaces).
constexpr double kZigZagNoise = 0.1;

struct ShippedGarment {
  std::string scene;
  std::string model;                            // the body's file, "" for MakeHuman's
  std::function<void(ClothEngine&)> configure;  // changes to the scene's own fields
  std::string catalogueGarment = {};            // the CatalogueGarment's garment, "" as shipped
};

void PrintTo(const ShippedGarment& garment, std::ostream* out) {
  *out << garment.scene;
  if (!garment.catalogueGarment.empty()) *out << " wearing " << garment.catalogueGarment;
}

std::vector<figment::Vec3> points(const SoMFVec3f& field) {
  std::vector<figment::Vec3> x;
  for (int i = 0; i < field.getNum(); ++i) x.emplace_back(field[i][0], field[i][1], field[i][2]);
  return x;
}

// The turning the openings would have as smooth curves sampled as they are: each vertex of
// a loop of length L turning by its spacing over the radius of a circle that long,
// (l_before + l_after) / 2 / (L / 2 pi), the 360 / n degrees of a regular n-gon at every
// vertex of one. Its median over the boundary's vertices, degrees. A closed curve turns at
// least a circle's 360 degrees in all (Fenchel), so this is what a smooth opening of that
// length and resolution turns where it turns least: one that wraps a body turns out of its
// plane too (an armhole over the shoulder), a drape folds a hem, and an opening that is not
// round (a neckline's U, a strap's end) turns more at some vertices. Up to kRoundness times
// it still reads as a curve; a cut along a grid's triangles turns by tens of degrees at every
// vertex whatever the resolution (the T-shirt's did 49, expectZigZagFails makes one on
// purpose). It scales with the mesh: a display mesh's loops, with two or four times the
// vertices, are held to half or a quarter of the simulation mesh's.
double roundTurning(const std::vector<figment::Vec3>& x, const std::vector<std::vector<int>>& loops) {
  std::vector<double> degrees;
  for (const std::vector<int>& loop : loops) {
    const size_t n = loop.size();
    double length = 0.0;
    for (size_t k = 0; k < n; ++k) length += (x[loop[(k + 1) % n]] - x[loop[k]]).norm();
    for (size_t k = 0; k < n && length > 0; ++k) {
      const double before = (x[loop[k]] - x[loop[(k + n - 1) % n]]).norm(),
                   after = (x[loop[(k + 1) % n]] - x[loop[k]]).norm();
      degrees.push_back(360.0 * 0.5 * (before + after) / length);
    }
  }
  return figment::BoundaryTurning::median(degrees);
}

// The median 3D turning of `faces`' openings at `x` and the bound roundTurning gives them.
struct Turning {
  double median = 0.0, bound = 0.0;
};
Turning turningOf(const std::vector<figment::Vec3>& x, const std::vector<figment::Triangle>& faces) {
  return {figment::medianBoundaryTurning(x, faces), kRoundness * roundTurning(x, figment::boundaryLoops(faces))};
}

// The display mesh that `levels` splits make of `faces` at `positions`: its turning.
Turning displayTurning(const std::vector<figment::Vec3>& positions, const std::vector<figment::Triangle>& faces,
                       int levels) {
  const figment::DisplaySubdivision layout(faces, positions, levels);
  std::vector<figment::Vec3> fine, normals;
  layout.apply(positions, fine, normals);
  return turningOf(fine, layout.triangles());
}

// The control: the same openings made to zig-zag on purpose, every other vertex of each loop
// moved across it within the cloth by a quarter of its spacing, one way and the next the
// other (as a hem cut along a grid's triangles zig-zags: about 2 atan(1/2), 53 degrees a
// vertex). The rule must fail it, at rest and draped, or it could not tell a jagged opening
// from a smooth one on this garment.
void expectZigZagFails(const std::vector<figment::Vec3>& x, const std::vector<figment::Triangle>& faces,
                       const std::string& what) {
  std::vector<figment::Vec3> normal(x.size(), figment::Vec3::Zero()), jagged = x;
  for (const figment::Triangle& t : faces) {
    const figment::Vec3 n = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
    for (const int v : t) normal[v] += n;
  }
  for (const std::vector<int>& loop : figment::boundaryLoops(faces)) {
    const size_t n = loop.size();
    for (size_t k = 0; k < n; ++k) {
      const figment::Vec3 &before = x[loop[(k + n - 1) % n]], &at = x[loop[k]], &after = x[loop[(k + 1) % n]];
      const figment::Vec3 across = normal[loop[k]].cross(after - before).normalized();
      const double spacing = 0.5 * ((at - before).norm() + (after - at).norm());
      if (across.allFinite()) jagged[loop[k]] += (k % 2 ? 0.25 : -0.25) * spacing * across;
    }
  }
  const Turning zigZag = turningOf(jagged, faces);
  EXPECT_GT(zigZag.median, zigZag.bound) << what << ": the rule would pass a zig-zag opening";
}

// The display mesh of `levels` splits of `faces` at the rest shape and at the drape, on the
// layout made at rest (as ClothingLayer makes it once for a drape).
std::pair<std::vector<figment::Vec3>, std::vector<figment::Vec3>> displayMeshes(
    const figment::DisplaySubdivision& layout, const std::vector<figment::Vec3>& rest,
    const std::vector<figment::Vec3>& draped) {
  std::vector<figment::Vec3> fineRest, fineDraped, normals;
  layout.apply(rest, fineRest, normals);
  layout.apply(draped, fineDraped, normals);
  return {fineRest, fineDraped};
}

// "No worse draped than at rest" within the cloth: the boundary's geodesic turning (its
// turning within the cloth, BoundaryTurning.h) depends on the triangles' edge lengths alone,
// so a drape moves it only by stretching the cloth. Each vertex's |geodesic| draped is then
// at most its rest value plus what the edges' measured strains allow it to move
// (geodesicStrainAllowance, first order: a worst case summed over the fan, whose slack
// covers the second-order terms at the drapes' strains of a few per cent), and so is the
// median. The folds of a drape turn a hem with the cloth (the normal part), which this does
// not count: the 3D medians above do. `what` names the mesh in failures and properties.
void expectNoWorseWithinTheCloth(const std::vector<figment::Triangle>& faces, const std::vector<figment::Vec3>& rest,
                                 const std::vector<figment::Vec3>& draped, const std::string& what) {
  const figment::BoundaryTurning turning(faces);
  const figment::BoundaryTurning::Summary atRest = turning.summary(rest), asDraped = turning.summary(draped);
  const std::vector<double> allowance = turning.geodesicStrainAllowance(rest, draped);
  std::vector<double> allowed;
  for (const std::vector<figment::BoundaryTurning::Turn>& loop : turning.turns(rest))
    for (const figment::BoundaryTurning::Turn& turn : loop)
      allowed.push_back(std::abs(turn.geodesic) + allowance[allowed.size()]);
  EXPECT_LE(asDraped.geodesic, figment::BoundaryTurning::median(allowed)) << what << ": at rest " << atRest.geodesic;
  // Within the cloth, the same bound: a smooth cut runs within twice a circle's turning there
  // too (round a body, next to none), a zig-zag cut does not (42 degrees, the old T-shirt's).
  EXPECT_LE(atRest.geodesic, kRoundness * roundTurning(rest, turning.loops())) << what;
  EXPECT_LE(asDraped.geodesic, kRoundness * roundTurning(draped, turning.loops())) << what;
  EXPECT_LE(asDraped.zigZagShare, atRest.zigZagShare + kZigZagNoise) << what;
  ::testing::Test::RecordProperty(what + "GeodesicRest", std::to_string(atRest.geodesic));
  ::testing::Test::RecordProperty(what + "GeodesicDraped", std::to_string(asDraped.geodesic));
  ::testing::Test::RecordProperty(what + "GeodesicAllowed", std::to_string(figment::BoundaryTurning::median(allowed)));
  ::testing::Test::RecordProperty(what + "ZigZagRest", std::to_string(atRest.zigZagShare));
  ::testing::Test::RecordProperty(what + "ZigZagDraped", std::to_string(asDraped.zigZagShare));
}

// Sets the scene's CatalogueGarment to `garment`.
void wear(SoNode* root, const std::string& garment) {
  SoSearchAction search;
  search.setType(CatalogueGarment::getClassTypeId());
  search.setSearchingAll(TRUE);  // it sits in a Switch that draws nothing
  search.apply(root);
  ASSERT_NE(search.getPath(), nullptr) << "no CatalogueGarment";
  static_cast<CatalogueGarment*>(search.getPath()->getTail())->garment = garment.c_str();
}

class GarmentEdges : public ::testing::TestWithParam<ShippedGarment> {};

TEST_P(GarmentEdges, TurnLittleAtRestAndDraped) {
  const std::string& model = GetParam().model;
  if (model.empty() ? figment::findMakeHumanData().empty() : figment::findModelFile(model).empty())
    GTEST_SKIP() << (model.empty() ? "MakeHuman's data" : model) << " not found";
  const ShippedGarmentScene scene(GetParam().scene);
  ASSERT_NE(scene.engine(), nullptr);
  ClothEngine& engine = *scene.engine();
  GetParam().configure(engine);
  if (!GetParam().catalogueGarment.empty()) wear(scene.root(), GetParam().catalogueGarment);
  const std::vector<figment::Triangle> faces =
      figment::garmentFromFields(engine.restPoints, engine.coordIndex).triangles;
  const Turning rest = turningOf(points(engine.restPoints), faces);
  SoMFVec3f positions;
  positions.connectFrom(&engine.positions);
  positions.evaluate();
  ASSERT_EQ(engine.lastError(), "");
  const Turning draped = turningOf(points(positions), faces);
  EXPECT_LE(rest.median, rest.bound);
  EXPECT_LE(draped.median, draped.bound) << "at rest " << rest.median;
  expectZigZagFails(points(engine.restPoints), faces, "at rest");
  expectZigZagFails(points(positions), faces, "draped");
  RecordProperty("restDegrees", std::to_string(rest.median));
  RecordProperty("restBound", std::to_string(rest.bound));
  RecordProperty("drapedDegrees", std::to_string(draped.median));
  RecordProperty("drapedBound", std::to_string(draped.bound));
  // What the picture shows with a display mesh (ClothingLayer.displaySubdivision).
  for (int levels : {1, 2}) {
    const Turning displayRest = displayTurning(points(engine.restPoints), faces, levels);
    const Turning displayDraped = displayTurning(points(positions), faces, levels);
    EXPECT_LT(displayRest.median, rest.median) << levels << " levels";
    EXPECT_LT(displayDraped.median, draped.median) << levels << " levels";
    EXPECT_LE(displayRest.median, displayRest.bound) << levels << " levels";
    EXPECT_LE(displayDraped.median, displayDraped.bound) << levels << " levels";
    RecordProperty("displayRestDegrees" + std::to_string(levels), std::to_string(displayRest.median));
    RecordProperty("displayDrapedDegrees" + std::to_string(levels), std::to_string(displayDraped.median));
  }
  expectNoWorseWithinTheCloth(faces, points(engine.restPoints), points(positions), "simulation");
  for (int levels : {1, 2}) {
    const figment::DisplaySubdivision layout(faces, points(engine.restPoints), levels);
    const auto [fineRest, fineDraped] = displayMeshes(layout, points(engine.restPoints), points(positions));
    expectNoWorseWithinTheCloth(layout.triangles(), fineRest, fineDraped, "display" + std::to_string(levels));
  }
}

void asShipped(ClothEngine&) {}

// Medians measured (degrees, rest / draped) on the garments this test was written with
// (the T-shirt's before its openings were cut along surfaces: 48.6 / 51.7).
INSTANTIATE_TEST_SUITE_P(Scenes, GarmentEdges,
                         ::testing::Values(ShippedGarment{"dress.iv", "human.zae", asShipped},   // 12.8 / 10.9
                                           ShippedGarment{"tshirt.iv", "human.zae", asShipped},  // 8.9 / 9.9
                                           // The scene's Heun at 1.5e-4 s takes 33,000 steps: the implicit step of
                                           // test_ShippedDrapes drapes the same skirt onto the hips.
                                           ShippedGarment{"skirt.iv", "human.zae",
                                                          [](ClothEngine& engine) {
                                                            engine.integrator = ClothEngine::IMPLICIT;
                                                            engine.timeStep = 0.05;
                                                            engine.maxTime = 10.0;
                                                          }},                                           // 8.6 / 13.6
                                           ShippedGarment{"human-body.iv", "", asShipped},              // 10.1 / 12.3
                                           ShippedGarment{"second-body.iv", "HUMAN.blend", asShipped},  // 11.1 / 16.9
                                           // Draped in their poses.
                                           ShippedGarment{"human-posed-arm.iv", "", asShipped},      // 8.8 / 9.8
                                           ShippedGarment{"human-posed-sitting.iv", "", asShipped},  // 9.5 / 7.6
                                           ShippedGarment{"human-posed-walk.iv", "", asShipped},     // 10.1 / 8.3
                                           // The catalogue's styles on the chart's XL body (MakeHuman's): the pencil
                                           // skirt in S as the scene has it (7.3 / 8.1), the others in the body's
                                           // size: the dress 10.3 / 13.1, the flared skirt 9.6 / 11.9, the T-shirt
                                           // 9.3 / 13.9.
                                           ShippedGarment{"sizes/pencil-S-on-XL.iv", "", asShipped},
                                           ShippedGarment{"sizes/pencil-S-on-XL.iv", "", asShipped, "dress:XL"},
                                           ShippedGarment{"sizes/pencil-S-on-XL.iv", "", asShipped, "skirt:XL"},
                                           ShippedGarment{"sizes/pencil-S-on-XL.iv", "", asShipped, "tshirt:XL"}),
                         [](const ::testing::TestParamInfo<ShippedGarment>& param) {
                           std::string name = param.param.scene.substr(0, param.param.scene.find('.'));
                           if (!param.param.catalogueGarment.empty()) name = param.param.catalogueGarment;
                           std::erase_if(name, [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); });
                           return name;
                         });

}  // namespace
