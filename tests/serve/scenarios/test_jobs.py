#!/usr/bin/env python3
"""The work queue in Redis: figment-precompute puts 100 render jobs on a Redis Stream of the
test's own, two job workers (figment-serve --job-worker, each with a drape cache of its own)
take them; one is stopped holding a job and killed with SIGKILL halfway. Every job's image is
then in Redis once, sound, of its request's size and garment colour, under the ETag an
instance gives the same request, and the killed worker's job was done by the other. A job
with a bad request is recorded failed once, not retried; a bad line in a request file is
refused naming it, with nothing queued. No timings asserted.

    test_jobs.py FIGMENT-SERVE FIGMENT-PRECOMPUTE [unittest options]
"""
import os
import signal
import subprocess
import sys
import time
import unittest

from ServeSupport import JobWorker, RedisServer, Server, claim_after, count_near, png_pixels

EXECUTABLE = None
PRECOMPUTE = None
OUTFITS = {"dress:M:ff0000": (255, 0, 0), "skirt:S:00ff00": (0, 255, 0),
           "tshirt:L:0000ff": (0, 0, 255), "dress:XL:00ff00": (0, 255, 0)}
HEADER = 16 + 32 + 32  # an image entry's: magic line, tag, size and checksum in hex


def precompute(redis, *arguments):
    return subprocess.run([PRECOMPUTE, "--redis", redis.url, *arguments], capture_output=True, text=True, timeout=900)


def as_bytes(value):
    return value if isinstance(value, bytes) else (value or "").encode()


def hash_of(redis, key):
    values = redis.command("HGETALL", key) or []
    return dict(zip(values[::2], values[1::2]))


def wait_until(condition):
    """Polls `condition` until it holds (no time limit is asserted: ctest's TIMEOUT bounds it)."""
    while not condition():
        time.sleep(0.05)


