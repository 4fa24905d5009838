#!/usr/bin/env python3
"""POST /api/render: a render as a background job on a server this test starts. 202 with
Location; the job's status polled until it ends; its result URL then a cache hit;
the same parameters (query or form body, any order) the same job; 400 as GET; an unknown
job 404; too many jobs waiting 503 with Retry-After. No timings asserted.

    test_render_jobs.py FIGMENT-SERVE [unittest options]
"""
import http.client
import json
import sys
import time
import unittest
import urllib.parse

from ServeSupport import Server, ServerCase

EXECUTABLE = None


def post(server, query="", form=None):
    """(status, headers with lower-case names, JSON body) of POST /api/render."""
    connection = http.client.HTTPConnection(server.host, server.port, timeout=120)
    try:
        body = urllib.parse.urlencode(form) if form is not None else None
        headers = {"Content-Type": "application/x-www-form-urlencoded"} if form is not None else {}
        connection.request("POST", "/api/render" + ("?" + query if query else ""), body=body, headers=headers)
        response = connection.getresponse()
        data = response.read()
        return response.status, {k.lower(): v for k, v in response.getheaders()}, json.loads(data)
    finally:
        connection.close()


def wait_for(server, location):
    """The job's status once it has ended (done or failed; or not 200). Polled with no time
    limit of its own: ctest's TIMEOUT is the only clock."""
    while True:
        status, job = server.json(location)
        if status != 200 or job["status"] in ("done", "failed"):
            return status, job
        time.sleep(0.2)


class RenderJobs(ServerCase):
    def test_job_runs_and_its_result_is_a_cache_hit(self):
        status, headers, job = post(self.server, "size=160x200&outfit=dress:M:ff0000&view=left")
        self.assertEqual(status, 202)
        location = headers["location"]
        self.assertTrue(location.startswith("/api/jobs/"), location)
        self.assertIn(job["status"], ("queued", "running", "done"))
        self.assertTrue(job["result"].startswith("/api/render?"), job["result"])
        status, job = wait_for(self.server, location)
        self.assertEqual((status, job["status"]), (200, "done"), job)
        status, headers, body = self.server.request(job["result"])
        self.assertEqual(status, 200)
        self.assertEqual(headers["x-figment-cache"], "hit")
        self.assertEqual(headers["etag"], '"%s"' % location.rsplit("/", 1)[1])
        self.assertTrue(body.startswith(b"\x89PNG"))
        again = post(self.server, "size=160x200&outfit=dress:M:ff0000&view=left")
        self.assertEqual((again[0], again[1]["location"], again[2]["status"]), (202, location, "done"))

    def test_same_parameters_are_the_same_job_as_query_or_form(self):
        first = post(self.server, "outfit=skirt:S:00ff00&size=160x200")
        second = post(self.server, form={"size": "160x200", "outfit": "skirt:S:00ff00"})
        self.assertEqual((first[0], second[0]), (202, 202))
        self.assertEqual(first[1]["location"], second[1]["location"])
        self.assertEqual(wait_for(self.server, first[1]["location"])[1]["status"], "done")

    def test_bad_parameter_is_400_as_get(self):
        status, headers, body = post(self.server, form={"outfit": "cape:M"})
        self.assertEqual(status, 400)
        self.assertEqual(body["parameter"], "outfit")
        self.assertNotIn("location", headers)

    def test_unknown_job_is_404(self):
        status, body = self.server.json("/api/jobs/" + "0" * 64)
        self.assertEqual(status, 404)
        self.assertIn("error", body)
        self.assertEqual(self.server.json("/api/jobs/")[0], 404)
        # An id quoted back cut to 64 bytes, never inside a character (22 euros: 66 bytes).
        status, body = self.server.json("/api/jobs/" + "%E2%82%AC" * 22)
        self.assertEqual((status, body["id"]), (404, "\u20ac" * 21))


class Overload(unittest.TestCase):
    def test_too_many_jobs_waiting_is_503_with_retry_after(self):
        server = Server(EXECUTABLE, "--workers", "1", "--queue", "1", "--rate", "0")
        try:
            answers = [post(server, "size=160x200&outfit=dress:M&hips=%.3f" % (0.90 + 0.01 * i)) for i in range(6)]
            statuses = [a[0] for a in answers]
            self.assertTrue(set(statuses) <= {202, 503}, statuses)
            self.assertIn(202, statuses)
            self.assertIn(503, statuses)
            for status, headers, body in answers:
                if status == 503:
                    self.assertGreater(int(headers["retry-after"]), 0)
                    self.assertIn("error", body)
            self.assertEqual(server.json("/healthz")[0], 200)
        finally:
            self.assertEqual(server.stop(), 0)


if __name__ == "__main__":
    EXECUTABLE = ServerCase.executable = sys.argv.pop(1)
    unittest.main()
