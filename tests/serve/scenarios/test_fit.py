#!/usr/bin/env python3
"""GET /api/fit end to end on a server this test starts on a loopback port: a chart body's
advice recommends its own size, with every candidate's regions, verdicts and shopper's text;
the answer is kept (a repeat is a cache hit, If-None-Match is 304); every class of bad
parameter is 400 naming it and its accepted range; the catalogue lists the chart's sizes
per style. And GET /api/render with a sex: MakeHuman's body made to the measurements in
the graded garment of a chart size, drawn in its colour and wider on a larger body.
The cases that make a body need MakeHuman's data (scripts/setup.sh fetches it): where the
file system has none, those are skipped before any case runs and the script exits 77
(ctest: skipped); where it has it, every case runs and must pass. No case decides anything
from what an answer says. No timings asserted.

    test_fit.py FIGMENT-SERVE [unittest options]
"""
import json
import sys
import urllib.parse

from ServeSupport import ServerCase, count_near, main, needs_makehuman, png_pixels

# The women's M and men's L chart bodies (scenes/sizes/chart.txt).
WOMANS_XS = dict(sex="female", stature="1.68", bust="0.80", waist="0.64", hips="0.88")
WOMANS_XL = dict(sex="female", stature="1.68", bust="0.96", waist="0.80", hips="1.04")
WOMANS_M = dict(sex="female", style="pencil", stature="1.68", bust="0.88", waist="0.72", hips="0.96")
MANS_L = dict(sex="male", style="tshirt", stature="1.77", bust="1.00", waist="0.88", hips="1.04")


def fit_path(**parameters):
    return "/api/fit?" + urllib.parse.urlencode(parameters)


