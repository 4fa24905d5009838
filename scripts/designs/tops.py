"""Sleeveless tops: a tank top (women's and men's) and a sleeveless A-line dress with bust
darts (women's). Each is a front and a back panel, whole across the body (no centre seam),
sewn at the shoulder straps and the sides."""

from dataclasses import dataclass

from assemble import face_out
from garment_library import CurveEdge, Edge, EdgeSeqFactory, EdgeSequence, Interface, Panel, Stitches


@dataclass
class Bodice:
    """Half-widths (cm, from the centre line) and heights (cm above the feet) of a sleeveless
    bodice's upper part, the same for front and back but for the neckline's depth."""
    neck_x: float  # where the strap meets the neckline
    neck_y: float
    shoulder_x: float  # the strap's outer end, over the shoulder
    shoulder_y: float
    underarm_x: float  # the armhole's low end, where the side seam starts
    underarm_y: float


def bodice_for(body, strap_inset, armhole_drop, ease):
    """The bodice of a sleeveless garment on `body`: the strap from 1 cm outside the neck to
    strap_inset cm inside the shoulder's end, the armhole armhole_drop cm below the bust line
    (above it when negative), ease cm round the bust."""
    neck_x = body["neck_w"] / 2 + 1.0
    shoulder_x = body["shoulder_w"] / 2 - strap_inset
    return Bodice(neck_x, body.neck, shoulder_x, body.neck - body.shoulder_drop(shoulder_x - neck_x),
                  (body["bust"] + ease) / 4, body.bust - armhole_drop)


def upper_edges(b, neck_depth, underarm_rise=0.0):
    """From the right underarm (+x) up the armhole, along the strap, across the neckline (a
    U of neck_depth below the strap's inner end), along the left strap and down the left
    armhole: five edges. underarm_rise lifts both underarm points (a front whose bust dart
    lengthens its sides)."""
    uy = b.underarm_y + underarm_rise
    mid = uy + 0.5 * (b.shoulder_y - uy)
    inward = b.underarm_x - 0.6 * (b.underarm_x - b.shoulder_x)
    # The armhole leaves the underarm heading in, level, and meets the strap heading up.
    right_armhole = CurveEdge([b.underarm_x, uy], [b.shoulder_x, b.shoulder_y],
                              [[inward, uy], [b.shoulder_x, mid]], relative=False)
    right_strap = Edge(right_armhole.end, [b.neck_x, b.neck_y])
    low = b.neck_y - 4.0 / 3.0 * neck_depth  # a symmetric cubic's lowest point is 3/4 of its controls' depth
    neckline = CurveEdge(right_strap.end, [-b.neck_x, b.neck_y], [[b.neck_x, low], [-b.neck_x, low]], relative=False)
    left_strap = Edge(neckline.end, [-b.shoulder_x, b.shoulder_y])
    left_armhole = CurveEdge(left_strap.end, [-b.underarm_x, uy], [[-b.shoulder_x, mid], [-inward, uy]],
                             relative=False)
    return right_armhole, right_strap, neckline, left_strap, left_armhole


