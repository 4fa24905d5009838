#!/usr/bin/env python3
"""figment-serve end to end, each case on a server this test starts on a loopback port:
every endpoint, 304, every class of 400, 404 on traversal without reading a file, limits,
a worker killed with SIGKILL mid-request (that request fails, the next succeeds), and an
overload answered 503 with Retry-After, the server still serving. No timings asserted.

    test_service.py FIGMENT-SERVE [unittest options]
"""
import json
import os
import signal
import sys
import threading
import time
import unittest
import urllib.parse

from ServeSupport import Server, ServerCase, count_near, main, needs_makehuman, png_pixels

EXECUTABLE = None
SMALL = "size=160x200"  # renders stay small: the test checks pictures, not detail


def render_path(**parameters):
    query = dict(size="160x200")
    query.update(parameters)
    return "/api/render?" + urllib.parse.urlencode(query)


class Endpoints(ServerCase):
    server_arguments = ("--workers", "2")

    def test_healthz(self):
        status, body = self.server.json("/healthz")
        self.assertEqual(status, 200)
        self.assertEqual(body["status"], "ok")
        self.assertEqual(body["workers"], 2)

    def test_openapi_lists_every_route_and_each_answers(self):
        status, document = self.server.json("/openapi.json")
        self.assertEqual(status, 200)
        self.assertTrue(document["openapi"].startswith("3."))
        # /api/jobs/{id}: tests/serve/scenarios/test_render_jobs.py; /api/fit: the next case.
        self.assertIn("/api/jobs/{id}", document["paths"])
        self.assertIn("/api/fit", document["paths"])
        for path in set(document["paths"]) - {"/api/jobs/{id}", "/api/fit"}:
            code, headers, body = self.server.request(path + ("?" + SMALL if path == "/api/render" else ""))
            self.assertEqual(code, 200, path)

    @needs_makehuman
    def test_fit_answers(self):
        # The women's M chart body's size advice (MakeHuman's body: skipped, before it runs,
        # where the file system has none of its data).
        code, headers, body = self.server.request(
            "/api/fit?sex=female&style=pencil&stature=1.68&bust=0.88&waist=0.72&hips=0.96")
        self.assertEqual(code, 200, body[:200])

    def test_catalogue(self):
        status, catalogue = self.server.json("/api/catalogue")
        self.assertEqual(status, 200)
        self.assertEqual(catalogue["bodies"], ["made", "mannequin"])
        made = catalogue["made"]
        names = [style["name"] for style in made["styles"]]
        self.assertIn("dress", names)
        for style in made["styles"]:
            # Each style's sizes are the chart's, per sex it is sold to: one vocabulary.
            for sex, sizes in style["sizes"].items():
                chart = [size["name"] for size in made["sizes"][sex]]
                self.assertTrue(sizes and set(sizes) <= set(chart), (style["name"], sex))
            self.assertTrue(all(len(c) == 6 for c in style["colours"]))
        self.assertIn("male", next(s for s in made["styles"] if s["name"] == "tshirt")["sizes"])
        self.assertNotIn("male", next(s for s in made["styles"] if s["name"] == "dress")["sizes"])
        self.assertEqual(made["measurements"]["female"]["bust"]["default"], 0.88)  # the women's M
        self.assertTrue(made["poses"])
        # The Mannequin's patterns come in no sizes.
        self.assertTrue(all("sizes" not in style for style in catalogue["mannequin"]["styles"]))
        self.assertGreaterEqual(len(catalogue["lights"]), 3)
        self.assertTrue(catalogue["skinTones"])

    def test_page(self):
        status, headers, body = self.server.request("/")
        self.assertEqual(status, 200)
        self.assertTrue(headers["content-type"].startswith("text/html"))
        self.assertIn(b"/app.js", body)

    def test_render_shows_the_garment_in_its_colour(self):
        red = self.server.request(render_path(outfit="dress:M:ff0000"))
        green = self.server.request(render_path(outfit="dress:M:00ff00"))
        for status, headers, _ in (red, green):
            self.assertEqual(status, 200)
            self.assertEqual(headers["content-type"], "image/png")
            self.assertIn(headers["x-figment-cache"], ("hit", "miss"))
            self.assertEqual(headers["x-figment-drape"], "rest")
            self.assertTrue(headers["etag"].startswith('"') and not headers["etag"].startswith("W/"))
            self.assertIn("max-age", headers["cache-control"])
        width, height, red_rows = png_pixels(red[2])
        self.assertEqual((width, height), (160, 200))
        _, _, green_rows = png_pixels(green[2])
        # Lit red cloth keeps red's hue; none of it in the green dress's picture (the control).
        self.assertGreater(count_near(red_rows, (255, 0, 0), 0.12), 200)
        self.assertEqual(count_near(green_rows, (255, 0, 0), 0.12), 0)
        self.assertGreater(count_near(green_rows, (0, 255, 0), 0.12), 200)
        # Only the colour differs: the second drape came from the first (the drape cache).
        self.assertEqual(green[1]["x-figment-cache"], "hit")
        self.assertNotEqual(red[1]["etag"], green[1]["etag"])

    @needs_makehuman
    def test_measurements_without_a_body_choice_draw_the_made_body(self):
        # The made body follows the measurements: two women 10 cm apart in hip girth, all else
        # the same, seen from the front with nothing on. Their silhouettes are as tall (the
        # stature), and the torso at the hips is wider on the fuller body by about the
        # girth's change over pi (a round section's diameter; a body's section is wider
        # than deep, so up to 1.5 times that), in the pixels a metre takes in the picture.
        def silhouette(hips):
            status, headers, body = self.server.request(render_path(
                stature="1.700", bust="0.900", waist="0.740", hips=hips, outfit="none", size="400x600"))
            self.assertEqual(status, 200, body[:200])
            _, _, rows = png_pixels(body)
            background = rows[0][0]
            drawn = [y for y, row in enumerate(rows) if any(p != background for p in row)]
            top, bottom = drawn[0], drawn[-1]

            def torso(y):  # the run of body pixels through the picture's middle column
                row, middle = rows[y], len(rows[y]) // 2
                left = right = middle
                while left > 0 and row[left - 1] != background:
                    left -= 1
                while right < len(row) - 1 and row[right + 1] != background:
                    right += 1
                return right - left + 1 if row[middle] != background else 0

            height = bottom - top + 1
            # The hips lie about half way up a standing body: the widest torso there.
            hips_width = max(torso(bottom - int(f * height)) for f in (0.46, 0.48, 0.50, 0.52, 0.54))
            return height, hips_width

        narrow, full = silhouette("0.960"), silhouette("1.060")
        self.assertLessEqual(abs(narrow[0] - full[0]), 2, (narrow, full))  # the same stature
        per_metre = narrow[0] / 1.70
        widened = full[1] - narrow[1]
        expected = 0.10 / 3.14159 * per_metre
        self.assertGreater(widened, 0.8 * expected, (narrow, full, expected))
        self.assertLess(widened, 1.6 * expected, (narrow, full, expected))

    @needs_makehuman
    def test_the_made_body_wears_underwear_unless_it_is_turned_off(self):
        # The same body and skirt with the base layer and without (the control): the pixels
        # that differ are the layer's, a dark neutral grey (little hue, low value) where the
        # bare body shows its skin. The layer lies inside the cloth's clearance, so the
        # second picture reuses the first one's drape.
        def picture(query):
            status, headers, body = self.server.request(render_path(outfit="pencil:M:c03030", size="300x400", **query))
            self.assertEqual(status, 200, body[:200])
            return headers, png_pixels(body)[2]

        def grey(p):
            return max(p) - min(p) <= 16 and max(p) < 140

        dressed_headers, dressed = picture({})
        bare_headers, bare = picture({"underwear": "off"})
        changed = [(a, b) for row_a, row_b in zip(dressed, bare) for a, b in zip(row_a, row_b) if a != b]
        layer = sum(1 for a, b in changed if grey(a) and not grey(b))
        self.assertGreater(layer, 300)                         # the band over the bust, above the skirt
        # Nothing else changed but the layer's outline, where its grey and the skin blend
        # (each pixel is the mean of 3 x 3 samples): about a fifth of the changed pixels.
        self.assertGreater(layer, 0.7 * len(changed), len(changed))
        self.assertEqual(bare_headers["x-figment-cache"], "hit")  # the same drape
        self.assertNotEqual(dressed_headers["etag"], bare_headers["etag"])

    def test_mannequins_at_the_ends_of_its_ranges_drape_and_say_how(self):
        # The tallest Mannequin once tangled the dress made for the default one (its
        # shoulders rose through the straps): the patterns now follow the stature. The
        # smallest body's outfit comes to rest. The largest body (1.90 m, bust 1.10, hips
        # 1.15) tears the paper's T-shirt (an edge past 1.5 times its rest length): the answer
        # says so (X-Figment-Drape, docs/service.md) and is not kept, so a repeat says it again.
        cached = self.server.json("/healthz")[1]["imageCacheBytes"]
        for body, drape in ((dict(stature="1.90", bust="1.10", hips="1.15"), "torn"),
                            (dict(stature="1.45", waist="0.60", hips="0.82"), "rest")):
            path = render_path(body="mannequin", outfit="tshirt,dress", **body)
            status, headers, body_bytes = self.server.request(path)
            self.assertEqual((status, headers["x-figment-drape"]), (200, drape), (body, body_bytes[:200]))
            self.assertEqual(self.server.request(path)[1]["x-figment-drape"], drape, body)
            kept = self.server.json("/healthz")[1]["imageCacheBytes"]
            self.assertEqual(kept > cached, drape == "rest", body)  # only a drape at rest is kept
            cached = kept

    def test_format_glb_is_the_dressed_body_as_gltf_binary(self):
        status, headers, body = self.server.request("/api/render?outfit=tshirt:M,skirt:L&format=glb")
        self.assertEqual(status, 200)
        self.assertEqual(headers["content-type"], "model/gltf-binary")
        self.assertEqual(body[:4], b"glTF")  # the GLB header's magic
        self.assertEqual(int.from_bytes(body[8:12], "little"), len(body))  # its stated length
        chunk = int.from_bytes(body[12:16], "little")
        document = json.loads(body[20:20 + chunk])
        self.assertGreaterEqual(len(document["meshes"]), 3)  # two garments and the skin

    def test_another_view_is_a_drape_cache_hit_and_if_none_match_is_304(self):
        path = render_path(outfit="tshirt:M", view="0,0")
        status, headers, _ = self.server.request(path)
        self.assertEqual(status, 200)
        status, side, _ = self.server.request(render_path(outfit="tshirt:M", view="90,10"))
        self.assertEqual(status, 200)
        self.assertEqual(side["x-figment-cache"], "hit")
        status, again, body = self.server.request(path, {"If-None-Match": headers["etag"]})
        self.assertEqual(status, 304)
        self.assertEqual(body, b"")
        self.assertEqual(again["etag"], headers["etag"])
        status, _, _ = self.server.request(path, {"If-None-Match": '"another"'})
        self.assertEqual(status, 200)

    def test_each_bad_parameter_is_400_naming_it(self):
        cases = [("stature=tall", "stature"), ("stature=3", "stature"), ("bust=0.1", "bust"),
                 ("skin=plaid", "skin"), ("pose=handstand", "pose"), ("light=laser", "light"),
                 ("outfit=cape:M", "outfit"), ("outfit=dress:M,tshirt:M,skirt:M,dress:S", "outfit"),
                 ("view=1,2,3", "view"), ("size=5000x5000", "size"), ("size=12", "size"), ("format=obj", "format"),
                 ("scene=%2Fetc%2Fpasswd", "scene"), ("pose=rest&pose=relaxed", "pose"),
                 ("skin=" + "%E2%82%AC" * 22, "skin")]  # quoted cut to 64 bytes: whole characters
        for query, parameter in cases:
            status, headers, body = self.server.request("/api/render?" + query)
            self.assertEqual(status, 400, query)
            self.assertTrue(headers["content-type"].startswith("application/json"), query)
            answer = json.loads(body)
            self.assertEqual(answer["parameter"], parameter, query)
            for key in ("error", "value", "accepted"):
                self.assertIn(key, answer, query)

    def test_unknown_and_traversal_paths_are_404_json_and_read_nothing(self):
        for path in ["/nothing", "/../../../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/..%2f..%2fetc%2fpasswd",
                     "/api/../../etc/passwd", "/app.js/../../etc/passwd", "//etc/passwd", "/%2fetc%2fpasswd",
                     "/style.css%00.png", "/appxjs", "/api/render/../../../etc/passwd", "/serve/http/web/index.html"]:
            status, headers, body = self.server.request(path)
            self.assertEqual(status, 404, path)
            self.assertEqual(json.loads(body)["error"], "no such path", path)
            self.assertNotIn(b"root:", body, path)

    def test_limits_on_url_and_headers(self):
        status, _, _ = self.server.request("/api/render?skin=" + "a" * 9000)
        self.assertIn(status, (400, 414))
        status, _, _ = self.server.request("/healthz", {"X-Big": "b" * 9000})
        self.assertIn(status, (400, 431))
        status, _ = self.server.json("/healthz")  # still serving
        self.assertEqual(status, 200)