class Fit(ServerCase):
    def advice(self, body):
        status, headers, answer = self.server.request(fit_path(**body))
        self.assertEqual(status, 200, answer)
        self.assertTrue(headers["content-type"].startswith("application/json"))
        return headers, json.loads(answer)

    @needs_makehuman
    def test_a_chart_body_gets_its_own_size(self):
        for body, own, sizes in ((WOMANS_M, "M", ["S", "M", "L"]), (MANS_L, "L", ["M", "L", "XL"])):
            _, advice = self.advice(body)
            self.assertEqual(advice["recommended"], own, body)
            self.assertFalse(advice["all_tight"])
            self.assertEqual(list(advice["sizes"]), sizes)
            for name, size in advice["sizes"].items():
                self.assertTrue(size["text"], name)
                self.assertTrue(size["regions"], name)
                for region in size["regions"].values():
                    self.assertIn(region["verdict"], ("tight", "fits", "loose"))
            own_size = advice["sizes"][own]
            self.assertNotIn("tight", [r["verdict"] for r in own_size["regions"].values()])

    @needs_makehuman
    def test_the_advices_drapes_are_the_pictures_drapes(self):
        # One drape per body and size: after the advice, each advised size's picture on the
        # same body is drawn from the drape the advice judged (X-Figment-Cache: hit, nothing
        # draped), and a size the advice did not try is draped anew (the control).
        body = dict(WOMANS_M, stature="1.695", hips="0.975")
        style = body.pop("style")
        _, advice = self.advice(dict(body, style=style))
        for size in advice["sizes"]:
            query = dict(body, outfit="%s:%s" % (style, size), size="160x200")
            status, headers, answer = self.server.request("/api/render?" + urllib.parse.urlencode(query))
            self.assertEqual((status, headers["x-figment-cache"], headers["x-figment-drape"]), (200, "hit", "rest"),
                             (size, answer[:200]))
        untried = next(size for size in ("XXS", "XL") if size not in advice["sizes"])
        query = dict(body, outfit="%s:%s" % (style, untried), size="160x200")
        status, headers, _ = self.server.request("/api/render?" + urllib.parse.urlencode(query))
        self.assertEqual((status, headers["x-figment-cache"]), (200, "miss"), untried)

    @needs_makehuman
    def test_a_repeat_is_kept_and_if_none_match_is_304(self):
        headers, first = self.advice(WOMANS_M)
        tag = headers["etag"]
        self.assertTrue(tag.startswith('"') and tag.endswith('"'))
        status, again, body = self.server.request(fit_path(**WOMANS_M))
        self.assertEqual(status, 200)
        self.assertEqual(again["x-figment-cache"], "hit")
        self.assertEqual(again["etag"], tag)
        self.assertEqual(json.loads(body), first)
        status, headers, body = self.server.request(fit_path(**WOMANS_M), {"If-None-Match": tag})
        self.assertEqual(status, 304)
        self.assertEqual(body, b"")
        # The same body written otherwise (another order, trailing zeros) is the same answer.
        same = dict(reversed(list(WOMANS_M.items())), bust="0.8800")
        self.assertEqual(self.server.request(fit_path(**same), {"If-None-Match": tag})[0], 304)

    def test_bad_parameters_are_400_naming_them(self):
        # The women's ranges as the catalogue lists them: the chart's bodies two sizes wider.
        women = self.server.json("/api/catalogue")[1]["made"]["measurements"]["female"]
        ranged = {name: "%.2f to %.2f (metres)" % (women[name]["min"], women[name]["max"]) for name in women}
        self.assertEqual(ranged["stature"], "1.45 to 1.95 (metres)")
        cases = [("style", "cape", "pencil"), ("sex", "other", "female, male"),
                 ("bust", "0.5", ranged["bust"]), ("waist", "abc", ranged["waist"]),
                 ("stature", "3", ranged["stature"])]
        for name, value, accepted in cases:
            status, error = self.server.json(fit_path(**dict(WOMANS_M, **{name: value})))
            self.assertEqual(status, 400, name)
            self.assertEqual(error["parameter"], name)
            self.assertEqual(error["value"], value)
            self.assertIn(accepted, error["accepted"])
        missing = dict(WOMANS_M)
        del missing["hips"]
        status, error = self.server.json(fit_path(**missing))
        self.assertEqual((status, error["parameter"], error["error"]), (400, "hips", "missing"))
        status, error = self.server.json(fit_path(**dict(WOMANS_M, colour="red")))
        self.assertEqual((status, error["parameter"]), (400, "colour"))

    def test_the_catalogue_lists_the_charts_sizes_per_style(self):
        status, catalogue = self.server.json("/api/catalogue")
        self.assertEqual(status, 200)
        made = catalogue["made"]
        styles = {style["name"]: style for style in made["styles"]}
        self.assertIn("pencil", styles)
        chart = {sex: [size["name"] for size in sizes] for sex, sizes in made["sizes"].items()}
        self.assertEqual(chart["female"][:6], ["XXS", "XS", "S", "M", "L", "XL"])
        self.assertEqual(chart["male"][:6], ["XS", "S", "M", "L", "XL", "XXL"])
        for style in styles.values():
            for sex, sizes in style["sizes"].items():
                self.assertEqual(sizes, [size for size in chart[sex] if size in sizes], (style["name"], sex))
        self.assertEqual(made["poses"], ["rest", "arms-down", "arm-raised", "walking", "sitting"])
        womens = made["measurements"]["female"]
        self.assertLess(womens["bust"]["min"], 0.76)
        self.assertGreater(womens["bust"]["max"], 0.96)

    def render(self, body, outfit):
        query = dict(body, outfit=outfit, size="160x200")
        status, headers, answer = self.server.request("/api/render?" + urllib.parse.urlencode(query))
        self.assertEqual(status, 200, answer)
        self.assertEqual(headers["content-type"], "image/png")
        return png_pixels(answer)[2]

    @needs_makehuman
    def test_a_measured_body_wears_its_graded_size_in_its_colour(self):
        small = count_near(self.render(WOMANS_XS, "pencil:XS:ff0000"), (255, 0, 0), 0.12)
        large = count_near(self.render(WOMANS_XL, "pencil:XL:ff0000"), (255, 0, 0), 0.12)
        self.assertGreater(small, 60)  # of 32000 pixels: the skirt is there, in its colour
        # The XL body's hips are 16 cm rounder: its XL skirt covers more of the picture.
        self.assertGreater(large, small * 1.05, (small, large))

    @needs_makehuman
    def test_a_shops_sewn_style_is_advised_and_pictured_on_the_made_body(self):
        # A pattern style (sewn from its size's GarmentCode pattern, scenes/patterns/): the
        # chart's M body is advised its own size among its neighbours, each sewn and at rest,
        # and each advised size's picture is the drape the advice judged (a cache hit). Posed
        # it is refused naming pose: its panels are placed and sewn round the standing body.
        _, advice = self.advice(dict(WOMANS_M, style="tee"))
        self.assertEqual(advice["recommended"], "M")
        self.assertEqual(list(advice["sizes"]), ["S", "M", "L"])
        body = dict(WOMANS_M)
        del body["style"]
        for size, fit in advice["sizes"].items():
            self.assertTrue(fit["at_rest"], size)
            query = dict(body, outfit="tee:" + size, size="160x200")
            status, headers, answer = self.server.request("/api/render?" + urllib.parse.urlencode(query))
            self.assertEqual((status, headers["x-figment-cache"], headers["x-figment-drape"]), (200, "hit", "rest"),
                             (size, answer[:200]))
        status, error = self.server.json("/api/render?" + urllib.parse.urlencode(
            dict(body, outfit="tee:M", pose="walking")))
        self.assertEqual((status, error["parameter"]), (400, "pose"), error)

    def test_a_measured_body_refuses_what_it_cannot_wear(self):
        cases = [(dict(WOMANS_M, outfit="pencil:XXXXL"), "outfit", "sizes XXS, XS, S, M, L, XL"),
                 (dict(WOMANS_M, outfit="cape:M"), "outfit", "female styles dress, skirt, pencil, tshirt"),
                 (dict(WOMANS_M, pose="relaxed"), "pose", "rest"),
                 (dict(WOMANS_M, sex="other"), "sex", "female, male")]
        for query, name, accepted in cases:
            del query["style"]
            status, error = self.server.json("/api/render?" + urllib.parse.urlencode(query))
            self.assertEqual(status, 400, query)
            self.assertEqual(error["parameter"], name)
            self.assertIn(accepted, error["accepted"])
        # A made body's measurements take the size advice's ranges for its sex (the chart's
        # bodies two sizes wider), not the Mannequin's: a bust 2 cm past them is refused.
        bust = self.server.json("/api/catalogue")[1]["made"]["measurements"]["female"]["bust"]
        over = "%.2f" % (bust["max"] + 0.02)
        status, error = self.server.json("/api/render?" + urllib.parse.urlencode(
            dict(WOMANS_XL, bust=over, outfit="pencil:XL")))
        self.assertEqual((status, error["parameter"], error["value"]), (400, "bust", over), error)
        self.assertEqual(error["accepted"], "%.2f to %.2f (metres)" % (bust["min"], bust["max"]))
        # The Mannequin wears the paper's patterns as cut: a size is refused on it.
        status, error = self.server.json("/api/render?body=mannequin&outfit=dress:XXS")
        self.assertEqual((status, error["parameter"]), (400, "outfit"))

    @needs_makehuman
    def test_a_measured_body_out_of_makehumans_reach_is_422_naming_the_measurement(self):
        # Each within its range, but no woman of a 0.76 m bust and 1.10 m hips has a 0.88 m
        # waist (the fit reaches 0.874 m): 422 as GET /api/fit answers, never 500; with no
        # outfit too (the body alone was drawn empty), and as a GLB.
        body = dict(sex="female", stature="1.68", bust="0.76", waist="0.88", hips="1.10")
        for extra in (dict(outfit="pencil:M"), dict(outfit="none"), dict(outfit="tshirt:S", format="glb")):
            status, headers, answer = self.server.request(
                "/api/render?" + urllib.parse.urlencode(dict(body, size="160x200", **extra)))
            error = json.loads(answer)
            self.assertEqual(status, 422, error)
            self.assertEqual((error["parameter"], error["value"]), ("waist", "0.880"), error)
            self.assertIn("out of reach", error["error"])
            self.assertIn("nearest", error["accepted"])
            self.assertEqual(headers["cache-control"], "no-store")
        # The same worker then draws a body it can make.
        self.render(WOMANS_XS, "pencil:XS:ff0000")

    @needs_makehuman
    def test_a_measured_body_takes_each_rig_pose_in_a_garment(self):
        # MakeHuman's presets: the body moves from rest into the pose as the T-shirt drapes
        # on it. Each picture shows the red shirt and another silhouette than the rest pose's.
        body = dict(WOMANS_M)
        del body["style"]

        def silhouette(pose):
            rows = self.render(dict(body, pose=pose), "tshirt:M:ff0000")
            self.assertGreater(count_near(rows, (255, 0, 0), 0.12), 60, pose)
            background = rows[0][0]
            return {(x, y) for y, row in enumerate(rows) for x, p in enumerate(row) if p != background}

        rest = silhouette("rest")
        for pose in ("arms-down", "arm-raised", "walking", "sitting"):
            posed = silhouette(pose)
            self.assertGreater(len(rest ^ posed), 0.05 * len(rest), pose)  # the body moved

    @needs_makehuman
    def test_a_measured_body_shows_its_fit_maps(self):
        # The pencil skirt of its own size on the women's M body: its ease map is red where
        # the skirt lies on the skin (the waist, the hips) and blue where it hangs away
        # (between the legs); stretch and pressure draw too, from the same drape.
        body = dict(WOMANS_M)
        del body["style"]

        def bands(kind):
            rows = self.render(dict(body, fitmap=kind), "pencil:M")
            red = blue = 0
            for row in rows:
                for p in row:
                    total = sum(p)
                    red += total > 60 and p[0] > 0.8 * total
                    blue += total > 60 and p[2] > 0.8 * total
            return red, blue

        red, blue = bands("ease")
        self.assertGreater(red, 50, (red, blue))
        self.assertGreater(blue, 50, (red, blue))
        for kind in ("stretch", "pressure"):
            self.assertGreater(sum(bands(kind)), 200, kind)  # the skirt in the map's colours
        status, error = self.server.json("/api/render?body=mannequin&fitmap=ease")  # no skin mesh
        self.assertEqual((status, error["parameter"]), (400, "fitmap"))


if __name__ == "__main__":
    ServerCase.executable = sys.argv.pop(1)
    main()