class SleevelessPanel(Panel):
    """A front or back of a sleeveless garment: the hem, the right side up through `side`
    (heights and half-widths from the hem up to below the underarm), the bodice, the left side
    down. Interfaces: 'right', 'left' (the sides, hem up), 'right_strap', 'left_strap',
    'neck', 'hem'."""

    def __init__(self, name, bodice, neck_depth, side, underarm_rise=0.0):
        super().__init__(name)
        (hem_x, hem_y), upper_side = side[0], side[1:]
        hem = Edge([-hem_x, hem_y], [hem_x, hem_y])
        top = upper_edges(bodice, neck_depth, underarm_rise)
        # Each side shares its end points with the hem and the armhole (one loop of vertices).
        right = EdgeSeqFactory.from_verts(hem.end, *([x, y] for x, y in upper_side), top[0].start)
        left = EdgeSeqFactory.from_verts(top[-1].end, *([-x, y] for x, y in reversed(upper_side)), hem.start)
        self.edges = EdgeSequence(hem, right, *top, left)
        self.hem, self.top = hem, top
        self.right_side, self.left_side = list(right.edges), list(left.edges)
        self._interfaces()

    def _interfaces(self):
        # Both sides listed hem first, so a front's and a back's pair edge by edge.
        self.interfaces = {
            "hem": Interface(self, self.hem),
            "right": Interface(self, EdgeSequence(*self.right_side)),
            "right_strap": Interface(self, self.top[1]),
            "neck": Interface(self, self.top[2]),
            "left_strap": Interface(self, self.top[3]),
            "left": Interface(self, EdgeSequence(*reversed(self.left_side))),
        }

    def add_bust_darts(self, width, depth, height):
        """A dart into each side's edge below the underarm, `width` cm wide where it opens,
        reaching `depth` cm in, its middle at `height` (cm above the feet). The sides'
        interfaces are what is left of them (the dart's two legs are sewn to each other)."""
        for side, upward in ((self.right_side, True), (self.left_side, False)):
            edge = side[-1] if upward else side[0]
            low, high = sorted((edge.start[1], edge.end[1]))
            along = (height - low) / (high - low) * edge.length()
            offset = along if upward else edge.length() - along
            # The panel's inside lies left of both sides as the outline runs (counter-clockwise).
            _, kept = self.add_dart(EdgeSeqFactory.dart_shape(width, depth=depth), edge, offset, right=False,
                                    edge_seq=self.edges, int_edge_seq=EdgeSequence(edge))
            at = next(i for i, e in enumerate(side) if e is edge)
            side[at:at + 1] = kept.edges
        self._interfaces()
        return self


def sewn_front_and_back(front, back):
    """The seams of a sleeveless front and back: both straps, both sides."""
    return Stitches(
        (front.interfaces["right_strap"], back.interfaces["right_strap"]),
        (front.interfaces["left_strap"], back.interfaces["left_strap"]),
        (front.interfaces["right"], back.interfaces["right"]),
        (front.interfaces["left"], back.interfaces["left"]),
    )


def tank_top(body, front_neck, back_neck):
    """A tank top to the hips: straps 2 cm in from the shoulders, the armhole's low end 3 cm
    above the bust line, 10 cm ease round the bust, 16 round the waist, 10 round the hips."""
    bodice = bodice_for(body, strap_inset=2.0, armhole_drop=-3.0, ease=10.0)
    side = [((body["hips"] + 10.0) / 4, body.hips - 3.0), ((body["waist"] + 16.0) / 4, body.waist)]
    front = face_out(SleevelessPanel("tank_front", bodice, front_neck, side).translate_to([0, 0, 30]), [0, 0, 1])
    back = face_out(SleevelessPanel("tank_back", bodice, back_neck, side).translate_to([0, 0, -25]), [0, 0, -1])
    return [front, back], sewn_front_and_back(front, back)


def aline_dress(body, front_neck, back_neck, dart_width):
    """A sleeveless A-line dress to above the knee: the bodice as the tank top's with 8 cm ease
    round the bust, 10 round the waist, 12 round the hips, flaring to 28 cm wider than the
    hips a panel at the hem; a bust dart in each of the front's sides, the front's sides
    dart_width longer above the waist for it."""
    bodice = bodice_for(body, strap_inset=2.5, armhole_drop=-3.0, ease=8.0)
    hem_y = body.hips - 30.0
    side = [((body["hips"] + 12.0) / 4 + 14.0, hem_y), ((body["hips"] + 12.0) / 4, body.hips),
            ((body["waist"] + 10.0) / 4, body.waist)]
    front = SleevelessPanel("dress_front", bodice, front_neck, side, underarm_rise=dart_width)
    # The dart points at the bust point (bust_points apart), stopping 3 cm short of it.
    front.add_bust_darts(dart_width, bodice.underarm_x - body["bust_points"] / 2 - 3.0, body.bust - 2.0)
    front = face_out(front.translate_to([0, 0, 30]), [0, 0, 1])
    back = face_out(SleevelessPanel("dress_back", bodice, back_neck, side).translate_to([0, 0, -25]), [0, 0, -1])
    return [front, back], sewn_front_and_back(front, back)
