"""A design's panels and stitches as GarmentCode's specification JSON, the same bytes on every run.

pygarment's Component.assembly merges its parts in the order of a Python set (object ids), so
the panels' and the darts' order would change from run to run; here the panels go in the
order given, each panel's own stitches (its darts) after it, then the design's stitches."""

import os

import numpy as np

from garment_library import BasicPattern, EdgeSequence


def _outline_area(panel):
    """Signed area of the panel's outline (curves as 8 chords each): > 0 counter-clockwise."""
    points = np.asarray(EdgeSequence([e.linearize(7) for e in panel.edges]).verts(), dtype=float)
    x, y = points[:, 0], points[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def face_out(panel, outward):
    """Runs the panel's outline counter-clockwise as seen from `outward` (a 3-D direction away
    from the body), as GarmentCode's stitches expect of every panel (the second edge of a
    stitch runs the other way). pygarment's own autonorm does this from the bounding box's
    corners, and leaves a panel as it is where three of those lie in a line (a NaN normal)."""
    facing = panel.rotation.apply([0.0, 0.0, 1.0]).dot(outward)
    if (_outline_area(panel) > 0.0) != (facing > 0.0):
        panel.edges.reverse()
    return panel


def _integral_start(panel):
    """Panel.assembly moves the panel's origin to its first vertex, shifting the vertices by the
    whole centimetres of that vertex and the translation by all of it (set_pivot's int()): the
    panel would land up to 1 cm off. Moving the origin by the fraction first keeps it in place."""
    start = np.asarray(panel.edges[0].start, dtype=float)
    fraction = start - np.trunc(start)
    panel.edges.translate_by(-fraction)
    panel.translation = np.asarray(panel.translation, dtype=float) + panel.rotation.apply([*fraction, 0.0])


def assemble(name, panels, stitches):
    """panels: Panel objects in the file's order, each facing out; stitches: a Stitches of the
    seams between them."""
    pattern = BasicPattern()
    pattern.name = name
    for panel in panels:
        _integral_start(panel)
        # A panel's assembly also numbers its edges as the file will (geometric_id), which the
        # stitches' assembly below reads.
        part = panel.assembly().pattern
        pattern.pattern["panels"].update(part["panels"])
        pattern.pattern["stitches"] += part["stitches"]
    pattern.pattern["stitches"] += stitches.assembly()
    pattern.panel_order(force_update=True)
    return pattern


def write(pattern, folder):
    """Writes folder/NAME_specification.json as pygarment serialises it; returns the path."""
    pattern.serialize(folder, to_subfolder=False)
    return os.path.join(folder, pattern.name + "_specification.json")
