"""Skirts: a six-gore flared skirt on a straight waistband, and a skirt of a fitted hip yoke
with a gathered tier below it (women's). Heights are cm above the feet, widths cm."""

import math

import numpy as np
from scipy.spatial.transform import Rotation

from assemble import face_out
from garment_library import CurveEdge, Edge, EdgeSeqFactory, EdgeSequence, Interface, Panel, Stitches

BAND_HEIGHT = 4.0


def _around(panel, degrees, distance, height):
    """Places a panel drawn facing +z turned `degrees` about the body's axis (0: the front, 90:
    the body's left), `distance` cm out from it, its origin at `height`; faces it out."""
    turn = Rotation.from_euler("y", degrees, degrees=True)
    panel.rotate_to(turn)
    out = turn.apply([0.0, 0.0, 1.0])
    panel.translate_to(out * distance + np.array([0.0, height, 0.0]))
    return face_out(panel, out)


class Gore(Panel):
    """One gore: its top (the waist seam) `top` wide at y = 0, `hip` wide `hip_depth` below,
    widening from there at `flare` degrees a side to the hem `length` below the top. Its hem
    is a curve through the centre, its corners raised so that the sides are as long as the
    centre (a level hem once sewn). Interfaces: 'top', 'right' and 'left' (top down), 'hem'."""

    def __init__(self, name, top, hip, hip_depth, length, flare):
        super().__init__(name)
        lower = length - hip_depth
        hem = hip + 2.0 * lower * math.tan(math.radians(flare))
        spread = (hem - hip) / 2
        # The corner's height: the side from the hip to it as long as the centre line's lower part.
        corner_y = -hip_depth - math.sqrt(lower**2 - spread**2)
        bottom = CurveEdge([-hem / 2, corner_y], [hem / 2, corner_y], [[0.0, 2.0 * -length - corner_y]],
                           relative=False)
        right = EdgeSeqFactory.from_verts(bottom.end, [hip / 2, -hip_depth], [top / 2, 0.0])
        waist = Edge(right[-1].end, [-top / 2, 0.0])
        left = EdgeSeqFactory.from_verts(waist.end, [-hip / 2, -hip_depth], bottom.start)
        self.edges = EdgeSequence(bottom, right, waist, left)
        self.interfaces = {
            "top": Interface(self, waist),
            "right": Interface(self, EdgeSequence(right[1], right[0])),
            "left": Interface(self, left),
            "hem": Interface(self, bottom),
        }


class Band(Panel):
    """A straight waistband's front or back: `pieces` lengths along its lower edge (one for each
    panel sewn below it), BAND_HEIGHT high, its top at y = 0. Interfaces: 'right', 'left'
    (its ends), 'top', and 'bottom' (a list, one edge a piece, from -x to +x)."""

    def __init__(self, name, pieces):
        super().__init__(name)
        width = sum(pieces)
        xs = np.concatenate([[0.0], np.cumsum(pieces)]) - width / 2
        bottom = EdgeSeqFactory.from_verts(*([x, -BAND_HEIGHT] for x in xs))
        right = Edge(bottom[-1].end, [width / 2, 0.0])
        top = Edge(right.end, [-width / 2, 0.0])
        left = Edge(top.end, bottom[0].start)
        self.edges = EdgeSequence(bottom, right, top, left)
        self.interfaces = {"right": Interface(self, right), "left": Interface(self, left), "top": Interface(self, top),
                           "bottom": [Interface(self, e) for e in bottom]}