def wait_until(condition):
    """Polls `condition` until it holds (no time limit is asserted: ctest's TIMEOUT bounds it)."""
    while not condition():
        time.sleep(0.02)


class Workers(unittest.TestCase):
    def test_a_killed_worker_fails_only_its_request(self):
        server = Server(EXECUTABLE, "--workers", "1")
        try:
            wait_until(lambda: len(server.worker_pids()) == 1)
            for attempt in range(3):  # a render may finish before the kill lands: try another body
                answer = {}
                path = render_path(outfit="tshirt:M,skirt:M", stature="%.3f" % (1.60 + 0.01 * attempt))
                thread = threading.Thread(target=lambda: answer.update(result=server.request(path)))
                thread.start()
                wait_until(lambda: server.json("/healthz")[1]["busy"] == 1)
                victim = server.worker_pids()[0]
                os.kill(victim, signal.SIGKILL)
                thread.join()
                if answer["result"][0] != 200:
                    break
            status, headers, body = answer["result"]
            self.assertEqual(status, 502)
            self.assertIn("error", json.loads(body))
            status, _, _ = server.request(render_path(outfit="dress:M", stature="1.700"))
            self.assertEqual(status, 200)
            self.assertGreaterEqual(server.json("/healthz")[1]["restarts"], 1)
            self.assertNotIn(victim, server.worker_pids())
        finally:
            self.assertEqual(server.stop(), 0)

    def test_a_render_past_its_time_limit_is_504_and_the_worker_replaced(self):
        # 1 ms: no drape and no render fits (a worker only starting takes longer).
        server = Server(EXECUTABLE, "--workers", "1", "--time-limit", "0.001")
        try:
            status, headers, body = server.request(render_path(outfit="dress:M"))
            self.assertEqual(status, 504)
            self.assertIn("time limit", json.loads(body)["error"])
            health = server.json("/healthz")[1]
            self.assertGreaterEqual(health["restarts"], 1)
            self.assertEqual(health["busy"], 0)
        finally:
            self.assertEqual(server.stop(), 0)

    def test_a_client_past_its_render_rate_gets_429_but_cached_images(self):
        server = Server(EXECUTABLE, "--workers", "1", "--rate", "0.001", "--burst", "1")
        try:
            first = render_path(outfit="dress:M")
            self.assertEqual(server.request(first)[0], 200)
            status, headers, body = server.request(render_path(outfit="dress:L"))
            self.assertEqual(status, 429)
            self.assertGreater(int(headers["retry-after"]), 0)
            self.assertIn("error", json.loads(body))
            self.assertEqual(server.request(first)[0], 200)  # in the image cache: no render
        finally:
            self.assertEqual(server.stop(), 0)

    def test_overload_is_503_with_retry_after_and_no_crash(self):
        server = Server(EXECUTABLE, "--workers", "1", "--queue", "1", "--rate", "0")
        try:
            for round in range(3):
                results = []
                lock = threading.Lock()

                def ask(i):
                    result = server.request(render_path(outfit="dress:M", hips="%.3f" % (0.90 + 0.002 * i + 0.03 * round)))
                    with lock:
                        results.append(result)
                threads = [threading.Thread(target=ask, args=(i,)) for i in range(8)]
                for t in threads:
                    t.start()
                for t in threads:
                    t.join()
                statuses = [r[0] for r in results]
                self.assertTrue(set(statuses) <= {200, 503}, statuses)
                if 503 in statuses:
                    break
            self.assertIn(503, statuses)
            self.assertIn(200, statuses)
            for status, headers, body in results:
                if status == 503:
                    self.assertTrue(int(headers["retry-after"]) > 0)
                    self.assertIn("error", json.loads(body))
            self.assertEqual(server.json("/healthz")[0], 200)
            self.assertIsNone(server.process.poll())
        finally:
            self.assertEqual(server.stop(), 0)


if __name__ == "__main__":
    EXECUTABLE = ServerCase.executable = sys.argv.pop(1)
    main()
