#!/usr/bin/env python3
"""Fails on tests that cannot fail the way they should (CONTRIBUTING.md, "Tests and benchmarks").

In the C++ tests, two kinds are found by reading the sources:
  - a timed assertion: a test that reads a clock (speed is figment-bench's to measure), or
    bounds a reported wall time from above;
  - whole image files compared byte for byte: equal pictures may differ in their bytes
    and different ones agree in metadata-free parts; compare decoded pixels instead.
A line that compares bytes on purpose (the test of reproducible files) ends with the
marker `// check-tests: bytes are the subject`.

In the Python tests (tests/**/*.py, read as Python syntax trees), three:
  - a skip decided from an answer: skipTest, SkipTest or pytest.skip (or a loop's
    `continue`) under a condition on an answer's text, body, page, status or output, or in
    an `except`; a skip names a precondition decided before the test runs, from the file
    system (unittest.skipUnless on a data file or a program), never what the code under
    test said;
  - a clock read (time.time, time.monotonic, time.perf_counter, datetime.now, ...): an
    assertion on a duration or a deadline; wait on something observable, and let ctest's
    TIMEOUT be the only clock;
  - a sleep outside a polling loop: a guess that something happened by then.

  scripts/check-tests.py [FOLDER ...]   (default: tests/; exit 1 and one line a finding)
  scripts/check-tests.py --self-test    (the rules against samples that must and must not be found)
"""
import ast
import pathlib
import re
import sys
import tempfile

CLOCK = re.compile(r"\b(steady_clock|high_resolution_clock|system_clock|gettimeofday|clock_gettime|getrusage)\b"
                   r"|\bstd::clock\s*\(|[^\w.]time\s*\(\s*(nullptr|NULL|0)?\s*\)")
WALL_UPPER_BOUND = re.compile(r"\b(EXPECT|ASSERT)_(LT|LE)\s*\(.*\b(wall|elapsed|seconds?|duration)\w*", re.IGNORECASE)
BYTE_COMPARE = re.compile(r"\b(EXPECT|ASSERT)_(EQ|NE)\s*\(.*\b(bytes|contents|bytesOf|readBytes)\s*\(.*\.png")
MARKER = "// check-tests: bytes are the subject"


def findings(path, text):
    for number, line in enumerate(text.splitlines(), 1):
        code = line.split("//", 1)[0] if MARKER not in line else ""
        where = f"{path}:{number}"
        if CLOCK.search(code):
            yield f"{where}: reads a clock; tests never time anything (measure with figment-bench)"
        elif WALL_UPPER_BOUND.search(code) and "wall" in code.lower():
            yield f"{where}: bounds a wall time from above; tests never time anything"
        elif BYTE_COMPARE.search(code):
            yield f"{where}: compares whole image files; compare decoded pixels (support/PngPixels.h)"


# What a condition may say about an answer of the code under test (a name or an attribute).
ANSWER_WORDS = {"text", "body", "page_source", "content", "status", "status_code", "code", "answer", "response",
                "reply", "error", "stdout", "stderr", "output", "returncode", "advice", "result"}
TEXT_WORDS = {"text", "body", "page_source", "content", "stdout", "stderr", "output"}
SKIPS = {"skipTest", "SkipTest", "skip"}
CLOCKS = {("time", "time"), ("time", "time_ns"), ("time", "monotonic"), ("time", "monotonic_ns"),
          ("time", "perf_counter"), ("time", "perf_counter_ns"), ("time", "process_time"),
          ("datetime", "now"), ("datetime", "utcnow"), ("date", "today")}
BARE_CLOCKS = {"perf_counter", "perf_counter_ns", "monotonic", "monotonic_ns"}


def words(node):
    """The names and attribute names a condition reads."""
    return {n.id for n in ast.walk(node) if isinstance(n, ast.Name)} | \
        {n.attr for n in ast.walk(node) if isinstance(n, ast.Attribute)}


def called(node):
    """(object, function) of a call: ("time", "time") for time.time(), (None, "skip") for skip()."""
    function = node.func
    if isinstance(function, ast.Attribute):
        owner = function.value
        return (owner.id if isinstance(owner, ast.Name) else owner.attr if isinstance(owner, ast.Attribute) else None,
                function.attr)
    return (None, function.id) if isinstance(function, ast.Name) else (None, None)


def inside(tree, kinds):
    """Every node with the chain of its ancestors' kinds that are in `kinds`."""
    stack = [(tree, ())]
    while stack:
        node, chain = stack.pop()
        yield node, chain
        here = chain + ((node,) if isinstance(node, kinds) else ())
        for child in ast.iter_child_nodes(node):
            stack.append((child, here))


