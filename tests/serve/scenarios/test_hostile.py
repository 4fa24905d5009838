#!/usr/bin/env python3
"""figment-serve against a hostile client, on a server this test starts on a loopback port.
On every route /openapi.json gives query parameters, a parameter whose value or name
percent-decodes to bytes that are not UTF-8 is a 400 naming it (a bad name as its
percent-encoding), in the query and in POST's form body; a job id that is not UTF-8 is a 404
showing it escaped; every JSON answer is strict UTF-8. A method the document does not list
for a path is 405 with Allow naming the listed ones (and HEAD with GET); an unknown path is
404 whatever the method. A request whose body's end is unclear (a body on GET, a chunked or
length-less POST) is refused with Connection: close. Nothing here renders; the server still
serves after it all and exits cleanly.

    test_hostile.py FIGMENT-SERVE [unittest options]
"""
import http.client
import json
import socket
import sys
import unittest

from ServeSupport import ServerCase

METHODS = ("GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS", "TRACE")


def strict_json(test, headers, body, what):
    """The body as JSON, after asserting it is JSON and strict UTF-8."""
    test.assertEqual(headers.get("content-type"), "application/json", what)
    text = body.decode("utf-8")  # strict: raises on bytes that are not UTF-8
    return json.loads(text)


class HostileClient(ServerCase):
    def send(self, method, target, body=None, headers=None):
        """(status, headers with lower-case names, body bytes) for a request sent as written."""
        connection = http.client.HTTPConnection(self.server.host, self.server.port, timeout=120)
        try:
            connection.putrequest(method, target, skip_accept_encoding=True)
            for name, value in (headers or {}).items():
                connection.putheader(name, value)
            if body is not None or method in ("POST", "PUT", "PATCH"):
                connection.putheader("Content-Length", str(len(body or b"")))
            connection.endheaders(body)
            response = connection.getresponse()
            return response.status, {k.lower(): v for k, v in response.getheaders()}, response.read()
        finally:
            connection.close()

    def send_raw(self, data):
        """The first answer to bytes sent as they are: (status, headers with lower-case names, body)."""
        with socket.create_connection((self.server.host, self.server.port), timeout=120) as connection:
            connection.sendall(data)
            response = http.client.HTTPResponse(connection)
            response.begin()
            return response.status, {k.lower(): v for k, v in response.getheaders()}, response.read()

    def document(self):
        status, headers, body = self.send("GET", "/openapi.json")
        self.assertEqual(status, 200)
        return strict_json(self, headers, body, "/openapi.json")

    def query_routes(self):
        """(path, method, first query parameter's name) of every operation that takes a query."""
        routes = []
        document = self.document()

        def resolved(parameter):  # a shared parameter is a "$ref" into components
            if "$ref" not in parameter:
                return parameter
            node = document
            for key in parameter["$ref"].lstrip("#/").split("/"):
                node = node[key]
            return node

        for path, item in document["paths"].items():
            for method, operation in item.items():
                parameters = [resolved(p) for p in operation.get("parameters", [])]
                names = [p["name"] for p in parameters if p.get("in") == "query"]
                if method.upper() in METHODS and names:
                    routes.append((path, method.upper(), names[0]))
        return routes

    def assert_refused(self, answer, parameter, value, what):
        status, headers, body = answer
        self.assertEqual(status, 400, what)
        refusal = strict_json(self, headers, body, what)
        self.assertEqual(refusal["parameter"], parameter, what)
        self.assertEqual(refusal["value"], value, what)

    def test_a_query_that_is_not_utf8_is_400_naming_the_parameter(self):
        routes = self.query_routes()
        self.assertIn(("/api/render", "GET", "stature"), routes)
        self.assertIn(("/api/fit", "GET", "sex"), routes)
        for path, method, name in routes:
            for query, parameter, value in ((name + "=%ff", name, "%FF"),
                                            (name + "=%c3%28", name, "%C3("),
                                            ("%c0%80", "%C0%80", ""),
                                            ("%ed%a0%80=1", "%ED%A0%80", "1")):
                what = "%s %s?%s" % (method, path, query)
                self.assert_refused(self.send(method, path + "?" + query), parameter, value, what)
                if method == "POST":  # the same in a form body
                    answer = self.send(method, path, query.encode(),
                                       {"Content-Type": "application/x-www-form-urlencoded"})
                    self.assert_refused(answer, parameter, value, what + " (form)")

    def test_a_job_id_that_is_not_utf8_is_404_shown_escaped(self):
        for segment, shown in (("%ff", "%FF"), ("%c0%80abc", "%C0%80abc"), ("%ff" * 40, "%FF" * 21)):
            status, headers, body = self.send("GET", "/api/jobs/" + segment)
            self.assertEqual(status, 404, segment)
            self.assertEqual(strict_json(self, headers, body, segment)["id"], shown)

    def test_a_method_the_document_does_not_list_is_405_with_allow(self):
        paths = self.document()["paths"]
        self.assertGreaterEqual(len(paths), 9)
        for path, item in paths.items():
            listed = {m.upper() for m in item if m.upper() in METHODS}
            self.assertTrue(listed, path)
            allowed = listed | ({"HEAD"} if "GET" in listed else set())
            target = path.replace("{id}", "0" * 32)
            for method in set(METHODS) - allowed:
                status, headers, body = self.send(method, target)
                self.assertEqual(status, 405, "%s %s" % (method, target))
                self.assertEqual({m.strip() for m in headers["allow"].split(",")}, allowed, target)
                self.assertIn("error", strict_json(self, headers, body, "%s %s" % (method, target)))

    def test_an_unknown_path_is_404_whatever_the_method(self):
        for path in ("/nope", "/api", "/api/render/x", "/api/jobs/a/b", "/openapi.json/x"):
            for method in METHODS:
                status, headers, body = self.send(method, path)
                self.assertEqual(status, 404, "%s %s" % (method, path))
                if method != "HEAD":
                    self.assertIn("error", strict_json(self, headers, body, "%s %s" % (method, path)))

    def test_a_request_whose_body_has_no_clear_end_is_refused_with_connection_close(self):
        hidden = b"GET /api/catalogue HTTP/1.1\r\nHost: t\r\n\r\n"
        length = b"Content-Length: %d\r\n" % len(hidden)
        for head, expected in ((b"GET /healthz HTTP/1.1\r\n" + length, 400),
                               (b"GET /nope HTTP/1.1\r\nTransfer-Encoding: chunked\r\n", 400),
                               (b"POST /api/render HTTP/1.1\r\nContent-Length: 1e3\r\n", 400),
                               (b"POST /api/render HTTP/1.1\r\nTransfer-Encoding: chunked\r\n", 411),
                               (b"POST /api/render HTTP/1.1\r\n", 411)):
            status, headers, body = self.send_raw(head + b"Host: t\r\n\r\n" + hidden)
            self.assertEqual(status, expected, head)
            self.assertEqual(headers.get("connection"), "close", head)
            self.assertIn("error", strict_json(self, headers, body, head))

    def test_the_server_still_serves(self):
        self.send("GET", "/api/render?stature=%ff")
        self.send("TRACE", "/healthz")
        status, headers, body = self.send("GET", "/healthz")
        self.assertEqual(status, 200)
        self.assertEqual(strict_json(self, headers, body, "/healthz")["status"], "ok")


if __name__ == "__main__":
    ServerCase.executable = sys.argv.pop(1)
    unittest.main()
