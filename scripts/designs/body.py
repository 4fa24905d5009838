"""The GarmentCode body a chart size was made for (scenes/patterns/bodies/SEX-NUMBER.yaml, cm),
and the heights the designs hang from. GarmentCode's body frame: y up, feet at y = 0, facing
+z, x to the body's left."""

import math
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


class Body:
    def __init__(self, sex, number):
        self.sex, self.number = sex, number
        self.m = {}
        path = os.path.join(ROOT, "scenes", "patterns", "bodies", "%s-%d.yaml" % (sex, number))
        with open(path) as f:  # "  key: value" lines under "body:"; no YAML library needed
            for line in f:
                key, _, value = line.strip().partition(":")
                if value.strip():
                    self.m[key] = float(value)

    def __getitem__(self, key):
        return self.m[key]

    # Heights (cm above the feet). GarmentCode measures its lengths down from the base of the
    # neck (height less the head): the waist waist_line below it, the hips hips_line below the
    # waist, the crotch crotch_hip_diff below the hips, the bust bust_line below the neck.
    @property
    def neck(self):
        return self["height"] - self["head_l"]

    @property
    def waist(self):
        return self.neck - self["waist_line"]

    @property
    def hips(self):
        return self.waist - self["hips_line"]

    @property
    def crotch(self):
        return self.hips - self["crotch_hip_diff"]

    @property
    def bust(self):
        return self.neck - self["bust_line"]

    def shoulder_drop(self, dx):
        """How far the shoulder line falls over dx cm out from the neck (shoulder_incl, degrees)."""
        return dx * math.tan(math.radians(self["shoulder_incl"]))


def chart_sizes(sex):
    """{number: letter code} of the chart's sizes for `sex` (scenes/sizes/chart.txt) that have a
    GarmentCode body (scenes/patterns/bodies/)."""
    sizes = {}
    with open(os.path.join(ROOT, "scenes", "sizes", "chart.txt")) as chart:
        for line in chart:
            words = line.split("#")[0].split()
            if len(words) == 7 and words[0] == sex and os.path.exists(
                    os.path.join(ROOT, "scenes", "patterns", "bodies", "%s-%s.yaml" % (sex, words[2]))):
                sizes[int(words[2])] = words[1]
    return sizes
