// GarmentCode's specification JSON read as GarmentCode reads it (io/PatternFile.cpp lists
// where each convention was checked): shipped patterns read whole, control points land
// where GarmentCode puts them, units, placement and stitch flags; each kind of bad file
// refused with one line naming the file and the panel, edge or stitch.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "io/PatternFile.h"
#include "sim/pattern/EdgeCurves.h"

using namespace figment;

namespace {

const std::string kData = std::string(FIGMENT_SOURCE_DIR) + "/tests/io/data/patterns/";

// A 10 cm square, counter-clockwise.
const std::string kSquare = R"({"vertices": [[0, 0], [10, 0], [10, 10], [0, 10]],
  "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]}, {"endpoints": [3, 0]}]})";

std::string spec(const std::string& panels, const std::string& stitches = "[]",
                 const std::string& properties = R"({"units_in_meter": 100, "curvature_coords": "relative"})") {
  return R"({"pattern": {"panels": )" + panels + R"(, "stitches": )" + stitches + R"(}, "properties": )" + properties +
         "}";
}

// A panel "a" whose edge 0, from (0, 0) to (10, 0) cm, has this curvature (closed by three
// straight edges through (10, -10) and (0, -10), below the curve: a curve bulging up is
// clear of them).
std::string curvedPanel(const std::string& curvature) {
  return R"({"a": {"vertices": [[0, 0], [10, 0], [10, -10], [0, -10]],
    "edges": [{"endpoints": [0, 1], "curvature": )" +
         curvature + R"(}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]}, {"endpoints": [3, 0]}]}})";
}

// The one line a refused text gets, or "(read)".
std::string refusal(const std::string& text) {
  try {
    parsePattern(text, "p.json");
  } catch (const PatternError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    return what;
  }
  return "(read)";
}

}  // namespace

// The three shipped patterns as index.json counts them; every stitch pairs edges of like
// length (within the documented ratio, which the reader checks) and each panel's edges
// close.
TEST(PatternFile, ReadsShippedGarmentCodePatterns) {
  struct Case {
    const char* file;
    size_t panels, stitches, darts;
  };
  for (const Case& c :
       {Case{"circle-f-50_specification.json", 4, 6, 0}, Case{"tshirt-f-38_specification.json", 8, 16, 0},
        Case{"pencil-f-46_specification.json", 4, 16, 4}}) {
    const SewingPattern pattern = readPatternFile(kData + c.file);
    EXPECT_EQ(pattern.panels.size(), c.panels) << c.file;
    EXPECT_EQ(pattern.stitches.size(), c.stitches) << c.file;
    size_t darts = 0;
    for (const Stitch& s : pattern.stitches) darts += s.first.panel == s.second.panel;
    EXPECT_EQ(darts, c.darts) << c.file;
    for (const Panel& panel : pattern.panels)
      for (size_t k = 0; k < panel.edges.size(); ++k)
        EXPECT_EQ(panel.edges[k].to, panel.edges[(k + 1) % panel.edges.size()].from);
  }
  EXPECT_EQ(readPatternFile(kData + "circle-f-50_specification.json").name, "circle-f-50");
}

// GarmentCode's pencil skirt back: its hip curve (edge 1, a quadratic with relative
// control point (0.4978, 0.0553)) rises from the hip corner (0, 33.27) cm, above the
// straight side seam from (0, 0). With b to the left of s -> e (rel_to_abs_2d) its control
// point lies on that seam's line u = 0, so the side seam runs on smoothly into the curve;
// with b's sign flipped it would land 2.66 cm inside the panel, a kink at the hip.
TEST(PatternFile, ARelativeControlPointLandsWhereGarmentCodePutsIt) {
  const SewingPattern pattern = readPatternFile(kData + "pencil-f-46_specification.json");
  ASSERT_EQ(pattern.panels[0].name, "skirt_back");  // panel_order's first
  const PanelEdge& hip = pattern.panels[0].edges[1];
  ASSERT_EQ(hip.curve.kind, EdgeCurve::Kind::Quadratic);
  // By hand: s + a (e - s) + b (-(e - s).y, (e - s).x) with s = (0, 33.2678), e = (2.6685,
  // 57.2885) cm: (2.3e-7, 45.37301248) cm.
  EXPECT_NEAR(hip.curve.controls[0].x(), 0.0, 1e-8);
  EXPECT_NEAR(hip.curve.controls[0].y(), 0.4537301248, 1e-10);
}

// Circle params [radius, large_arc, right]: right bulges to the right of s -> e, here
// downwards (into the panel); left (right = 0) upwards, clear of the panel's other edges.
TEST(PatternFile, ACircleBulgesToTheSideItsFlagSays) {
  const SewingPattern left = parsePattern(spec(curvedPanel(R"({"type": "circle", "params": [5, 0, 0]})")), "p");
  EXPECT_NEAR((edgePoint(left.panels[0], 0, 0.5) - Vec2(0.05, 0.05)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(edgeLength(left.panels[0], 0), M_PI * 0.05, 1e-15);
  const SewingPattern right = parsePattern(spec(curvedPanel(R"({"type": "circle", "params": [13, 0, 1]})")), "p");
  // Sagitta of a 10 cm chord on a 13 cm circle: 13 - 12 = 1 cm, below the chord.
  EXPECT_NEAR((edgePoint(right.panels[0], 0, 0.5) - Vec2(0.05, -0.01)).norm(), 0.0, 1e-15);
}

TEST(PatternFile, ReadsEveryCurveFormAndUnit) {
  // Relative (0.5, 0.2): 2 cm to the left of (0, 0) -> (10, 0), i.e. up.
  const SewingPattern quadratic =
      parsePattern(spec(curvedPanel(R"({"type": "quadratic", "params": [[0.5, 0.2]]})")), "p");
  EXPECT_NEAR((quadratic.panels[0].edges[0].curve.controls[0] - Vec2(0.05, 0.02)).norm(), 0.0, 1e-15);
  // Older files: the bare pair.
  const SewingPattern bare = parsePattern(spec(curvedPanel("[0.5, 0.2]")), "p");
  EXPECT_EQ(bare.panels[0].edges[0].curve.controls[0], quadratic.panels[0].edges[0].curve.controls[0]);
  const SewingPattern cubic =
      parsePattern(spec(curvedPanel(R"({"type": "cubic", "params": [[0.25, 0.3], [0.75, 0.1]]})")), "p");
  ASSERT_EQ(cubic.panels[0].edges[0].curve.kind, EdgeCurve::Kind::Cubic);
  EXPECT_NEAR((cubic.panels[0].edges[0].curve.controls[0] - Vec2(0.025, 0.03)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((cubic.panels[0].edges[0].curve.controls[1] - Vec2(0.075, 0.01)).norm(), 0.0, 1e-15);
  // Absolute control points in millimetres.
  const SewingPattern absolute = parsePattern(spec(curvedPanel(R"({"type": "quadratic", "params": [[50, 20]]})"), "[]",
                                                   R"({"units_in_meter": 1000, "curvature_coords": "absolute"})"),
                                              "p");
  EXPECT_NEAR((absolute.panels[0].vertices[1] - Vec2(0.01, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((absolute.panels[0].edges[0].curve.controls[0] - Vec2(0.05, 0.02)).norm(), 0.0, 1e-15);
  // No properties: centimetres, relative.
  const SewingPattern plain = parsePattern(R"({"pattern": {"panels": {"a": )" + kSquare + "}}}", "p");
  EXPECT_NEAR((plain.panels[0].vertices[2] - Vec2(0.1, 0.1)).norm(), 0.0, 1e-15);
}

// rotation [rx, ry, rz] in degrees is Rz Ry Rx: with [90, 90, 0] the panel's v axis goes
// to +z under Rx, then to +x under Ry (Rx Ry would leave it at +z), and its u axis, kept
// by Rx, to -z; translation in cm.
TEST(PatternFile, PlacesPanelsAsGarmentCodeDoes) {
  const std::string panel = R"({"a": {"translation": [10, 150, -20], "rotation": [90, 90, 0],
    "vertices": [[0, 0], [10, 0], [10, 10], [0, 10]],
    "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]}, {"endpoints": [3, 0]}]}})";
  // The pattern held by name: a reference into the temporary's panels dangled (ASan).
  const SewingPattern pattern = parsePattern(spec(panel), "p");
  const Panel& placed = pattern.panels[0];
  EXPECT_NEAR((placed.rotation * Vec3(0, 1, 0) - Vec3(1, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((placed.rotation * Vec3(1, 0, 0) - Vec3(0, 0, -1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((placed.translation - Vec3(0.1, 1.5, -0.2)).norm(), 0.0, 1e-15);
}

TEST(PatternFile, ReadsStitchDirectionAndPanelOrder) {
  const std::string panels = R"({"b": )" + kSquare + R"(, "a": )" + kSquare + "}";
  const std::string stitches = R"([[{"panel": "a", "edge": 1}, {"panel": "b", "edge": 3}],
    [{"panel": "a", "edge": 0}, {"panel": "b", "edge": 0}, "right_wrong"]])";
  const SewingPattern sorted = parsePattern(spec(panels, stitches), "p");
  ASSERT_EQ(sorted.panels.size(), 2u);
  EXPECT_EQ(sorted.panels[0].name, "a");  // no panel_order: by name
  ASSERT_EQ(sorted.stitches.size(), 2u);
  EXPECT_FALSE(sorted.stitches[0].sameDirection);
  EXPECT_TRUE(sorted.stitches[1].sameDirection);
  EXPECT_EQ(sorted.stitches[0].first.panel, 0);
  EXPECT_EQ(sorted.stitches[0].first.edge, 1);
  EXPECT_EQ(sorted.stitches[0].second.panel, 1);
  EXPECT_EQ(sorted.stitches[0].second.edge, 3);
  const std::string ordered = R"({"pattern": {"panel_order": ["b", "a"], "panels": )" + panels + "}}";
  EXPECT_EQ(parsePattern(ordered, "p").panels[0].name, "b");
}

TEST(PatternFile, RefusesWhatIsNotAPattern) {
  EXPECT_EQ(refusal("{\"pattern\": "), "p.json: not JSON (syntax error at byte 13)");
  EXPECT_EQ(refusal("[1, 2]"), "p.json: not a pattern specification (not a JSON object)");
  EXPECT_EQ(refusal(R"({"pattern": {"stitches": []}})"), "p.json: pattern.panels: missing, empty or not an object");
  EXPECT_EQ(refusal(R"({"pattern": {"panels": {}}})"), "p.json: pattern.panels: missing, empty or not an object");
  try {
    readPatternFile(kData + "no-such_specification.json");
    ADD_FAILURE() << "read a missing file";
  } catch (const PatternError& e) {
    EXPECT_EQ(std::string(e.what()), kData + "no-such_specification.json: cannot open the file");
  }
}

TEST(PatternFile, RefusesAPanelThatIsNotAClosedOutline) {
  EXPECT_EQ(refusal(spec(R"({"a": {"vertices": [[0, 0], [1, 0]], "edges": [{"endpoints": [0, 1]},
    {"endpoints": [1, 0]}]}})")),
            "p.json: panel \"a\": 2 vertices, fewer than 3");
  EXPECT_EQ(refusal(spec(R"({"a": {"vertices": [[0, 0], [10, 0], [10, 10], [0, 10]],
    "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [3, 2]}, {"endpoints": [3, 0]}]}})")),
            "p.json: panel \"a\" edge 1: ends at vertex 2 but edge 2 starts at vertex 3: the edges are not a closed "
            "loop");
  EXPECT_EQ(refusal(spec(R"({"a": {"vertices": [[0, 0], [10, 0], [10, 10], [0, 10]],
    "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 4]}, {"endpoints": [4, 3]}, {"endpoints": [3, 0]}]}})")),
            "p.json: panel \"a\" edge 1: endpoint 4 is out of range (0 to 3)");
  // A bow tie: (0,0) (10,0) (0,10) (10,10) crosses between edges 1 and 3.
  EXPECT_EQ(refusal(spec(R"({"a": {"vertices": [[0, 0], [10, 0], [0, 10], [10, 10]],
    "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]}, {"endpoints": [3, 0]}]}})")),
            "p.json: panel \"a\": the outline crosses itself (edges 1 and 3)");
  // A curve that swings through a straight edge: the quadratic's control point 30 cm down.
  EXPECT_EQ(refusal(spec(curvedPanel("[0.5, -3]"))), "p.json: panel \"a\": the outline crosses itself (edges 0 and 2)");
}

TEST(PatternFile, RefusesABadCurveOrNumber) {
  EXPECT_EQ(refusal(spec(curvedPanel(R"({"type": "spline", "params": []})"))),
            "p.json: panel \"a\" edge 0: unknown curvature type \"spline\"");
  EXPECT_EQ(refusal(spec(curvedPanel(R"({"type": "circle", "params": [4, 0, 1]})"))),
            "p.json: panel \"a\" edge 0: circle radius 0.04 m is less than half its chord 0.05 m");
  EXPECT_EQ(refusal(spec(curvedPanel(R"({"type": "circle", "params": [1e999, 0, 1]})"))),
            "p.json: not JSON (a number out of range)");
  EXPECT_EQ(refusal(spec(curvedPanel(R"({"type": "circle", "params": ["5", 0, 1]})"))),
            "p.json: panel \"a\" edge 0: circle radius is not a number");
  EXPECT_EQ(refusal(spec(R"({"a": {"vertices": [[0, 0], [1e6, 0], [10, 10]],
    "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 0]}]}})")),
            "p.json: panel \"a\" vertex 1: position 10000 m is beyond 1000 m");
  EXPECT_EQ(refusal(spec(R"({"a": {"vertices": [[0, 0], [10, 0], [10, 0], [0, 10]],
    "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]}, {"endpoints": [3, 0]}]}})")),
            "p.json: panel \"a\" edge 1: length 0 m, shorter than 1e-06 m");
}

TEST(PatternFile, RefusesABadStitch) {
  const std::string panels = R"({"a": )" + kSquare + R"(, "b": )" + kSquare + "}";
  EXPECT_EQ(refusal(spec(panels, R"([[{"panel": "a", "edge": 0}, {"panel": "c", "edge": 0}]])")),
            "p.json: stitch 0: panel \"c\" does not exist");
  EXPECT_EQ(refusal(spec(panels, R"([[{"panel": "a", "edge": 0}, {"panel": "b", "edge": 4}]])")),
            "p.json: stitch 0 panel \"b\": edge 4 is out of range (0 to 3)");
  EXPECT_EQ(refusal(spec(panels, R"([[{"panel": "a", "edge": 0}, {"panel": "b", "edge": 0}],
    [{"panel": "b", "edge": 2}, {"panel": "a", "edge": 0}]])")),
            "p.json: stitch 1: panel \"a\" edge 0 is already in stitch 0: an edge is sewn to one other edge");
  EXPECT_EQ(refusal(spec(panels, R"([[{"panel": "a", "edge": 0}, {"panel": "b", "edge": 0}, "inside_out"]])")),
            "p.json: stitch 0: third element \"inside_out\" is not \"right_wrong\"");
  // A 10 cm edge sewn to a 50 cm one: a ratio of 5, past the limit of 4.
  const std::string wide = R"({"a": )" + kSquare + R"(, "w": {"vertices": [[0, 0], [50, 0], [50, 10], [0, 10]],
    "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]}, {"endpoints": [3, 0]}]}})";
  EXPECT_EQ(refusal(spec(wide, R"([[{"panel": "a", "edge": 0}, {"panel": "w", "edge": 0}]])")),
            "p.json: stitch 0: panel \"a\" edge 0 (0.1 m) and panel \"w\" edge 0 (0.5 m) differ in length by a ratio "
            "of 5, more than 4");
  // A gather of 3 (GarmentCode's largest) is a seam.
  const std::string gathered = R"({"a": )" + kSquare + R"(, "g": {"vertices": [[0, 0], [30, 0], [30, 10], [0, 10]],
    "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]}, {"endpoints": [3, 0]}]}})";
  EXPECT_EQ(refusal(spec(gathered, R"([[{"panel": "a", "edge": 0}, {"panel": "g", "edge": 0}]])")), "(read)");
}

// GarmentCode's pencil skirt for women's 54 as GarmentCode wrote it: its front waistband's
// two nearly straight edges (62 cm chords on 8 m circles) flagged as large arcs, 50 m loops
// that cross the panel. Refused, not sewn (scenes/patterns ships the file mended, below).
TEST(PatternFile, RefusesAFlatArcFlaggedLarge) {
  EXPECT_EQ(refusal(spec(R"({"wb_front": {"vertices": [[-0.17317810895712427, 0], [0.0017606091853714645,
    -4.57201956856449], [61.99823939081463, -4.57201956856449], [62.173178108957124, 0]],
    "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2], "curvature": {"type": "circle",
    "params": [810.7311321402475, 1, 0]}}, {"endpoints": [2, 3]}, {"endpoints": [3, 0], "curvature":
    {"type": "circle", "params": [815.3064973158856, 1, 1]}}]}})")),
            "p.json: panel \"wb_front\": the outline crosses itself (edges 1 and 3)");
}

// The shipped pencil 54, mended (scenes/patterns/README.md): read as the small arcs its
// grading runs to. The waistband front's lower edge is as long as the skirt front's top
// edge it is sewn to, and the skirt hangs where the 50 and 52 put theirs, not 8 m up where
// GarmentCode placed it under the 50 m loop.
TEST(PatternFile, TheShippedPencil54IsMendedAsItsGradingRuns) {
  const std::string folder = std::string(FIGMENT_SOURCE_DIR) + "/scenes/patterns/pencil/";
  const auto panel = [](const SewingPattern& pattern, const std::string& name) -> const Panel& {
    for (const Panel& p : pattern.panels)
      if (p.name == name) return p;
    throw std::runtime_error("no panel " + name);
  };
  const SewingPattern p50 = readPatternFile(folder + "pencil-f-50_specification.json");
  const SewingPattern p52 = readPatternFile(folder + "pencil-f-52_specification.json");
  const SewingPattern p54 = readPatternFile(folder + "pencil-f-54_specification.json");
  const Panel& band = panel(p54, "wb_front");
  const Panel& skirt = panel(p54, "skirt_front");
  EXPECT_NEAR(edgeLength(band, 1), edgeLength(skirt, 3), 0.01 * edgeLength(skirt, 3));
  for (const char* name : {"skirt_front", "skirt_back"}) {
    const double y50 = panel(p50, name).translation.y(), y52 = panel(p52, name).translation.y();
    EXPECT_NEAR(panel(p54, name).translation.y(), 2.0 * y52 - y50, 0.01) << name;
  }
}