class WorkQueue(unittest.TestCase):
    def setUp(self):
        self.redis = RedisServer()
        self.folder = self.redis.folder.name

    def tearDown(self):
        self.redis.stop()

    def write_requests(self, lines):
        path = os.path.join(self.folder, "requests.txt")
        with open(path, "w") as out:
            out.write("# outfit × view\n" + "\n".join(lines) + "\n")
        return path

    def held_job(self, worker):
        """Stops `worker` (SIGSTOP) while it holds a job; that job's key."""
        for _ in range(200):
            os.kill(worker.process.pid, signal.SIGSTOP)
            pending = self.redis.command("XPENDING", "figment:jobs", "workers", "-", "+", 10, worker.name + "/0")
            if pending:
                entry = self.redis.command("XRANGE", "figment:jobs", pending[0][0], pending[0][0])
                fields = dict(zip(entry[0][1][::2], entry[0][1][1::2]))
                return fields["key"]
            os.kill(worker.process.pid, signal.SIGCONT)  # between two jobs: let it take the next
            time.sleep(0.05)
        self.fail("the worker never held a job")

    def test_100_jobs_over_two_workers_one_killed_halfway(self):
        lines = ["outfit=%s&view=%d,0&size=64x80" % (outfit, 14 * v) for outfit in OUTFITS for v in range(25)]
        result = precompute(self.redis, "--requests", self.write_requests(lines))
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("100 requests, 100 added", result.stdout)
        claim = claim_after(20)
        arguments = ("--workers", "1", "--claim-after", claim)
        first = JobWorker(EXECUTABLE, self.redis.url, "first", *arguments)
        second = JobWorker(EXECUTABLE, self.redis.url, "second", *arguments)
        try:
            wait_until(lambda: self.redis.command("HLEN", "figment:jobs:done") >= 30)
            key = self.held_job(first)
            first.process.send_signal(signal.SIGKILL)
            first.process.wait(timeout=60)
            # The killed worker's job waits out the claim time before the other takes it.
            result = precompute(self.redis, "--status", "--wait", str(600 + int(float(claim))))
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        finally:
            first.stop()
            self.assertEqual(second.stop(), 0)
        done, made = hash_of(self.redis, "figment:jobs:done"), hash_of(self.redis, "figment:jobs:made")
        self.assertEqual(len(done), 100)
        self.assertEqual(self.redis.command("HLEN", "figment:jobs:failed"), 0)
        self.assertEqual(self.redis.command("HLEN", "figment:jobs:queued"), 0)
        self.assertEqual(self.redis.command("XPENDING", "figment:jobs", "workers")[0], 0)
        self.assertIn(key, done)  # the killed worker's job, done by the other
        self.assertEqual(set(made.values()), {"1"})  # none rendered twice
        # Each rendered once, but the held job may have been rendered and stored by the
        # killed worker just before it stopped: the other then found its image and made
        # nothing (idempotent by digest).
        self.assertGreaterEqual(len(made), 99)
        # Redis crashes and starts again: every acknowledged result is still there.
        self.redis.kill()
        self.redis.start()
        self.assertEqual(hash_of(self.redis, "figment:jobs:done"), done)
        self.check_images(done)

    def check_images(self, done):
        requests = hash_of(self.redis, "figment:jobs:requests")
        for key, tag in done.items():
            entry = as_bytes(self.redis.command("GET", "figment:image:" + tag))
            self.assertEqual(entry[:48], b"figment-image 1\n" + tag.encode())
            width, height, rows = png_pixels(entry[HEADER:])
            self.assertEqual((width, height), (64, 80))
            outfit = [p.split("=")[1] for p in requests[key].split("&") if p.startswith("outfit=")][0]
            self.assertGreater(count_near(rows, OUTFITS[outfit], 0.2), 5, requests[key])
        # An instance over the same Redis answers a job's request from it, under the same tag.
        server = Server(EXECUTABLE, "--workers", "1", "--redis", self.redis.url)
        try:
            key, tag = next(iter(done.items()))
            status, headers, _ = server.request("/api/render?" + requests[key])
            self.assertEqual((status, headers["etag"], headers["x-figment-cache"]), (200, '"%s"' % tag, "hit"))
            self.assertEqual(server.json("/healthz")[1]["busy"], 0)
        finally:
            self.assertEqual(server.stop(), 0)

    def test_a_bad_job_is_recorded_once_and_not_retried(self):
        self.redis.command("XADD", "figment:jobs", "*", "key", "handmade", "request", "garbage=1&outfit=dress:M")
        self.redis.command("XADD", "figment:jobs", "*", "key", "norequest")
        # A claim time of 1 ms: a job left unacknowledged is taken over by the worker's next
        # claim, which comes first in every turn of its loop (serve/workers/JobQueue.h's next()).
        worker = JobWorker(EXECUTABLE, self.redis.url, "only", "--workers", "1", "--claim-after", "0.001")
        try:
            result = precompute(self.redis, "--requests", self.write_requests(["outfit=skirt:M&size=64x80"]))
            self.assertEqual(result.returncode, 0, result.stderr)
            result = precompute(self.redis, "--status", "--wait", "600")
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            self.assertIn("failed: handmade: 400: unknown parameter (garbage)", result.stdout)
            self.assertIn("failed: norequest: 400: the job has no request", result.stdout)
            # Another job, added once those are recorded, then done: the worker has since
            # turned its loop, claiming first, a render's time (far past 1 ms) after the
            # failures; a failed job left pending would have been taken again before it
            # (and, delivered five times, recorded "given up" instead).
            result = precompute(self.redis, "--requests", self.write_requests(["outfit=tshirt:M&size=64x80"]))
            self.assertEqual(result.returncode, 0, result.stderr)
            result = precompute(self.redis, "--status", "--wait", "600")
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            self.assertEqual(self.redis.command("HLEN", "figment:jobs:done"), 2)
            failed = hash_of(self.redis, "figment:jobs:failed")
            self.assertEqual(failed, {"handmade": "400: unknown parameter (garbage)",
                                      "norequest": "400: the job has no request"})
            self.assertEqual(self.redis.command("XLEN", "figment:jobs"), 0)
            self.assertEqual(self.redis.command("XPENDING", "figment:jobs", "workers")[0], 0)
        finally:
            self.assertEqual(worker.stop(), 0)

    def test_a_job_that_never_finishes_is_given_up_after_five_deliveries(self):
        # Every render runs past a time limit of 1 ms: its worker is killed and the job left
        # pending, taken over again after the claim time, until it has been delivered 5 times.
        worker = JobWorker(EXECUTABLE, self.redis.url, "only", "--workers", "1", "--time-limit", "0.001",
                           "--claim-after", "0.2")
        try:
            result = precompute(self.redis, "--requests", self.write_requests(["outfit=dress:L&size=64x80"]))
            self.assertEqual(result.returncode, 0, result.stderr)
            result = precompute(self.redis, "--status", "--wait", "600")
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            self.assertIn("1 jobs: 0 done, 1 failed", result.stdout)
            self.assertIn("given up after 5 deliveries", result.stdout)
            self.assertEqual(self.redis.command("XLEN", "figment:jobs"), 0)
        finally:
            self.assertEqual(worker.stop(), 0)

    def test_a_job_worker_goes_on_after_redis_restarts(self):
        worker = JobWorker(EXECUTABLE, self.redis.url, "only", "--workers", "1")
        try:
            self.redis.kill()
            wait_until(lambda: "unreachable" in worker.log_so_far())  # it found Redis away
            self.redis.start()
            result = precompute(self.redis, "--requests", self.write_requests(["outfit=dress:S&size=64x80"]))
            self.assertEqual(result.returncode, 0, result.stderr)
            result = precompute(self.redis, "--status", "--wait", "600")
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            self.assertIn("1 jobs: 1 done, 0 failed", result.stdout)
        finally:
            self.assertEqual(worker.stop(), 0)
        self.assertEqual(worker.log.count("unreachable"), 1, worker.log)
        self.assertEqual(worker.log.count("reachable again"), 1, worker.log)

    def test_a_bad_request_line_is_refused_and_nothing_queued(self):
        path = self.write_requests(["outfit=dress:M&size=64x80", "outfit=dress:Q&size=64x80"])
        result = precompute(self.redis, "--requests", path)
        self.assertEqual(result.returncode, 2)
        self.assertEqual(result.stderr.count("\n"), 1, result.stderr)
        self.assertIn("requests.txt:3: outfit=dress:Q", result.stderr)
        self.assertEqual(self.redis.command("EXISTS", "figment:jobs", "figment:jobs:requests"), 0)


if __name__ == "__main__":
    EXECUTABLE = sys.argv.pop(1)
    PRECOMPUTE = sys.argv.pop(1)
    unittest.main()
