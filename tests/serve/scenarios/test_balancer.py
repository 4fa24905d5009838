#!/usr/bin/env python3
"""The deployment's load balancer: Debian's nginx with the shipped site (deploy/nginx.conf),
its upstream pointed at two figment-serve instances on loopback ports, listening on a Unix
socket in a temporary folder (no port of its own) and stopped at the end. Requests through
it reach both instances; an image one instance made is a hit through the other (one Redis);
with one instance stopped, requests through nginx are still answered 200.

    test_balancer.py FIGMENT-SERVE NGINX NGINX-SITE [unittest options]
"""
import http.client
import os
import re
import socket
import subprocess
import sys
import tempfile
import time
import unittest

from ServeSupport import RedisServer, Server

EXECUTABLE = None
NGINX = None
SITE = None


class UnixConnection(http.client.HTTPConnection):
    def __init__(self, path):
        super().__init__("localhost", timeout=600)
        self.path = path

    def connect(self):
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        self.sock.connect(self.path)


class Nginx:
    """nginx in the foreground, one process, every file in a temporary folder."""

    def __init__(self, site, upstreams):
        self.folder = tempfile.TemporaryDirectory(prefix="figment-nginx-test-")
        self.socket = os.path.join(self.folder.name, "nginx.sock")
        with open(site) as text:
            site = text.read()
        site = re.sub(r"server \S+:\d+ ", "SERVER ", site)
        lines = site.split("\n")
        first = next(i for i, line in enumerate(lines) if "SERVER " in line)
        template = lines[first]
        lines = [line for line in lines if "SERVER " not in line]
        for upstream in reversed(upstreams):
            lines.insert(first, template.replace("SERVER ", "server %s " % upstream))
        site = "\n".join(lines).replace("listen 80;", "listen unix:%s;" % self.socket)
        # Which instance answered, for the test only (the shipped site does not tell clients).
        site = site.replace("proxy_pass http://figment;",
                            "proxy_pass http://figment;\n        add_header X-Upstream $upstream_addr always;")
        folder = self.folder.name
        with open(os.path.join(folder, "site.conf"), "w") as out:
            out.write(site)
        temporary = "".join("%s_temp_path %s/%s;\n" % (kind, folder, kind)
                            for kind in ("client_body", "proxy", "fastcgi", "uwsgi", "scgi"))
        with open(os.path.join(folder, "nginx.conf"), "w") as out:
            out.write("daemon off;\nmaster_process off;\nworker_processes 1;\npid %s/nginx.pid;\n"
                      "error_log %s/error.log;\nevents { worker_connections 64; }\n"
                      "http {\naccess_log off;\n%sinclude %s/site.conf;\n}\n" % (folder, folder, temporary, folder))
        self.process = subprocess.Popen([NGINX, "-e", os.path.join(folder, "error.log"), "-p", folder,
                                         "-c", os.path.join(folder, "nginx.conf")],
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        while not os.path.exists(self.socket):
            if self.process.poll() is not None:
                with open(os.path.join(folder, "error.log")) as log:
                    raise RuntimeError("nginx did not start: " + log.read())
            time.sleep(0.05)

    def request(self, path):
        connection = UnixConnection(self.socket)
        try:
            connection.request("GET", path)
            response = connection.getresponse()
            return response.status, {k.lower(): v for k, v in response.getheaders()}, response.read()
        finally:
            connection.close()

    def stop(self):
        self.process.terminate()
        self.process.wait(timeout=60)
        self.folder.cleanup()


class Balancer(unittest.TestCase):
    def test_requests_through_nginx_reach_both_instances(self):
        redis = RedisServer()
        servers = [Server(EXECUTABLE, "--workers", "1", "--rate", "0", "--redis", redis.url) for _ in range(2)]
        addresses = ["127.0.0.1:%d" % server.port for server in servers]
        nginx = Nginx(SITE, addresses)
        try:
            answered = {}
            for i in range(8):
                status, headers, _ = nginx.request("/healthz")
                self.assertEqual(status, 200)
                answered[headers["x-upstream"]] = answered.get(headers["x-upstream"], 0) + 1
            self.assertEqual(set(answered), set(addresses), answered)
            # One render, then the same image through whichever instance answers: a hit on both.
            path = "/api/render?size=96x120&outfit=tshirt:M:ff0000"
            status, headers, _ = nginx.request(path)
            self.assertEqual(status, 200)
            caches = set()
            for _ in range(4):
                status, headers, _ = nginx.request(path)
                self.assertEqual(status, 200)
                caches.add((headers["x-upstream"], headers["x-figment-cache"]))
            self.assertEqual(caches, {(address, "hit") for address in addresses})
            # One instance gone: nginx answers from the other.
            self.assertEqual(servers[0].stop(), 0)
            for _ in range(4):
                status, headers, _ = nginx.request(path)
                self.assertEqual((status, headers["x-upstream"].split(", ")[-1]), (200, addresses[1]))
        finally:
            nginx.stop()
            for server in servers:
                server.stop()
            redis.stop()


if __name__ == "__main__":
    EXECUTABLE = sys.argv.pop(1)
    NGINX = sys.argv.pop(1)
    SITE = sys.argv.pop(1)
    unittest.main()
