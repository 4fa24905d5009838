#!/usr/bin/env python3
"""The OpenAPI document checked by a real client: Schemathesis (tests/serve/contract/
requirements.txt pins it and its dependencies by hash; scripts/setup.sh installs them in
a venv of the build folder) runs every check against a figment-serve this test starts on
a free loopback port: each operation's answers to requests that keep its schemas (each
accepted, every status, header, content type and body as documented) and to requests
that break them (each refused), and the links between operations (a POSTed job's status).
A fixed seed and number of examples: the same cases on every run. The test fails when
Schemathesis finds anything, did not test every operation of the document, or the
server did not stop cleanly. No timings asserted.

    test_contract.py FIGMENT-SERVE SCHEMATHESIS-ST

Exits 77 (ctest's SKIP_RETURN_CODE for serve.Contract), before anything runs, when
SCHEMATHESIS-ST is not there: scripts/setup.sh installs it.
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ElementTree

from ServeSupport import ServerCase

ST = None
CONTRACT = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "contract")
SKIP = 77
# Per operation and phase: renders are slow (a new body drapes in seconds), so few, but
# the coverage phase adds each parameter's edges and wrong types besides.
EXAMPLES = 8
SEED = 45


class Contract(ServerCase):
    # Renders never wait behind a full queue or a rate (503 and 429 are documented, but
    # the fuzzing would be refused instead of answered), nor past a time limit.
    server_arguments = ("--workers", "2", "--queue", "10000", "--rate", "0", "--time-limit", "600")

    def checks(self):
        """Every check this Schemathesis has (its --checks choices) but the one left out."""
        usage = subprocess.run([ST, "run", "--help"], capture_output=True, text=True, check=True).stdout
        choices = " ".join(usage.split("--checks", 1)[1].split("]", 1)[0].split())
        names = [name.strip() for name in choices.split("possible values:", 1)[1].split(",")]
        self.assertIn("not_a_server_error", names)
        # unsupported_method: Debian's cpp-httplib 0.11.4 answers a method it does not know
        # (QUERY) with its own 400 before any handler runs; the methods it knows and the
        # document does not list get 405 with Allow (serve.HostileClient tests those).
        # max_response_time (on with "all", at 10 s) is not a choice: tests never time
        # anything (CONTRIBUTING.md); the server bounds a render with its own --time-limit.
        return [name for name in names if name not in ("all", "unsupported_method")]

    def test_schemathesis_finds_nothing(self):
        status, headers, served = self.server.request("/openapi.json")
        self.assertEqual(status, 200)
        document = json.loads(served)
        with tempfile.TemporaryDirectory(prefix="figment-contract-") as reports:
            junit = os.path.join(reports, "junit.xml")
            # The document as the server sends it, read from a file: Schemathesis leaves
            # out the operation it loads its schema from, so GET /openapi.json is tested too.
            schema = os.path.join(reports, "openapi.json")
            with open(schema, "wb") as out:
                out.write(served)
            environment = dict(os.environ, PYTHONPATH=CONTRACT, SCHEMATHESIS_HOOKS="hooks", NO_COLOR="1")
            run = subprocess.run(
                [ST, "--config-file", os.path.join(CONTRACT, "schemathesis.toml"), "run",
                 schema, "--url", self.server.url.rstrip("/"), "--checks", ",".join(self.checks()),
                 "--max-examples", str(EXAMPLES), "--seed", str(SEED), "--workers", "1",
                 "--request-timeout", "600",  # a render may take that long: the server's --time-limit
                 "--report", "junit", "--report-junit-path", junit],
                cwd=reports, env=environment, capture_output=True, text=True)
            print(run.stdout[-6000:], run.stderr[-3000:], file=sys.stderr)
            self.assertEqual(run.returncode, 0, "Schemathesis found something (its report above)")
            tested = ElementTree.parse(junit).getroot()
            cases = {case.get("name"): case for case in tested.iter("testcase")}
        operations = {"%s %s" % (method.upper(), path) for path, item in document["paths"].items() for method in item}
        self.assertEqual(set(cases) - {"Stateful tests"}, operations)  # every operation tested, no other
        self.assertIn("Stateful tests", cases)  # the links: a POSTed job's status
        for name, case in cases.items():
            self.assertEqual(list(case.iter("failure")) + list(case.iter("error")), [], name)
            self.assertEqual(list(case.iter("skipped")), [], name)


if __name__ == "__main__":
    ServerCase.executable = sys.argv.pop(1)
    ST = sys.argv.pop(1)
    if not os.access(ST, os.X_OK):
        print("serve.Contract skipped: no Schemathesis at %s (scripts/setup.sh installs it)" % ST, file=sys.stderr)
        sys.exit(SKIP)
    unittest.main()
