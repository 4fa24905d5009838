"""Shorts on a straight waistband (women's and men's): a front and a back panel a leg, sewn at
the sides, the inside legs, the front and the back crotch, and to the band. Heights are cm
above the feet, widths cm; x as the body's (+x its left)."""

from assemble import face_out
from garment_library import CurveEdge, Edge, EdgeSeqFactory, EdgeSequence, Interface, Panel, Stitches
from skirts import BAND_HEIGHT, Band


class LegPanel(Panel):
    """A front or back leg panel of the body's right leg drawn in the body's x (its outer side
    at -x, its crotch point at +x; side = -1 mirrors it for the left leg), its top's centre end
    at (0, rise) and its side end at y = 0.
      top_width: the top's width; hip_width: the width across the hips, hip_depth below the top;
      centre_share: how far down the hip depth the centre line runs straight before the
      crotch curve; crotch_depth: the crotch point's depth below the top, crotch_ext how far
      past the centre line it reaches; inseam: the inside leg's length to the hem.
    Interfaces: 'top', 'side' and 'centre' (top down), 'inseam', 'hem'."""

    def __init__(self, name, side, top_width, rise, slant, hip_width, hip_depth, centre_share, crotch_depth,
                 crotch_ext, inseam):
        super().__init__(name)

        def p(x, y):
            return [side * x, y]

        hem_y = -crotch_depth - inseam
        outer = -hip_width - 0.5  # the leg widens by 0.5 cm from the hips to the hem
        centre_top = p(-slant, rise)
        bend = p(0.0, -centre_share * hip_depth)
        tip = p(crotch_ext, -crotch_depth)
        hem = Edge(p(outer, hem_y), p(crotch_ext - 1.0, hem_y))
        inseam_edge = Edge(hem.end, tip)
        # The crotch curve leaves the centre line heading down and reaches the tip level.
        crotch = CurveEdge(tip, bend, [p(0.0, -crotch_depth)], relative=False)
        centre = Edge(crotch.end, centre_top)
        top = Edge(centre.end, p(-slant - top_width, 0.0))
        sides = EdgeSeqFactory.from_verts(top.end, p(-hip_width, -hip_depth), hem.start)
        self.edges = EdgeSequence(hem, inseam_edge, crotch, centre, top, sides)
        self.interfaces = {
            "hem": Interface(self, hem),
            "inseam": Interface(self, inseam_edge),
            "centre": Interface(self, EdgeSequence(centre, crotch)),
            "top": Interface(self, top),
            "side": Interface(self, sides),
        }


def shorts(body, inseam, name_prefix="shorts"):
    """Shorts with `inseam` cm inside legs, the crotch 2 cm below the body's; 2 cm ease round
    the waist (band and panels' tops), 8 round the hips. The back rises 3 cm higher at its
    centre, slanted 3.5 cm in; the crotch reaches a sixteenth of the hips past the front's
    centre and an eighth past the back's."""
    hip_depth = body["hips_line"] - BAND_HEIGHT
    crotch_depth = hip_depth + body["crotch_hip_diff"] + 2.0
    front_top = (body["waist"] - body["waist_back_width"]) / 2 + 0.5
    back_top = body["waist_back_width"] / 2 + 0.5
    front_hip = (body["hips"] - body["hip_back_width"]) / 2 + 2.0
    back_hip = body["hip_back_width"] / 2 + 2.0
    below = body.waist - BAND_HEIGHT
    legs = {}
    for side, leg in ((1, "r"), (-1, "l")):
        front = LegPanel("%s_front_%s" % (name_prefix, leg), side, front_top, 0.0, 0.0, front_hip, hip_depth, 0.6,
                         crotch_depth, body["hips"] / 16, inseam)
        back = LegPanel("%s_back_%s" % (name_prefix, leg), side, back_top, 3.0, 3.5, back_hip, hip_depth, 0.55,
                        crotch_depth, body["hips"] / 8, inseam)
        # Each leg's panels moved out to their side until the crotch points are 1 cm off the
        # body's centre, so a leg's front (or back) does not cross the other's.
        front.translate_to([-side * (body["hips"] / 16 + 1.0), below, 25.0])
        back.translate_to([-side * (body["hips"] / 8 + 1.0), below, -20.0])
        legs[leg] = (face_out(front, [0, 0, 1]), face_out(back, [0, 0, -1]))
    (front_r, back_r), (front_l, back_l) = legs["r"], legs["l"]
    band_f = Band("wb_front", [front_r.interfaces["top"].edges.length(), front_l.interfaces["top"].edges.length()])
    band_b = Band("wb_back", [back_r.interfaces["top"].edges.length(), back_l.interfaces["top"].edges.length()])
    band_f.translate_to([0, body.waist, 20]), band_b.translate_to([0, body.waist, -15])
    face_out(band_f, [0, 0, 1]), face_out(band_b, [0, 0, -1])
    seams = [(band_f.interfaces["right"], band_b.interfaces["right"]),
             (band_f.interfaces["left"], band_b.interfaces["left"]),
             (front_r.interfaces["centre"], front_l.interfaces["centre"]),
             (back_r.interfaces["centre"], back_l.interfaces["centre"])]
    for front, back in ((front_r, back_r), (front_l, back_l)):
        seams += [(front.interfaces["side"], back.interfaces["side"]),
                  (front.interfaces["inseam"], back.interfaces["inseam"])]
    # The bands' pieces from -x: the right leg's, then the left's.
    for band, (right, left) in ((band_f, (front_r, front_l)), (band_b, (back_r, back_l))):
        seams += [(band.interfaces["bottom"][0], right.interfaces["top"]),
                  (band.interfaces["bottom"][1], left.interfaces["top"])]
    return [band_f, band_b, front_r, front_l, back_r, back_l], Stitches(*seams)
