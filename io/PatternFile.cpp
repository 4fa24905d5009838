// GarmentCode's conventions, as its own code applies them (github.com/maria-korosteleva/
// GarmentCode, commit d449629, the one the shipped patterns were made with; MIT). Read to
// learn, not copied:
// - Relative control points (pygarment/pattern/utils.py, rel_to_abs_2d): for an edge from
//   s to e, (a, b) is s + a (e - s) + b perp(e - s) with perp(x, y) = (-y, x): b > 0 lies to
//   the LEFT of s -> e with the panel's v axis up. The `_flip_y` that
//   pygarment/pattern/core.py's `_edge_as_curve` applies to b is a drawing concern: only
//   VisPattern (pygarment/pattern/wrappers.py) defines it, and it draws the panel with v
//   negated (SVG's y runs down), where negating b keeps the point in place. The mesher
//   that sews (pygarment/meshgen/boxmeshgen.py, Edge.init_curve) uses rel_to_abs_2d
//   unflipped ("#maya: self.flip_y(p)" commented out). Quadratic edges also come as a bare
//   [a, b] list (older files; both readers accept it).
// - Circles (pygarment/garmentcode/edge.py, CircleEdge.as_radius_flag and assembly):
//   params are [radius, large_arc, right] with right = control_y < 0, the arc's middle
//   being rel_to_abs_2d(s, e, [0.5, control_y]): `right` bulges to the RIGHT of s -> e
//   (v up). boxmeshgen.py draws it as svgpathtools.Arc(..., large_arc, sweep=right) in
//   the same unflipped frame: counter-clockwise when right. edge_factory.py's
//   CircleEdgeFactory.from_points_radius takes a radius a rounding under half the chord
//   as a half circle.
// - Placement (pygarment/pattern/core.py, _point_in_3D; pygarment/pattern/rotation.py,
//   euler_xyz_to_R): a panel point (u, v) lands at R (u, v, 0) + translation with
//   "rotation" in degrees and R = Rz(rz) Ry(ry) Rx(rx) (Maya's xyz order: x applied first).
// - Units: properties.units_in_meter (core.py `_normalize_template`; 100, cm, when absent);
//   curvature_coords "absolute" gives control points in panel coordinates.
// - Stitches (boxmeshgen.py, read_stitches and Seam): by default the end of one edge meets
//   the start of the other (`swap`, right sides of the fabric together); a third element
//   "right_wrong" keeps the direction. An edge in two stitches is refused there
//   (MultiStitchingError); the shipped patterns have none.
#include "io/PatternFile.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "sim/pattern/EdgeCurves.h"