def six_gore_skirt(body, length, flare):
    """Six equal gores to `length` below the waist band's bottom, flaring `flare` degrees a side
    from the hips, on a straight band round the waist (2 cm ease), 4 cm ease round the hips.
    The side seams are the seams between the front three gores and the back three."""
    top, hip = (body["waist"] + 2.0) / 6, (body["hips"] + 4.0) / 6
    hip_depth = body["hips_line"] - BAND_HEIGHT
    below = body.waist - BAND_HEIGHT
    # Gores at 0 (front centre), 60, 120, 180, 240 and 300 degrees round, 28 cm out: far enough
    # apart that their hems, up to 30 cm wide, do not cross where they are placed.
    gores = [_around(Gore("gore_%d" % (60 * k), top, hip, hip_depth, length, flare), 60 * k, 28.0, below)
             for k in range(6)]
    front = Band("wb_front", [top] * 3)
    back = Band("wb_back", [top] * 3)
    front.translate_to([0, body.waist, 20]), back.translate_to([0, body.waist, -15])
    face_out(front, [0, 0, 1]), face_out(back, [0, 0, -1])
    seams = [(gores[k].interfaces["right"], gores[(k + 1) % 6].interfaces["left"]) for k in range(6)]
    # The front band's pieces from -x: the gores at 300, 0 and 60 degrees; the back's: 240, 180, 120.
    for piece, k in zip(front.interfaces["bottom"], (5, 0, 1)):
        seams.append((piece, gores[k].interfaces["top"]))
    for piece, k in zip(back.interfaces["bottom"], (4, 3, 2)):
        seams.append((piece, gores[k].interfaces["top"]))
    seams += [(front.interfaces["right"], back.interfaces["right"]), (front.interfaces["left"], back.interfaces["left"])]
    return [front, back] + gores, Stitches(*seams)


def _girth_below_waist(body, depth):
    """The body's girth `depth` cm below the waist: from the waist's to the hips' in a line."""
    return body["waist"] + (body["hips"] - body["waist"]) * min(1.0, depth / body["hips_line"])


def _trapezoid(name, top, bottom, height):
    """A panel `top` wide at y = 0 and `bottom` wide `height` below, centred on x = 0.
    Interfaces: 'top', 'bottom', 'right', 'left' (the sides, top down)."""
    panel = Panel(name)
    panel.edges = EdgeSeqFactory.from_verts([-bottom / 2, -height], [bottom / 2, -height], [top / 2, 0.0],
                                            [-top / 2, 0.0], loop=True)
    low, right, high, left = panel.edges
    panel.interfaces = {"bottom": Interface(panel, low), "right": Interface(panel, right),
                        "top": Interface(panel, high), "left": Interface(panel, left)}
    return panel


def yoke_skirt(body, yoke_depth, length, gather):
    """A hip yoke from the waist (2 cm ease) to `yoke_depth` below it (4 cm ease there), and a
    tier below it to `length` below the waist, `gather` times the yoke's width, gathered onto
    it; front and back each, sewn at the sides."""
    top = (body["waist"] + 2.0) / 2
    bottom = (_girth_below_waist(body, yoke_depth) + 4.0) / 2
    panels = {}
    for name, z, out in (("front", 20.0, 1.0), ("back", -15.0, -1.0)):
        yoke = _trapezoid("yoke_" + name, top, bottom, yoke_depth).translate_to([0, body.waist, z])
        tier = _trapezoid("tier_" + name, bottom * gather, bottom * gather, length - yoke_depth)
        tier.translate_to([0, body.waist - yoke_depth, z + 5.0 * out])
        panels[name] = (face_out(yoke, [0, 0, out]), face_out(tier, [0, 0, out]))
    (yoke_f, tier_f), (yoke_b, tier_b) = panels["front"], panels["back"]
    seams = []
    for a, b in ((yoke_f, yoke_b), (tier_f, tier_b)):
        seams += [(a.interfaces["right"], b.interfaces["right"]), (a.interfaces["left"], b.interfaces["left"])]
    for yoke, tier in ((yoke_f, tier_f), (yoke_b, tier_b)):
        # The tier's top gathered onto the yoke's bottom (pygarment's ruffle: the gathered
        # length over the sewn one).
        seams.append((yoke.interfaces["bottom"], Interface(tier, tier.interfaces["top"].edges, ruffle=gather)))
    return [yoke_f, yoke_b, tier_f, tier_b], Stitches(*seams)
