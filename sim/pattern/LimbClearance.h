#pragma once
// A panel placed along a limb starts clear of it.
//
// A sleeve is two panels, front and back, placed flat on either side of the arm; sewing
// pulls their seams straight together, so the arm must lie between them when the
// sewing starts. GarmentCode's bodies hold their arms straight in the body's plane, so
// its sleeves' panels lie 15 cm before and behind the arm's axis; MakeHuman's chart
// bodies bend their elbows, the forearm reaching 20 to 35 cm forward of the shoulder at
// the wrist, through the front panel's plane. Sewn so, the front panel's nodes the arm
// goes through are pushed out on the wrong side, and the sleeve closes beside the
// forearm or across it (docs/patterns.md, "Known limits").
//
// So a panel along a limb moves along its normal, away from the limb, until no part of
// the body whose projection on the panel's plane falls inside its outline lies beyond it.

#include "sim/core/TriangleMesh.h"
#include "sim/pattern/SewingPattern.h"

namespace figment {

// How far (m) `panel` (placed in the body's frame) moves along its normal (rotation z;
// negative: against it), away from the body's vertices that lie within its outline seen
// along its normal, so that all of them lie at least `clearance` behind its plane: it
// moves to the side of its plane away from their centroid, and not at all when they
// already lie `clearance` behind it or none lies within its outline.
double clearingShift(const Panel& panel, const TriangleMesh& body, double clearance);

// The panel moved by clearingShift() along its normal.
void moveClearOf(Panel& panel, const TriangleMesh& body, double clearance);

}  // namespace figment