namespace figment {

namespace {

using nlohmann::json;

// Panel coordinates at which an outline is tested for crossing itself: a curved edge as
// this many chords of equal arc length (a straight edge is one).
constexpr int kOutlineChords = 24;

std::string quoted(const std::string& text) {
  // JSON's escaping keeps a name with control characters on one line.
  return json(text).dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string number(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw PatternError(file_ + ": " + where + ": " + what);
  }

  SewingPattern read(const std::string& text) {
    json doc;
    try {
      doc = json::parse(text);
    } catch (const json::parse_error& e) {
      throw PatternError(file_ + ": not JSON (syntax error at byte " + std::to_string(e.byte) + ")");
    } catch (const json::out_of_range&) {
      throw PatternError(file_ + ": not JSON (a number out of range)");  // 1e999: JSON has no infinity
    }
    if (!doc.is_object()) throw PatternError(file_ + ": not a pattern specification (not a JSON object)");
    readProperties(doc);
    const json* pattern = member(doc, "pattern");
    if (!pattern || !pattern->is_object()) fail("pattern", "missing, or not an object");
    const json* panels = member(*pattern, "panels");
    if (!panels || !panels->is_object() || panels->empty()) fail("pattern.panels", "missing, empty or not an object");

    SewingPattern result;
    for (const std::string& name : panelOrder(*pattern, *panels))
      result.panels.push_back(readPanel(name, (*panels)[name]));
    for (int p = 0; p < static_cast<int>(result.panels.size()); ++p) panelIndex_[result.panels[p].name] = p;
    if (const json* stitches = member(*pattern, "stitches")) {
      if (!stitches->is_array()) fail("pattern.stitches", "not a list");
      for (size_t k = 0; k < stitches->size(); ++k)
        result.stitches.push_back(readStitch(result, static_cast<int>(k), (*stitches)[k]));
    }
    return result;
  }

 private:
  static const json* member(const json& object, const char* key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  double finite(const json& value, const std::string& where, const std::string& what) const {
    if (!value.is_number()) fail(where, what + " is not a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(where, what + " is not finite");
    return x;
  }

  // A length in file units as metres, bounded by kMaxCoordinate.
  double metres(const json& value, const std::string& where, const std::string& what) const {
    const double x = finite(value, where, what) * scale_;
    if (!(std::abs(x) <= kMaxCoordinate))
      fail(where, what + " " + number(x) + " m is beyond " + number(kMaxCoordinate) + " m");
    return x;
  }

  int index(const json& value, long long size, const std::string& where, const std::string& what) const {
    if (!value.is_number_integer()) fail(where, what + " is not a whole number");
    const bool negative = value.is_number_unsigned() ? false : value.get<long long>() < 0;
    if (negative || value.get<unsigned long long>() >= static_cast<unsigned long long>(size))
      fail(where, what + " " + value.dump() + " is out of range (0 to " + std::to_string(size - 1) + ")");
    return static_cast<int>(value.get<long long>());
  }

  Vec2 pair(const json& value, const std::string& where, const std::string& what, bool inMetres) const {
    if (!value.is_array() || value.size() != 2) fail(where, what + " is not a pair of numbers");
    if (inMetres) return Vec2(metres(value[0], where, what), metres(value[1], where, what));
    return Vec2(finite(value[0], where, what), finite(value[1], where, what));
  }

  void readProperties(const json& doc) {
    const json* properties = member(doc, "properties");
    if (!properties) return;
    if (!properties->is_object()) fail("properties", "not an object");
    if (const json* units = member(*properties, "units_in_meter")) {
      const double perMetre = finite(*units, "properties", "units_in_meter");
      if (!(perMetre > 0.0)) fail("properties", "units_in_meter " + number(perMetre) + " is not positive");
      scale_ = 1.0 / perMetre;
    }
    if (const json* coords = member(*properties, "curvature_coords")) {
      if (*coords == "absolute")
        relative_ = false;
      else if (*coords != "relative")
        fail("properties", "curvature_coords " + coords->dump() + " is neither \"relative\" nor \"absolute\"");
    }
  }

  std::vector<std::string> panelOrder(const json& pattern, const json& panels) const {
    std::vector<std::string> order;
    const json* listed = member(pattern, "panel_order");
    if (!listed) {
      for (const auto& [name, panel] : panels.items()) order.push_back(name);  // sorted: json objects are maps
      return order;
    }
    if (!listed->is_array()) fail("pattern.panel_order", "not a list");
    for (const json& name : *listed) {
      if (!name.is_string()) fail("pattern.panel_order", name.dump() + " is not a panel name");
      const std::string text = name.get<std::string>();
      if (!panels.contains(text)) fail("pattern.panel_order", quoted(text) + " is not a panel");
      if (std::find(order.begin(), order.end(), text) != order.end())
        fail("pattern.panel_order", quoted(text) + " is listed twice");
      order.push_back(text);
    }
    for (const auto& [name, panel] : panels.items())
      if (std::find(order.begin(), order.end(), name) == order.end())
        fail("panel " + quoted(name), "not in pattern.panel_order");
    return order;
  }

  Panel readPanel(const std::string& name, const json& spec) {
    const std::string where = "panel " + quoted(name);
    if (!spec.is_object()) fail(where, "not an object");
    Panel panel;
    panel.name = name;
    const json* vertices = member(spec, "vertices");
    if (!vertices || !vertices->is_array()) fail(where, "no list of vertices");
    if (vertices->size() < 3) fail(where, std::to_string(vertices->size()) + " vertices, fewer than 3");
    for (size_t v = 0; v < vertices->size(); ++v)
      panel.vertices.push_back(pair((*vertices)[v], where + " vertex " + std::to_string(v), "position", true));

    const json* edges = member(spec, "edges");
    if (!edges || !edges->is_array()) fail(where, "no list of edges");
    const long long n = static_cast<long long>(panel.vertices.size());
    for (size_t k = 0; k < edges->size(); ++k) {
      const std::string at = where + " edge " + std::to_string(k);
      const json& edge = (*edges)[k];
      if (!edge.is_object()) fail(at, "not an object");
      const json* ends = member(edge, "endpoints");
      if (!ends || !ends->is_array() || ends->size() != 2) fail(at, "endpoints is not a pair of vertex indices");
      PanelEdge pe;
      pe.from = index((*ends)[0], n, at, "endpoint");
      pe.to = index((*ends)[1], n, at, "endpoint");
      panel.edges.push_back(pe);
    }
    checkLoop(panel, where);
    for (size_t k = 0; k < edges->size(); ++k) {
      const std::string at = where + " edge " + std::to_string(k);
      if (const json* curvature = member((*edges)[k], "curvature"))
        panel.edges[k].curve = readCurve(panel, static_cast<int>(k), *curvature, at);
      double length = 0.0;
      try {
        length = edgeLength(panel, static_cast<int>(k));
      } catch (const std::invalid_argument& e) {
        fail(at, e.what());  // what EdgeCurves checks and readCurve already has: kept as a guard
      }
      if (!(length >= kMinEdgeLength))
        fail(at, "length " + number(length) + " m, shorter than " + number(kMinEdgeLength) + " m");
      lengths_[{name, static_cast<int>(k)}] = length;
    }
    checkOutline(panel, where);

    if (const json* translation = member(spec, "translation")) {
      if (!translation->is_array() || translation->size() != 3) fail(where, "translation is not 3 numbers");
      for (int i = 0; i < 3; ++i) panel.translation[i] = metres((*translation)[i], where, "translation");
    }
    if (const json* rotation = member(spec, "rotation")) {
      if (!rotation->is_array() || rotation->size() != 3) fail(where, "rotation is not 3 angles");
      double angle[3];
      for (int i = 0; i < 3; ++i) angle[i] = finite((*rotation)[i], where, "rotation") * M_PI / 180.0;
      panel.rotation = (Eigen::AngleAxisd(angle[2], Vec3::UnitZ()) * Eigen::AngleAxisd(angle[1], Vec3::UnitY()) *
                        Eigen::AngleAxisd(angle[0], Vec3::UnitX()))
                           .toRotationMatrix();
    }
    return panel;
  }

  // One closed loop through every vertex once: edge k ends where edge k + 1 starts.
  void checkLoop(const Panel& panel, const std::string& where) const {
    const size_t n = panel.edges.size();
    if (n != panel.vertices.size())
      fail(where, std::to_string(n) + " edges for " + std::to_string(panel.vertices.size()) +
                      " vertices: not one closed loop through every vertex");
    std::vector<bool> started(n, false);
    for (size_t k = 0; k < n; ++k) {
      const PanelEdge& edge = panel.edges[k];
      const PanelEdge& next = panel.edges[(k + 1) % n];
      if (edge.to != next.from)
        fail(where + " edge " + std::to_string(k), "ends at vertex " + std::to_string(edge.to) + " but edge " +
                                                       std::to_string((k + 1) % n) + " starts at vertex " +
                                                       std::to_string(next.from) + ": the edges are not a closed loop");
      if (started[edge.from])
        fail(where + " edge " + std::to_string(k),
             "starts at vertex " + std::to_string(edge.from) + " again: the loop passes a vertex twice");
      started[edge.from] = true;
    }
  }

  EdgeCurve readCurve(const Panel& panel, int k, const json& spec, const std::string& at) const {
    const Vec2 s = panel.vertices[panel.edges[k].from], e = panel.vertices[panel.edges[k].to];
    EdgeCurve curve;
    // A control point: relative to the edge (utils.py rel_to_abs_2d) or in file units.
    const auto control = [&](const json& value) -> Vec2 {
      if (!relative_) return pair(value, at, "control point", true);
      const Vec2 ab = pair(value, at, "control point", false);
      const Vec2 d = e - s;
      const Vec2 c = s + ab.x() * d + ab.y() * Vec2(-d.y(), d.x());
      if (!(c.cwiseAbs().maxCoeff() <= kMaxCoordinate))
        fail(at, "control point (" + number(ab.x()) + ", " + number(ab.y()) + ") lands beyond " +
                     number(kMaxCoordinate) + " m");
      return c;
    };
    if (spec.is_array()) {  // older files: a quadratic's one relative control point
      curve.kind = EdgeCurve::Kind::Quadratic;
      curve.controls = {control(spec)};
      return curve;
    }
    if (!spec.is_object()) fail(at, "curvature is neither an object nor a pair of numbers");
    const json* type = member(spec, "type");
    const json* params = member(spec, "params");
    if (!type || !type->is_string()) fail(at, "curvature has no type");
    if (!params || !params->is_array()) fail(at, "curvature has no list of params");
    const std::string kind = type->get<std::string>();
    if (kind == "quadratic" || kind == "cubic") {
      const size_t count = kind == "quadratic" ? 1 : 2;
      if (params->size() != count)
        fail(at, kind + " curvature has " + std::to_string(params->size()) + " control points, not " +
                     std::to_string(count));
      curve.kind = count == 1 ? EdgeCurve::Kind::Quadratic : EdgeCurve::Kind::Cubic;
      for (const json& p : *params) curve.controls.push_back(control(p));
      return curve;
    }
    if (kind != "circle") fail(at, "unknown curvature type " + quoted(kind));
    if (params->size() != 3) fail(at, "circle params are not [radius, large_arc, right]");
    const auto flag = [&](const json& value, const char* what) {
      if (value.is_boolean()) return value.get<bool>();
      if (value.is_number() && (value == 0 || value == 1)) return value == 1;
      fail(at, std::string("circle ") + what + " " + value.dump() + " is neither 0 nor 1");
    };
    curve.kind = EdgeCurve::Kind::Circle;
    curve.radius = metres((*params)[0], at, "circle radius");
    curve.largeArc = flag((*params)[1], "large_arc");
    curve.right = flag((*params)[2], "right");
    const double chord = (e - s).norm();
    if (!(chord > 0.0)) fail(at, "a circular arc between coincident vertices");
    if (curve.radius < 0.5 * chord * (1.0 - kArcRadiusSlack))
      fail(at,
           "circle radius " + number(curve.radius) + " m is less than half its chord " + number(0.5 * chord) + " m");
    return curve;
  }

  // The outline, each curved edge as chords of equal arc length, must not cross or touch
  // itself: two chords that are not neighbours share no point, and neighbours only their
  // common vertex (no folding back along each other).
  void checkOutline(const Panel& panel, const std::string& where) const {
    struct Chord {
      Vec2 a, b;
      int edge;
    };
    std::vector<Chord> chords;
    for (int k = 0; k < static_cast<int>(panel.edges.size()); ++k) {
      const int count = panel.edges[k].curve.kind == EdgeCurve::Kind::Straight ? 1 : kOutlineChords;
      const std::vector<Vec2> points = sampleEdge(panel, k, count);
      for (int j = 0; j < count; ++j) chords.push_back({points[j], points[j + 1], k});
    }
    const size_t n = chords.size();
    const auto cross = [](const Vec2& o, const Vec2& a, const Vec2& b) {
      return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
    };
    const auto sign = [](double x) { return (x > 0.0) - (x < 0.0); };
    // p on the closed segment [a, b], given that it is collinear with it.
    const auto within = [](const Vec2& a, const Vec2& b, const Vec2& p) {
      return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
             p.y() <= std::max(a.y(), b.y());
    };
    const auto meet = [&](const Chord& u, const Chord& v) {
      const int d1 = sign(cross(u.a, u.b, v.a)), d2 = sign(cross(u.a, u.b, v.b));
      const int d3 = sign(cross(v.a, v.b, u.a)), d4 = sign(cross(v.a, v.b, u.b));
      if (d1 * d2 < 0 && d3 * d4 < 0) return true;
      return (d1 == 0 && within(u.a, u.b, v.a)) || (d2 == 0 && within(u.a, u.b, v.b)) ||
             (d3 == 0 && within(v.a, v.b, u.a)) || (d4 == 0 && within(v.a, v.b, u.b));
    };
    const auto report = [&](const Chord& u, const Chord& v) {
      const int a = std::min(u.edge, v.edge), b = std::max(u.edge, v.edge);
      if (a == b) fail(where + " edge " + std::to_string(a), "the edge crosses itself");
      fail(where, "the outline crosses itself (edges " + std::to_string(a) + " and " + std::to_string(b) + ")");
    };
    for (size_t i = 0; i < n; ++i) {
      // Neighbours: folding back means the next chord's end lies on this one, collinear.
      const Chord& u = chords[i];
      const Chord& next = chords[(i + 1) % n];
      if (cross(u.a, u.b, next.b) == 0.0 && (u.b - u.a).dot(next.b - next.a) < 0.0) report(u, next);
    }
    // Sweep along u: only chords whose u ranges overlap can meet.
    std::vector<size_t> order(n);
    for (size_t i = 0; i < n; ++i) order[i] = i;
    const auto low = [&](size_t i) { return std::min(chords[i].a.x(), chords[i].b.x()); };
    const auto high = [&](size_t i) { return std::max(chords[i].a.x(), chords[i].b.x()); };
    std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return low(i) < low(j); });
    for (size_t x = 0; x < n; ++x) {
      const size_t i = order[x];
      for (size_t y = x + 1; y < n && low(order[y]) <= high(i); ++y) {
        const size_t j = order[y];
        if ((i + 1) % n == j || (j + 1) % n == i) continue;  // neighbours share their vertex
        if (meet(chords[i], chords[j])) report(chords[i], chords[j]);
      }
    }
  }

  Stitch readStitch(const SewingPattern& pattern, int k, const json& spec) {
    const std::string where = "stitch " + std::to_string(k);
    if (!spec.is_array() || spec.size() < 2 || spec.size() > 3)
      fail(where, "not a list of two edges (and \"right_wrong\")");
    Stitch stitch;
    if (spec.size() == 3) {
      if (spec[2] != "right_wrong") fail(where, "third element " + spec[2].dump() + " is not \"right_wrong\"");
      stitch.sameDirection = true;
    }
    EdgeRef* sides[2] = {&stitch.first, &stitch.second};
    std::string names[2];
    for (int side = 0; side < 2; ++side) {
      const json& ref = spec[side];
      if (!ref.is_object()) fail(where, "side " + std::to_string(side) + " is not {\"panel\", \"edge\"}");
      const json* panel = member(ref, "panel");
      const json* edge = member(ref, "edge");
      if (!panel || !panel->is_string() || !edge)
        fail(where, "side " + std::to_string(side) + " is not {\"panel\", \"edge\"}");
      const std::string name = panel->get<std::string>();
      const auto found = panelIndex_.find(name);
      if (found == panelIndex_.end()) fail(where, "panel " + quoted(name) + " does not exist");
      const Panel& p = pattern.panels[found->second];
      sides[side]->panel = found->second;
      sides[side]->edge =
          index(*edge, static_cast<long long>(p.edges.size()), where + " panel " + quoted(name), "edge");
      names[side] = "panel " + quoted(name) + " edge " + std::to_string(sides[side]->edge);
      const auto [previous, fresh] = stitched_.emplace(std::make_pair(found->second, sides[side]->edge), k);
      if (!fresh)
        fail(where, names[side] + " is already in stitch " + std::to_string(previous->second) +
                        ": an edge is sewn to one other edge");
    }
    const double a = lengths_.at({pattern.panels[stitch.first.panel].name, stitch.first.edge});
    const double b = lengths_.at({pattern.panels[stitch.second.panel].name, stitch.second.edge});
    const double ratio = std::max(a, b) / std::min(a, b);
    if (!(ratio <= kMaxStitchLengthRatio))
      fail(where, names[0] + " (" + number(a) + " m) and " + names[1] + " (" + number(b) +
                      " m) differ in length by a ratio of " + number(ratio) + ", more than " +
                      number(kMaxStitchLengthRatio));
    return stitch;
  }

  std::string file_;
  double scale_ = 0.01;  // m per file unit: GarmentCode's default is cm
  bool relative_ = true;
  std::map<std::pair<std::string, int>, double> lengths_;  // m, per panel name and edge
  std::map<std::string, int> panelIndex_;
  std::map<std::pair<int, int>, int> stitched_;  // (panel, edge) -> its stitch
};

std::string stem(const std::string& name) {
  std::string base = name.substr(name.find_last_of('/') + 1);
  if (base.size() > 5 && base.compare(base.size() - 5, 5, ".json") == 0) base.resize(base.size() - 5);
  const std::string suffix = "_specification";
  if (base.size() > suffix.size() && base.compare(base.size() - suffix.size(), suffix.size(), suffix) == 0)
    base.resize(base.size() - suffix.size());
  return base;
}

}  // namespace

SewingPattern parsePattern(const std::string& text, const std::string& name) {
  SewingPattern pattern = Reader(name).read(text);
  pattern.name = stem(name);
  return pattern;
}

SewingPattern readPatternFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw PatternError(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw PatternError(path + ": cannot read the file");
  return parsePattern(text.str(), path);
}

}  // namespace figment
