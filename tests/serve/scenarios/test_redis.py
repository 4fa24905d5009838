#!/usr/bin/env python3
"""figment-serve over a Redis of the test's own (a Unix socket in a temporary folder): two
instances share rendered images and drapes (one's render is a cache hit on the other); a
damaged or foreign entry in Redis is dropped and the image made again; Redis killed under
traffic: every request still answered 200 from the local level, /healthz says Redis is
down and the log says it once; Redis started again: the instance reconnects, and what Redis
acknowledged before the crash is still there. No timings asserted.

    test_redis.py FIGMENT-SERVE [unittest options]
"""
import collections
import subprocess
import sys
import threading
import time
import unittest
import urllib.parse

from ServeSupport import RedisServer, Server, count_near, png_pixels

EXECUTABLE = None


def render_path(**parameters):
    query = dict(size="160x200")
    query.update(parameters)
    return "/api/render?" + urllib.parse.urlencode(query)


def tag_of(headers):
    return headers["etag"].strip('"')


def wait_until(condition):
    """Polls `condition` until it holds (no time limit is asserted: ctest's TIMEOUT bounds it)."""
    while not condition():
        time.sleep(0.05)


class SharedCache(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.redis = RedisServer()
        cls.first = Server(EXECUTABLE, "--workers", "1", "--redis", cls.redis.url)
        cls.second = Server(EXECUTABLE, "--workers", "1", "--redis", cls.redis.url)

    @classmethod
    def tearDownClass(cls):
        statuses = [cls.first.stop(), cls.second.stop()]
        cls.redis.stop()
        if statuses != [0, 0]:
            raise AssertionError("figment-serve exited with %s" % statuses)

    def test_an_image_one_instance_made_is_a_hit_on_the_other(self):
        path = render_path(outfit="dress:M:ff0000")
        status, made, image = self.first.request(path)
        self.assertEqual((status, made["x-figment-cache"]), (200, "miss"))
        self.assertEqual(self.second.json("/healthz")[1]["redis"], "up")
        status, shared, same = self.second.request(path)
        self.assertEqual((status, shared["x-figment-cache"]), (200, "hit"))
        self.assertEqual(shared["etag"], made["etag"])
        self.assertEqual(png_pixels(same), png_pixels(image))
        self.assertEqual(self.redis.command("EXISTS", "figment:image:" + tag_of(made)), 1)

    def test_a_drape_one_instance_made_is_a_hit_on_the_other(self):
        # A skirt in L on a body of its own: neither instance has draped it. The second asks
        # for another view, an image nobody made, whose drape is in Redis only.
        body = dict(outfit="skirt:L:00ff00", hips="1.010")
        status, made, _ = self.first.request(render_path(**body))
        self.assertEqual((status, made["x-figment-cache"]), (200, "miss"))
        self.assertTrue(self.redis.command("KEYS", "figment:drape:*"))
        status, shared, image = self.second.request(render_path(view="back", **body))
        self.assertEqual((status, shared["x-figment-cache"]), (200, "hit"))
        self.assertNotEqual(shared["etag"], made["etag"])
        rows = png_pixels(image)[2]  # the green skirt from behind, and nothing red (the control)
        self.assertGreater(count_near(rows, (0, 255, 0), 0.2), 50)
        self.assertEqual(count_near(rows, (255, 0, 0), 0.2), 0)

    def test_a_damaged_or_foreign_image_in_redis_is_dropped_and_made_again(self):
        for damage in ("flip", "foreign"):
            path = render_path(outfit="tshirt:M:0000ff", view="%s,0" % (30 if damage == "flip" else 60))
            status, made, image = self.first.request(path)
            self.assertEqual(status, 200)
            key = "figment:image:" + tag_of(made)
            entry = self.redis.command("GET", key)
            entry = entry if isinstance(entry, bytes) else entry.encode()
            if damage == "flip":
                entry = entry[:-40] + bytes([entry[-40] ^ 0x20]) + entry[-39:]
            else:  # another image's entry, whole and sound, under this key
                other = self.first.request(render_path(outfit="tshirt:M:0000ff", view="90,0"))[1]
                entry = self.redis.command("GET", "figment:image:" + tag_of(other))
                entry = entry if isinstance(entry, bytes) else entry.encode()
            self.redis.command("SET", key, entry)
            status, again, remade = self.second.request(path)
            self.assertEqual(status, 200, damage)
            self.assertEqual(png_pixels(remade), png_pixels(image), damage)
            # Dropped, then stored again sound: the entry holds this image once more.
            stored = self.redis.command("GET", key)
            stored = stored if isinstance(stored, bytes) else stored.encode()
            self.assertTrue(stored.endswith(image), damage)


class Faults(unittest.TestCase):
    def test_redis_killed_and_started_again_under_traffic(self):
        redis = RedisServer()
        server = Server(EXECUTABLE, "--workers", "1", "--rate", "0", "--redis", redis.url, capture_log=True)
        try:
            status, before, _ = server.request(render_path(outfit="dress:S:ff0000"))
            self.assertEqual(status, 200)
            kept = "figment:image:" + tag_of(before)
            self.assertEqual(redis.command("EXISTS", kept), 1)  # acknowledged by Redis

            statuses, stop = [], threading.Event()

            def traffic():  # the image made before, and new views of it, all through the fault
                view = 0
                while not stop.is_set():
                    view = (view + 7) % 360
                    statuses.append(server.request(render_path(outfit="dress:S:ff0000"))[0])
                    statuses.append(server.request(render_path(outfit="dress:S:ff0000", view="%d,0" % view))[0])
            thread = threading.Thread(target=traffic)
            thread.start()
            try:
                wait_until(lambda: len(statuses) >= 4)
                redis.kill()
                wait_until(lambda: server.json("/healthz")[1]["redis"] == "down")
                down = len(statuses)
                wait_until(lambda: len(statuses) >= down + 6)  # served with Redis away
                redis.start()
                wait_until(lambda: server.json("/healthz")[1]["redis"] == "up")
                up = len(statuses)
                wait_until(lambda: len(statuses) >= up + 4)
            finally:
                stop.set()
                thread.join()
            self.assertEqual(set(statuses), {200}, collections.Counter(statuses))
            log = server.log()
            self.assertEqual(log.count("unreachable"), 1, log)
            self.assertEqual(log.count("reachable again"), 1, log)
            self.assertEqual(redis.command("EXISTS", kept), 1)  # nothing acknowledged was lost
            status, after, _ = server.request(render_path(outfit="dress:S:ff0000", size="150x190"))
            self.assertEqual(status, 200)
            self.assertEqual(redis.command("EXISTS", "figment:image:" + tag_of(after)), 1)  # stored again
        finally:
            self.assertEqual(server.stop(), 0)
            redis.stop()

    def test_healthz_says_off_without_redis_and_a_bad_url_is_refused(self):
        server = Server(EXECUTABLE, "--workers", "1")
        try:
            self.assertEqual(server.json("/healthz")[1]["redis"], "off")
        finally:
            self.assertEqual(server.stop(), 0)
        result = subprocess.run([EXECUTABLE, "--port", "0", "--redis", "http://example.org"], capture_output=True,
                                text=True, timeout=60)
        self.assertEqual(result.returncode, 2)
        self.assertEqual(result.stdout, "")
        self.assertEqual(result.stderr.count("\n"), 1, result.stderr)
        self.assertIn("--redis http://example.org: not redis://", result.stderr)


if __name__ == "__main__":
    EXECUTABLE = sys.argv.pop(1)
    unittest.main()
