#pragma once
// Sewing patterns in GarmentCode's specification JSON (Korosteleva & Sorkine-Hornung, ETH
// Zurich; the format: docs/patterns.md) read into sim/pattern's SewingPattern: metres,
// absolute control points, each panel's rotation as a matrix.
//
// FILE FORMAT (what is read; other keys are ignored)
//   {"pattern": {"panels": {NAME: PANEL, ...}, "stitches": [STITCH, ...], "panel_order": [NAME, ...]},
//    "properties": {"units_in_meter": 100, "curvature_coords": "relative"}}
//   PANEL  = {"vertices": [[u, v], ...], "edges": [EDGE, ...], "translation": [x, y, z],
//             "rotation": [rx, ry, rz]}            rotation: degrees, R = Rz Ry Rx
//   EDGE   = {"endpoints": [i, j], "curvature": CURVE}     no curvature: straight
//   CURVE  = {"type": "circle", "params": [radius, large_arc, right]}
//          | {"type": "quadratic", "params": [[a, b]]} | [a, b]  (older files)
//          | {"type": "cubic", "params": [[a1, b1], [a2, b2]]}
//   STITCH = [{"panel": NAME, "edge": k}, {"panel": NAME, "edge": k}] (, "right_wrong")
// DEFAULTS: units_in_meter 100 (cm), curvature_coords "relative" (control point
// s + a (e - s) + b perp(e - s), perp(x, y) = (-y, x)), translation and rotation zero;
// panels in panel_order's order, else by name.
//
// A file that cannot be sewn is refused with one line naming the file, the panel, edge or
// stitch, and what is wrong (PatternError): not JSON; no panels; a panel of fewer than 3
// vertices, or whose edges are not one closed loop through every vertex; an index out of
// range; an unknown curvature type; a circle whose radius is less than half its chord; a
// number that is not finite or a coordinate past kMaxCoordinate; an edge shorter than
// kMinEdgeLength; a panel whose outline crosses or touches itself; a stitch naming a
// missing panel or edge; an edge in two stitches; two stitched edges whose lengths
// differ by more than kMaxStitchLengthRatio.

#include <stdexcept>
#include <string>

#include "sim/pattern/SewingPattern.h"

namespace figment {

// A pattern file that cannot be read or sewn: what() is one line, "FILE: where: what".
class PatternError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The largest ratio of two stitched edges' arc lengths. GarmentCode gathers (ruffles) an
// edge into a shorter one by up to 3 (its design parameters' ranges: sleeve cuffs'
// `top_ruffle` 1-3, skirt levels' `ruffle` 1-2, default 1.3), so a tighter limit would
// refuse its own designs; the shipped graded patterns reach 1.13 (eased sleeve caps). A
// third above the largest gather leaves room for the edge splits GarmentCode makes along
// a gathered seam, and still catches a stitch to the wrong edge of very different length
// or an arc whose flags make it metres long.
constexpr double kMaxStitchLengthRatio = 4.0;
// Panel coordinates, translations and radii beyond this (m) are not a garment's, and
// keeping them bounded keeps every length finite.
constexpr double kMaxCoordinate = 1000.0;
// An edge shorter than this (m) is a repeated vertex, not an edge.
constexpr double kMinEdgeLength = 1e-6;

// Reads the specification file at `path`.
SewingPattern readPatternFile(const std::string& path);

// Reads a specification from `text`; `name` stands for the file in messages, and the
// pattern's name is its stem less "_specification" (GarmentCode's naming).
SewingPattern parsePattern(const std::string& text, const std::string& name);

}  // namespace figment
