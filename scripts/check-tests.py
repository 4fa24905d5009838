#!/usr/bin/env python3
"""Fails on tests that cannot fail the way they should (CONTRIBUTING.md, "Tests and benchmarks").

Two kinds are found by reading the test sources:
  - a timed assertion: a test that reads a clock (speed is figment-bench's to measure), or
    bounds a reported wall time from above;
  - whole image files compared byte for byte: equal pictures may differ in their bytes
    and different ones agree in metadata-free parts; compare decoded pixels instead.
A line that compares bytes on purpose (the test of reproducible files) ends with the
marker `// check-tests: bytes are the subject`.

  scripts/check-tests.py [FOLDER ...]   (default: tests/; exit 1 and one line a finding)
  scripts/check-tests.py --self-test    (the rules against samples that must and must not be found)
"""
import pathlib
import re
import sys

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


def check(folders):
    found = []
    for folder in folders:
        for path in sorted(pathlib.Path(folder).rglob("*")):
            if path.suffix in (".cpp", ".h") and "fuzz" not in path.parts:
                found += findings(path, path.read_text(errors="replace"))
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
    wrong = [s for s in must if not list(findings("sample", s))]
    wrong += [s for s in must_not if list(findings("sample", s))]
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