def py_findings(path, text):
    try:
        tree = ast.parse(text)
    except SyntaxError as error:
        yield f"{path}:{error.lineno}: does not parse as Python"
        return
    for node, chain in inside(tree, (ast.If, ast.ExceptHandler, ast.While, ast.For, ast.IfExp)):
        where = f"{path}:{getattr(node, 'lineno', 0)}"
        conditions = [words(a.test) for a in chain if isinstance(a, (ast.If, ast.IfExp))]
        if isinstance(node, ast.Call) and called(node)[1] in SKIPS:
            if any(isinstance(a, ast.ExceptHandler) for a in chain):
                yield f"{where}: skips in an except: a skip is decided before the test runs, from the file system"
            elif any(c & ANSWER_WORDS for c in conditions):
                yield f"{where}: skips on an answer's text or status; skip only on a named precondition (skipUnless)"
        elif isinstance(node, ast.Continue) and any(c & TEXT_WORDS for c in conditions):
            yield f"{where}: passes over a case on an answer's text: a silent skip"
        elif isinstance(node, ast.Call) and (called(node) in CLOCKS or called(node)[1] in BARE_CLOCKS):
            yield f"{where}: reads a clock; tests never time anything (wait on something observable)"
        elif isinstance(node, ast.Call) and called(node) == ("time", "sleep") and \
                not any(isinstance(a, (ast.While, ast.For)) for a in chain):
            yield f"{where}: sleeps outside a polling loop: wait on something observable instead"


def check(folders):
    found = []
    for folder in folders:
        for path in sorted(pathlib.Path(folder).rglob("*")):
            if path.suffix in (".cpp", ".h") and "fuzz" not in path.parts:
                found += findings(path, path.read_text(errors="replace"))
            elif path.suffix == ".py":
                found += sorted(py_findings(path, path.read_text(errors="replace")),
                                key=lambda line: int(line.split(":")[1]))
    return found


def self_test():
    must = ["auto start = std::chrono::steady_clock::now();",
            "EXPECT_LT(wall.count(), 5.0);",
            "ASSERT_LE(stats[\"wall_s\"], 1.0);",
            "EXPECT_NE(bytes(path(\"plain.png\")), bytes(path(\"hybrid.png\")));",
            "const time_t t = time(nullptr);"]
    must_not = ["EXPECT_GE(garment[\"wall_s\"].get<double>(), 0.0);",
                "EXPECT_EQ(bytes(path(\"a.png\")), bytes(path(\"b.png\")));  " + MARKER,
                "EXPECT_EQ(image.count(kRed), 0);  // no steady_clock here",
                "EXPECT_LT(meanDistance(a, b), 0.005);",
                "EXPECT_NEAR(run.simulatedSeconds, run.iterations * dt, 1e-9);"]
    py_must = ["if b'MakeHuman' in body:\n    self.skipTest('no data')",
               "if 'MakeHuman' in advice.text:\n    self.skipTest('no data')",
               "if status == 500:\n    raise unittest.SkipTest('the server is broken')",
               "if driver.page_source.count('error'):\n    pytest.skip('no page')",
               "try:\n    start()\nexcept OSError:\n    self.skipTest('no server')",
               "for path in paths:\n    if code == 500 and b'MakeHuman' in body:\n        continue",
               "deadline = time.monotonic() + 60",
               "self.assertLess(time.time() - start, 5.0)",
               "start = perf_counter()",
               "time.sleep(2)  # past the claim time: nothing comes back",
               "def test_a(self):\n    self.redis.kill()\n    time.sleep(1.5)"]
    py_must_not = ["@unittest.skipUnless(os.path.exists(DATA), 'no data')\ndef test_a(self):\n    pass",
                   "needs_data = unittest.skipUnless(data_folder(), 'no data')",
                   "while not condition():\n    time.sleep(0.02)",
                   "for _ in range(200):\n    if held():\n        return\n    time.sleep(0.05)",
                   "if status != 200 or job['status'] in ('done', 'failed'):\n    return status, job",
                   "if not os.access(ST, os.X_OK):\n    sys.exit(SKIP)",
                   "self.assertEqual(body, b'')  # not time.time() here",
                   "connection = http.client.HTTPConnection(host, port, timeout=600)",
                   "for path in document['paths']:\n    if '{' in path:\n        continue"]
    wrong = [s for s in must if not list(findings("sample", s))]
    wrong += [s for s in must_not if list(findings("sample", s))]
    wrong += [s for s in py_must if not list(py_findings("sample.py", s))]
    wrong += [s for s in py_must_not if list(py_findings("sample.py", s))]
    with tempfile.TemporaryDirectory() as folder:  # and as check() finds them: in a folder's .py files
        for number, sample in enumerate(py_must):
            (pathlib.Path(folder) / f"test_{number}.py").write_text(sample + "\n")
        wrong += [f"{len(py_must)} Python files in a folder" for found in [check([folder])]
                  if len(found) != len(py_must)]
    for sample in wrong:
        print(f"check-tests self-test: wrongly judged: {sample}", file=sys.stderr)
    return 1 if wrong else 0


def main(arguments):
    if arguments == ["--self-test"]:
        return self_test()
    found = check(arguments or ["tests"])
    for line in found:
        print(line, file=sys.stderr)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
